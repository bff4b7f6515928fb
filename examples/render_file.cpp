// SPDX-License-Identifier: MIT
// A scene file through the installed io component (rastrules::io): read a window-space scene
// (spec/scene.md), rasterize it with the kernel, and print the fragment list as JSON, as
// `rastrules render SCENE --fragments -` does. Bad input gets the reader's one-line error.
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/scene.hpp"

int main(int argc, char** argv) {
  using namespace rastrules;
  if (argc != 2) {
    std::fprintf(stderr, "usage: render_file SCENE.json\n");
    return 2;
  }
  const auto text = io::read_scene_file(argv[1]);
  if (const auto* e = std::get_if<SceneError>(&text)) {
    std::fprintf(stderr, "render_file: %s\n", e->what().c_str());
    return 2;
  }
  const auto scene = io::read_scene(std::get<std::string>(text));
  if (const auto* e = std::get_if<SceneError>(&scene)) {
    std::fprintf(stderr, "render_file: %s\n", e->what().c_str());
    return 2;
  }
  const auto fragments = render(std::get<Scene>(scene));
  if (const auto* e = std::get_if<SceneError>(&fragments)) {
    std::fprintf(stderr, "render_file: %s\n", e->what().c_str());
    return 2;
  }
  std::fputs(io::fragments_to_json(std::get<std::vector<Fragment>>(fragments)).c_str(), stdout);
  return 0;
}
