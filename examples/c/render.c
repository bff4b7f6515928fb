/* SPDX-License-Identifier: MIT */
/*
 * A C99 program on the C API (rastrules/rastrules.h): reads a scene file, optionally gives it
 * a profile, renders it and prints its fragments as JSON, one per line, in the order and with
 * the keys of `rastrules render SCENE --fragments -` ("coverage_q16" instead of the decimal
 * "coverage", attributes as a list); with --explain X,Y it prints the explanation of a pixel.
 * Bad input: the library's one-line message on standard error, exit status 2.
 *
 *   render SCENE.json [--profile d3d11|vulkan|opengl] [--explain X,Y]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rastrules/rastrules.h"

static int fail(rr_status status) {
  fprintf(stderr, "render: %s: %s\n", rr_status_name(status), rr_last_error());
  return 2;
}

static void print_fragment(const rr_fragment* f, int first) {
  size_t k;
  printf("%s\n  {\"prim\": %u", first ? "" : ",", (unsigned)f->prim);
  if (f->flags & RR_FRAGMENT_PART)
    printf(", \"part\": %u", (unsigned)f->part);
  printf(", \"x\": %d, \"y\": %d, \"mask\": %u", (int)f->x, (int)f->y, (unsigned)f->mask);
  if (f->flags & RR_FRAGMENT_SEG)
    printf(", \"seg\": %u", (unsigned)f->seg);
  if (f->flags & RR_FRAGMENT_SAMPLE)
    printf(", \"sample\": %u", (unsigned)f->sample);
  if (f->flags & RR_FRAGMENT_HELPER)
    printf(", \"helper\": true");
  if (f->flags & RR_FRAGMENT_COVERAGE)
    printf(", \"coverage_q16\": %u", (unsigned)f->coverage_q16);
  if (f->flags & RR_FRAGMENT_AREA)
    printf(", \"area\": \"%s\", \"alpha\": %u", f->area_text, (unsigned)f->alpha);
  if (f->flags & RR_FRAGMENT_BARY) {
    printf(", \"bary\": [%lld, %lld, %lld, %lld]", (long long)f->bary[0], (long long)f->bary[1],
           (long long)f->bary[2], (long long)f->bary_area);
  }
  if (f->attr_count > 0) {
    printf(", \"attr\": [");
    for (k = 0; k < f->attr_count; ++k)
      printf("%s%.9g", k ? ", " : "", (double)f->attr[k]);
    printf("]");
  }
  if (f->flags & RR_FRAGMENT_DEPTH) {
    if (f->depth_count > 0) {
      printf(", \"depth\": [");
      for (k = 0; k < f->depth_count; ++k)
        printf("%s%.17g", k ? ", " : "", f->depth[k]);
      printf("]");
    }
    printf(", \"passed\": %u", (unsigned)f->passed);
  }
  printf("}");
}

int main(int argc, char** argv) {
  const char* path = NULL;
  const char* profile = NULL;
  const char* pixel = NULL;
  rr_scene* scene = NULL;
  rr_render* render = NULL;
  rr_status status;
  size_t count = 0, i;
  int a;
  for (a = 1; a < argc; ++a) {
    if (strcmp(argv[a], "--profile") == 0 && a + 1 < argc) {
      profile = argv[++a];
    } else if (strcmp(argv[a], "--explain") == 0 && a + 1 < argc) {
      pixel = argv[++a];
    } else if (path == NULL) {
      path = argv[a];
    } else {
      path = NULL;
      break;
    }
  }
  if (path == NULL) {
    fprintf(stderr, "usage: render SCENE.json [--profile NAME] [--explain X,Y] (rastrules %s)\n",
            rr_version());
    return 2;
  }
  status = rr_scene_from_file(path, &scene);
  if (status != RR_OK)
    return fail(status);
  if (profile != NULL && (status = rr_scene_set_profile(scene, profile)) != RR_OK) {
    rr_scene_free(scene);
    return fail(status);
  }
  if (pixel != NULL) {
    int x = 0, y = 0;
    char* text = NULL;
    if (sscanf(pixel, "%d,%d", &x, &y) != 2) {
      rr_scene_free(scene);
      fprintf(stderr, "render: --explain needs X,Y\n");
      return 2;
    }
    status = rr_explain(scene, x, y, 0, &text);
    rr_scene_free(scene);
    if (status != RR_OK)
      return fail(status);
    fputs(text, stdout);
    rr_string_free(text);
    return 0;
  }
  status = rr_render_scene(scene, NULL, &render);
  rr_scene_free(scene); /* the render keeps what it needs */
  if (status != RR_OK)
    return fail(status);
  rr_render_fragment_count(render, &count);
  printf("{\"fragments\": [");
  for (i = 0; i < count; ++i) {
    rr_fragment f;
    if ((status = rr_render_fragment(render, i, &f)) != RR_OK) {
      rr_render_free(render);
      return fail(status);
    }
    print_fragment(&f, i == 0);
  }
  printf(count == 0 ? "]}\n" : "\n]}\n");
  rr_render_free(render);
  return 0;
}
