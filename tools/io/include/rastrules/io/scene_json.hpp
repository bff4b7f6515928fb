// SPDX-License-Identifier: MIT
// Scene files (spec/scene.md, version 1): a strict streaming reader and a writer.
// Implements: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.INPUT.ERRORS (the reader's part),
//             SCENE.MSAA (the keys; the rules between them are prepare()'s, MSAA.LIMITS),
//             SCENE.PIPELINE (the keys, their types, counts and finiteness)
// Does not implement: target limits and vertex validity, which the kernel's prepare() checks
// (SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID) after reading; the viewport's ranges and the
// positions' magnitude, which run_pipeline() checks (PIPE.VIEWPORT.RANGE, PIPE.INPUT.POSITION).

#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include <cstdint>

#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::io {

// Largest scene file accepted, in bytes. Memory used by reading is proportional to the input
// (about 40 bytes per primitive in memory for at least 40 bytes of text), so this bounds it.
// rule: SCENE.INPUT.LIMITS
inline constexpr std::size_t kMaxSceneBytes = std::size_t{64} << 20; // 64 MiB

// The other limits of SCENE.INPUT.LIMITS (spec/scene.md states why and the memory each bounds).
// Most primitives in one scene.
inline constexpr std::size_t kMaxScenePrimitives = std::size_t{1} << 20; // 1048576
// Most vertices in one primitive's "v" (only a line strip can have more than 3).
inline constexpr std::size_t kMaxStripVertices = std::size_t{1} << 16; // 65536
// Deepest nesting of JSON arrays and objects: scene, primitives, primitive, v, vertex. The
// schema itself enforces it (an array or object where a scalar belongs is a type error, found
// at its first character), so the parser's stack never holds more than this many levels.
inline constexpr std::size_t kMaxSceneNesting = 5;
// Default of `rastrules render --max-fragments`: most fragments one render may produce.
inline constexpr std::uint64_t kDefaultMaxFragments = std::uint64_t{1} << 26; // 67108864

// Returns the scene described by the JSON text, or the first error found in reading order.
// Errors name the field path (`primitives[2].v[1][0]: must be a number ...`) or, for
// malformed JSON, the parser's position (`(json): parse error at line 1, column 7: ...`).
// Coordinates are converted from their decimal text directly to the nearest float32
// (SCENE.NUMBER.FLOAT32); the strings "NaN", "Infinity" and "-Infinity" are accepted and left
// for prepare() to reject. The pipeline keys (SCENE.PIPELINE: "viewport", "transform",
// "depth", "attributes", "provoking_vertex", and "z", "w", "pos", "attr" in a primitive) fill
// the scene's pipeline state; checks between keys that may come in any order, such as "attr"
// against "attributes", are made when the root object ends.
// rule: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.PIPELINE, SCENE.INPUT.ERRORS
[[nodiscard]] std::variant<Scene, SceneError> read_scene(std::string_view json_text);

// read_scene() in two steps, for the tests and the fuzz target that compare them:
// read_scene_fast() reads the common large scene (a "target" and a list of triangles given
// by "type" and "v" alone, numbers as plain JSON numbers, nothing else) in one pass without the
// general reader's per-field bookkeeping, and returns nullopt for any text outside that form
// (then read_scene_general(), the strict general reader, decides, errors included). When
// read_scene_fast() returns a scene, it is the scene read_scene_general() returns for the same
// text (SCENE.INPUT.FAST_READER: a filter that never changes the answer).
// rule: SCENE.INPUT.FAST_READER
[[nodiscard]] std::optional<Scene> read_scene_fast(std::string_view json_text);
[[nodiscard]] std::variant<Scene, SceneError> read_scene_general(std::string_view json_text);

// The fast reader's form read as coordinates alone, for callers that need nothing else of the
// triangles (render --count through the batch counter): the scene read_scene_fast() returns
// without its primitives, and six floats a triangle (x0 y0 x1 y1 x2 y2) in primitive order.
// nullopt exactly where read_scene_fast() declines. No Primitive is built (a million of them
// took more time than the batch counter's whole count).
// rule: SCENE.INPUT.FAST_READER
struct FastTriangles {
  Scene scene;           // every field but primitives (empty)
  std::vector<float> xy; // 6 * the number of triangles
};
[[nodiscard]] std::optional<FastTriangles> read_triangles_fast(std::string_view json_text);
// The same, the list read in up to `threads` parts of at least min_part_bytes of text each on
// as many threads (parts that do not join where they meet, as a guess at a part's start can
// make them, are read again on one thread): the same result for every thread count
// (FAST.THREADS.DETERMINISTIC).
[[nodiscard]] std::optional<FastTriangles>
read_triangles_fast(std::string_view json_text, unsigned threads,
                    std::size_t min_part_bytes = std::size_t{1} << 20);

// Takes the triangles of a scene of the fast form as stream_triangles_fast reads them.
class TriangleStream {
public:
  virtual ~TriangleStream() = default;
  // The scene of the keys before the list (its target and state; no primitives), before any
  // triangle. false declines.
  virtual bool begin(const Scene& head) = 0;
  // After begin(): at most this many triangles follow (a bound from the text's length), for a
  // consumer that reserves its records once.
  virtual void reserve(std::size_t triangles) { (void)triangles; }
  // The next triangles of the list in order, six floats each (x0 y0 x1 y1 x2 y2), at most
  // kTriangleStreamChunk at a time. false declines.
  virtual bool triangles(std::span<const float> xy) = 0;
};
inline constexpr std::size_t kTriangleStreamChunk = 16384;

// read_triangles_fast without the list: the triangles handed to `stream` in chunks as they are
// read (a 10^6-triangle scene's 24 MB of coordinates never held at once, and a consumer can work
// while the text is read), for the text of the fast form whose root keys all come before
// "primitives" (the order generated scenes use). Returns the scene read_triangles_fast gives, or
// nullopt where it declines, where a root key follows the list, or where the stream declined:
// the stream may then have taken part of the list, and the caller reads the text another way.
[[nodiscard]] std::optional<Scene> stream_triangles_fast(std::string_view json_text,
                                                         TriangleStream& stream);

// Returns the whole content of a scene file ("-" is standard input), or an error naming the
// file when it cannot be read or is larger than kMaxSceneBytes.
[[nodiscard]] std::variant<std::string, SceneError> read_scene_file(const std::string& path);

// A scene file's text without a copy where it can be: a regular file is mapped into memory
// (read-only, its pages populated at once), anything else (standard input, a pipe) read into a
// string. Reading a 56 MB scene into a string cost 45 ms of page faults, zeroing and copying
// against 3 ms for the mapping (rastrules_render_split). A mapped file that another process
// truncates while it is read raises SIGBUS in the reader: the command line turns that signal
// into a one-line error (exit 2); other programs that map scenes handle it themselves or use
// read_scene_file. Move-only.
class SceneText {
public:
  SceneText() = default;
  explicit SceneText(std::string text) : owned_(std::move(text)) {}
  SceneText(const SceneText&) = delete;
  SceneText& operator=(const SceneText&) = delete;
  SceneText(SceneText&& other) noexcept;
  SceneText& operator=(SceneText&& other) noexcept;
  ~SceneText();

  [[nodiscard]] std::string_view view() const {
    return map_ != nullptr ? std::string_view(map_, size_) : std::string_view(owned_);
  }
  [[nodiscard]] bool mapped() const { return map_ != nullptr; }

private:
  friend std::variant<SceneText, SceneError> open_scene_file(const std::string& path);
  std::string owned_;
  const char* map_ = nullptr;
  std::size_t size_ = 0;
};

// The text of a scene file as read_scene_file reads it ("-" is standard input; the same errors
// and limit), mapped where the file is a regular one.
[[nodiscard]] std::variant<SceneText, SceneError> open_scene_file(const std::string& path);

// Returns the scene as JSON text that read_scene() reads back as the same scene (same_scene),
// one primitive per line: the target, state and multisampling keys, then "provoking_vertex"
// (when "last"), "viewport", "transform", "depth" and "attributes" when present (every sub-key
// written), and per primitive "v" with "z" and "w" when given, or "pos" (4 coordinates each),
// and "attr". Floats are written in their shortest form that reads back to the same float32;
// NaN and infinities as the strings "NaN", "Infinity", "-Infinity".
// rule: SCENE.FORMAT.V1, SCENE.PIPELINE
[[nodiscard]] std::string write_scene(const Scene& scene);

// Returns the scene-file name of a line mode: "d3d", "vulkan-bresenham", "quad-wide",
// "quad-narrow" (SCENE.LINE_MODE).
// rule: SCENE.LINE_MODE
[[nodiscard]] std::string_view line_mode_name(LineMode m);

// Returns the shortest decimal text that reads back (SCENE.NUMBER.FLOAT32) to exactly v,
// or "NaN", "Infinity", "-Infinity".
[[nodiscard]] std::string format_float(float v);

// Returns the float32 nearest to the decimal number `text` (JSON number syntax), ties to
// even, converted directly from the text; values too large become infinities, values too
// small zeros of the right sign. nullopt when the text is not a number.
// rule: SCENE.NUMBER.FLOAT32
[[nodiscard]] std::optional<float> decimal_to_float32(std::string_view text);

// Returns s with every byte outside printable ASCII written as \xNN, cut to max_len bytes
// (with "..." appended when cut), so that it is safe inside a one-line error message.
[[nodiscard]] std::string printable(std::string_view s, std::size_t max_len = 60);

// Returns whether two scenes hold the same state, pipeline state and bit-identical numbers
// (any NaN equals any NaN: NaN payloads are not part of a scene file). Used to check that a
// written scene reads back as itself (showcase, fuzz targets).
[[nodiscard]] bool same_scene(const Scene& a, const Scene& b);

// The scene-file names of the pipeline enumerations (SCENE.PIPELINE): "perspective", "linear",
// "flat"; "center", "centroid", "sample"; "d16", "d24", "d32f"; "never", "less", ...; "first",
// "last".
[[nodiscard]] std::string_view interpolation_name(pipe::Interpolation i);
[[nodiscard]] std::string_view location_name(pipe::Location l);
[[nodiscard]] std::string_view depth_format_name(pipe::DepthFormat f);
[[nodiscard]] std::string_view compare_func_name(pipe::CompareFunc f);
[[nodiscard]] std::string_view provoking_name(pipe::Provoking p);

// Returns s as a JSON string literal (quotes included; '"', '\\' and control characters
// escaped; other bytes, valid UTF-8 as the reader checked, as they are).
[[nodiscard]] std::string json_string(std::string_view s);

} // namespace rastrules::io
