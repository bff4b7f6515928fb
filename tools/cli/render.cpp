// SPDX-License-Identifier: MIT
// rastrules render: the fragment list and the picture of a scene.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <memory>
#include <optional>
#include <string>

#include "cli.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::cli {

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS
int run_render(const Args& args) {
  std::optional<std::string> scene_path, fragments_path, png_path;
  std::optional<int> scale;
  std::uint64_t max_fragments = io::kDefaultMaxFragments;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) -> std::optional<std::string> {
      const std::string prefix = std::string(flag) + "=";
      if (a.rfind(prefix, 0) == 0) return a.substr(prefix.size());
      if (i + 1 < args.size()) return args[++i];
      return std::nullopt;
    };
    auto is = [&](const char* flag) { return a == flag || a.rfind(std::string(flag) + "=", 0) == 0; };
    if (a == "--help" || a == "-h") {
      print_usage(stdout);
      return kExitOk;
    } else if (is("--fragments")) {
      fragments_path = value("--fragments");
      if (!fragments_path || fragments_path->empty()) return usage_error("--fragments needs a file name");
    } else if (is("--png")) {
      png_path = value("--png");
      if (!png_path || png_path->empty()) return usage_error("--png needs a file name");
    } else if (is("--scale")) {
      const std::optional<std::string> v = value("--scale");
      const auto n = v ? parse_int(*v, 1, io::kMaxPictureSide) : std::nullopt;
      if (!n) return usage_error("--scale needs an integer in [1, 4096]");
      scale = static_cast<int>(*n);
    } else if (is("--max-fragments")) {
      // rule: SCENE.INPUT.LIMITS
      const std::optional<std::string> v = value("--max-fragments");
      const auto n = v ? parse_int(*v, 1, std::int64_t{1} << 40) : std::nullopt;
      if (!n) return usage_error("--max-fragments needs an integer in [1, 2^40]");
      max_fragments = static_cast<std::uint64_t>(*n);
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("render: unknown option \"" + a + "\"");
    } else if (scene_path) {
      return usage_error("render: more than one scene file");
    } else {
      scene_path = a;
    }
  }
  if (!scene_path) return usage_error("render: missing SCENE.json");
  if (!fragments_path && !png_path) return usage_error("render: give --fragments OUT.json, --png OUT.png or both");
  if (fragments_path && png_path && *fragments_path == "-" && *png_path == "-") {
    return usage_error("render: --fragments and --png cannot both be standard output");
  }
  if (scale && !png_path) return usage_error("render: --scale needs --png");

  const std::optional<LoadedScene> loaded = load_scene(*scene_path);
  if (!loaded) return kExitBadInput;
  const PreparedScene& scene = loaded->prepared;

  int picture_scale = 0;
  if (png_path) {
    picture_scale = scale ? *scale : io::default_picture_scale(scene.width, scene.height);
    if (!io::picture_fits(scene.width, scene.height, picture_scale)) {
      return error("--png: a picture of the " + std::to_string(scene.width) + "x" +
                   std::to_string(scene.height) + " target" +
                   (scale ? " at --scale " + std::to_string(*scale) : std::string()) +
                   " would be larger than " + std::to_string(io::kMaxPictureSide) +
                   " pixels a side");
    }
  }

  OutputFile fragments_file, png_file;
  if (fragments_path) {
    if (auto err = fragments_file.open(*fragments_path)) return error(*err);
  }
  if (png_path) {
    if (auto err = png_file.open(*png_path)) return error(*err);
  }

  // Fragments are streamed primitive by primitive in the (prim, y, x, seg) order of
  // SCENE.OUTPUT.FRAGMENTS: a triangle's as the traversal finds them (memory independent of
  // their number), a point's or line's after the kernel sorts that one primitive's list. The
  // coverage map (for the picture) is width * height.
  std::optional<io::FragmentWriter> writer;
  if (fragments_path) writer.emplace(fragments_file.get());
  std::unique_ptr<io::CoverageMap> coverage;
  if (png_path) coverage = std::make_unique<io::CoverageMap>(scene.width, scene.height);
  bool in_order = true;
  std::uint64_t fragment_count = 0;
  // rule: SCENE.INPUT.LIMITS
  // The work limit: counted while streaming; the first fragment beyond it stops the traversal
  // (the exception unwinds out of the kernel's walk) and the outputs, still under their
  // temporary names, are removed by ~OutputFile.
  struct TooManyFragments {};
  try {
    for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
      for_each_fragment(scene, p, [&](const Fragment& f) {
        if (++fragment_count > max_fragments) throw TooManyFragments{};
        if (writer)
          in_order = writer->add(f) && in_order;
        if (coverage)
          coverage->add(f.prim, f.x, f.y, f.coverage_q16);
      });
    }
  } catch (const TooManyFragments&) {
    return error("render: more than " + std::to_string(max_fragments) +
                 " fragments (limit SCENE.INPUT.LIMITS); raise it with --max-fragments N");
  }
  if (!in_order)
    return error("internal error: the kernel emitted fragments out of (prim, y, x, seg) order");
  if (writer) {
    if (!writer->finish()) return error(*fragments_path + ": write failed");
  }
  if (png_path) {
    const io::Image image = io::draw_picture(scene, *coverage, picture_scale);
    if (auto err = io::write_png(png_file.get(), image)) return error(*png_path + ": " + *err);
  }
  if (fragments_path) {
    if (auto err = fragments_file.commit()) return error(*err);
  }
  if (png_path) {
    if (auto err = png_file.commit()) {
      // No partial result: the fragment list goes too.
      std::error_code ec;
      if (fragments_path && *fragments_path != "-" &&
          std::filesystem::is_regular_file(std::filesystem::symlink_status(*fragments_path, ec))) {
        std::filesystem::remove(*fragments_path, ec);
      }
      return error(*err);
    }
  }
  const bool stdout_used = (fragments_path && *fragments_path == "-") || (png_path && *png_path == "-");
  if (!stdout_used) {
    std::printf("render: %zu primitives, %llu fragments%s%s%s%s\n", scene.primitives.size(),
                static_cast<unsigned long long>(fragment_count), fragments_path ? " -> " : "",
                fragments_path ? fragments_path->c_str() : "",
                png_path ? (fragments_path ? ", " : " -> ") : "",
                png_path ? png_path->c_str() : "");
  }
  return kExitOk;
}

}  // namespace rastrules::cli
