/* SPDX-License-Identifier: MIT */
/*
 * rastrules.h: the C API of rastrules (C99), for C programs and other languages' FFI.
 *
 * It reads a scene (spec/scene.md) with the library's one strict reader, renders it with the
 * flow of `rastrules render` (coverage; depth and attributes when the scene has the pipeline
 * state; a path's exact area), lets the caller walk the fragments, and explains a pixel as
 * `rastrules explain` does. It decides nothing itself: every answer is the C++ library's.
 *
 * Errors. Every function that can fail returns an rr_status. RR_OK (0) is success; any other
 * value is an error, and then rr_last_error() returns its one-line message (the reader's message
 * for a bad scene: "primitives[0].v[1][1]: must be a number, ..."). The message is held per
 * thread: it stays valid until the next call of an rr_ function on the same thread, and a call
 * that returns RR_OK makes it the empty string. No C++ exception crosses this interface: out of
 * memory is RR_ERROR_OUT_OF_MEMORY, anything unexpected RR_ERROR_INTERNAL. A NULL pointer where a
 * handle or an output is needed is RR_ERROR_NULL_ARGUMENT (never a crash).
 *
 * Ownership and lifetimes.
 *   - rr_scene: made by rr_scene_from_json or rr_scene_from_file, owned by the caller, released
 *     with rr_scene_free. The text or path given is copied: it may be freed after the call.
 *   - rr_render: made by rr_render_scene, owned by the caller, released with rr_render_free.
 *     It holds its own copy of everything it needs: it stays valid after its scene is freed.
 *   - rr_fragment: plain fields filled by rr_render_fragment; its pointers (attr, depth,
 *     area_text) point into the rr_render and stay valid until that rr_render is freed.
 *   - Strings returned through a char** (rr_explain) are owned by the caller and released with
 *     rr_string_free. Strings returned as const char* (rr_version, rr_status_name,
 *     rr_last_error) belong to the library and must not be freed.
 *   - Every rr_*_free accepts NULL and does nothing.
 * Threads. Different handles may be used on different threads at once. One scene may be
 * rendered and explained from several threads at once as long as no thread changes it
 * (rr_scene_set_profile); one rr_render may be read from several threads at once.
 *
 * Limits (SCENE.INPUT.LIMITS): a scene text larger than 64 MiB, and a render beyond its fragment
 * or work limit (rr_render_options), are refused with RR_ERROR_BAD_SCENE or RR_ERROR_LIMIT:
 * memory stays bounded by the limits whatever the input. A render keeps all its fragments for
 * the caller (about 100 bytes each, twice that with pipeline data): lower max_fragments to bound
 * that memory on a small machine.
 */
#ifndef RASTRULES_RASTRULES_H
#define RASTRULES_RASTRULES_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The version of this header; rr_version() gives the library's ("0.1.0"). They are the
 * project's version (project(VERSION) in CMakeLists.txt). */
#define RASTRULES_VERSION_MAJOR 0
#define RASTRULES_VERSION_MINOR 1
#define RASTRULES_VERSION_PATCH 0
#define RASTRULES_VERSION_STRING "0.1.0"

/* Returns the library's version, "MAJOR.MINOR.PATCH" (a static string). */
const char* rr_version(void);

/* What a call did. */
typedef enum rr_status {
  RR_OK = 0,
  RR_ERROR_NULL_ARGUMENT = 1, /* a required pointer was NULL */
  RR_ERROR_BAD_SCENE = 2,     /* malformed JSON or a bad scene (SCENE.INPUT.ERRORS) */
  RR_ERROR_LIMIT = 3, /* beyond the fragment or work limit of a render (SCENE.INPUT.LIMITS) */
  RR_ERROR_FILE = 4,  /* a scene file that cannot be read, or larger than 64 MiB */
  RR_ERROR_OUT_OF_RANGE = 5,  /* a fragment index or a pixel outside the render or target */
  RR_ERROR_UNKNOWN_NAME = 6,  /* a profile name that is not d3d11, vulkan or opengl */
  RR_ERROR_OUT_OF_MEMORY = 7, /* an allocation failed; nothing was changed */
  RR_ERROR_INTERNAL = 8       /* a failure of the library itself (please report it) */
} rr_status;

/* Returns the name of a status ("RR_OK", "RR_ERROR_BAD_SCENE", ...; "unknown status" for other
 * values), a static string. */
const char* rr_status_name(rr_status status);

/* Returns the message of the last call on this thread that failed ("" after a success), valid
 * until the next rr_ call on this thread. Never NULL. */
const char* rr_last_error(void);

/* ---- Scenes ---------------------------------------------------------------------------- */

typedef struct rr_scene rr_scene;

/* Reads a scene from JSON text of `length` bytes (not necessarily NUL-terminated) and checks
 * it as `rastrules render` does (the reader, then the kernel's checks or the pipeline's
 * validation). On success *out is a new scene; on failure *out is NULL and the message names
 * the field ("primitives[2].v[1][0]: ...") or, for malformed JSON, "(json): parse error at
 * line L, column C: ...". */
rr_status rr_scene_from_json(const char* text, size_t length, rr_scene** out);

/* rr_scene_from_json on the content of a file ("-" is standard input). A file that cannot be
 * read or is larger than 64 MiB is RR_ERROR_FILE; a parse error names the file. */
rr_status rr_scene_from_file(const char* path, rr_scene** out);

/* Gives the scene the conventions of a profile (spec/rules/profile.md): "d3d11", "vulkan" or
 * "opengl", as rastrules::apply(profile(...)) does. An unknown name is RR_ERROR_UNKNOWN_NAME;
 * a scene the profile makes invalid (an antialiased line under Vulkan's Bresenham lines) is
 * RR_ERROR_BAD_SCENE. On any error the scene is left as it was. */
rr_status rr_scene_set_profile(rr_scene* scene, const char* name);

/* What a scene is. */
typedef struct rr_scene_info {
  int32_t width, height; /* the target, in pixels */
  uint32_t primitives;   /* number of primitives */
  uint32_t samples;      /* samples per pixel (1 without multisampling) */
  int pipeline;          /* nonzero: the scene has pipeline state (SCENE.PIPELINE) */
  int has_depth;         /* nonzero: fragments carry depth (the scene has "depth") */
  uint32_t attributes;   /* declared attributes: values per fragment */
} rr_scene_info;

rr_status rr_scene_get_info(const rr_scene* scene, rr_scene_info* out);

/* Releases a scene (NULL: nothing). Renders made from it stay valid. */
void rr_scene_free(rr_scene* scene);

/* ---- Rendering ------------------------------------------------------------------------- */

/* Limits of one render (SCENE.INPUT.LIMITS); 0 takes the default of `rastrules render`. */
typedef struct rr_render_options {
  uint64_t max_fragments; /* default 2^26 (as --max-fragments) */
  uint64_t max_work;      /* default 2^36 sample tests (as --max-work) */
} rr_render_options;

typedef struct rr_render rr_render;

/* Renders a scene as `rastrules render` does: a scene without pipeline state by coverage
 * alone, one with it through the pipeline (depth, attributes). options may be NULL (the
 * defaults). On success *out holds the fragments in the order of SCENE.OUTPUT.FRAGMENTS
 * (SCENE.OUTPUT.PIPELINE for pipeline scenes); beyond a limit it is RR_ERROR_LIMIT, a scene the
 * pipeline rejects (a viewport or position out of range) RR_ERROR_BAD_SCENE. */
rr_status rr_render_scene(const rr_scene* scene, const rr_render_options* options, rr_render** out);

/* The number of fragments of a render. */
rr_status rr_render_fragment_count(const rr_render* render, size_t* count);

/* Which optional fields of an rr_fragment hold a value (bits of rr_fragment.flags). */
enum {
  RR_FRAGMENT_SEG = 1u << 0,         /* seg: line strips */
  RR_FRAGMENT_SAMPLE = 1u << 1,      /* sample: sample-frequency shading */
  RR_FRAGMENT_HELPER = 1u << 2,      /* a helper lane of a 2x2 quad (mask 0) */
  RR_FRAGMENT_COVERAGE = 1u << 3,    /* coverage_q16: antialiased lines */
  RR_FRAGMENT_CENTROID = 1u << 4,    /* centroid_x, centroid_y */
  RR_FRAGMENT_DERIVATIVES = 1u << 5, /* ddx_x, ddx_y, ddy_x, ddy_y */
  RR_FRAGMENT_AREA = 1u << 6,        /* area, area_text, alpha: paths with "coverage": "area" */
  RR_FRAGMENT_PART = 1u << 7,        /* part: a clipped primitive's fan triangle or segment */
  RR_FRAGMENT_DEPTH = 1u << 8,       /* depth, depth_count, passed: the scene has "depth" */
  RR_FRAGMENT_BARY = 1u << 9         /* bary, bary_area: pipeline scenes with depth or attributes */
};

/* One fragment (SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.MSAA, SCENE.OUTPUT.AREA,
 * SCENE.OUTPUT.PIPELINE). Fields whose flag is not set are 0 (pointers NULL). */
typedef struct rr_fragment {
  uint32_t prim;                      /* the scene's primitive index */
  int32_t x, y;                       /* the pixel */
  uint32_t mask;                      /* covered samples after the sample mask, bit i = sample i */
  uint32_t flags;                     /* RR_FRAGMENT_* */
  uint32_t seg;                       /* line strip segment */
  uint32_t sample;                    /* the sample of a sample-frequency fragment */
  uint32_t coverage_q16;              /* antialiased line coverage in 1/65536, in [1, 65536] */
  int32_t centroid_x, centroid_y;     /* centroid offset from the pixel centre, 1/16 px */
  int32_t ddx_x, ddx_y, ddy_x, ddy_y; /* evaluation derivatives, 1/16 px */
  double area;                        /* exact area in px^2, rounded to the nearest double */
  const char* area_text;              /* the exact area, "num/den" or "num" */
  uint8_t alpha;                      /* the area as 8-bit alpha: floor(area * 255 + 1/2) */
  uint32_t part;                      /* a clipped primitive's part */
  int64_t bary[3];                    /* exact barycentrics e0, e1, e2 (PIPE.BARY.EXACT) ... */
  int64_t bary_area;   /* ... over their sum A: weight of vertex i = bary[i] / bary_area */
  uint32_t passed;     /* samples that passed the depth test (== mask without depth) */
  size_t depth_count;  /* one depth per sample of mask (none for a killed fragment) */
  const double* depth; /* as stored: d16, d24 the UNORM integer; d32f the float value */
  size_t attr_count;   /* one value per declared attribute (none for a killed fragment) */
  const float* attr;   /* in the order of the scene's "attributes" */
} rr_fragment;

/* Fills *out with fragment `index` (0 <= index < count; else RR_ERROR_OUT_OF_RANGE). */
rr_status rr_render_fragment(const rr_render* render, size_t index, rr_fragment* out);

/* Releases a render (NULL: nothing); the pointers of its fragments become invalid. */
void rr_render_free(rr_render* render);

/* ---- Explanations ---------------------------------------------------------------------- */

/* Explains pixel (x, y) as `rastrules explain --pixel x,y` prints it (as_json nonzero: its
 * --json output): the snapped vertices, the edge values at the centre and the rule that
 * decided, per primitive; for a pipeline scene the fragments there and what they carry.
 * *out is a new NUL-terminated string, released with rr_string_free. A pixel outside the
 * target is RR_ERROR_OUT_OF_RANGE. */
rr_status rr_explain(const rr_scene* scene, int32_t x, int32_t y, int as_json, char** out);

/* Releases a string returned by the library (NULL: nothing). */
void rr_string_free(char* s);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* RASTRULES_RASTRULES_H */
