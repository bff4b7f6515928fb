// SPDX-License-Identifier: MIT
// rastrules render: the fragment list, the picture and the resolved target of a scene.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS, SCENE.OUTPUT.MSAA,
//             FAST.THREADS.DETERMINISTIC, FAST.ISA.DISPATCH (--isa)

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/isa.hpp"

#include "rastrules/parallel.hpp"

namespace rastrules::cli {

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS
int run_render(const Args& args) {
  std::optional<std::string> scene_path, fragments_path, png_path, resolve_path;
  std::optional<int> scale;
  std::uint64_t max_fragments = io::kDefaultMaxFragments;
  RenderOptions options;
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
    } else if (is("--resolve")) {
      resolve_path = value("--resolve");
      if (!resolve_path || resolve_path->empty()) return usage_error("--resolve needs a file name");
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
    } else if (is("--threads")) {
      // rule: FAST.THREADS.DETERMINISTIC
      const std::optional<std::string> v = value("--threads");
      const auto n = v ? parse_int(*v, 1, kMaxThreads) : std::nullopt;
      if (!n) {
        return error("--threads needs an integer in [1, " + std::to_string(kMaxThreads) + "], got " +
                     (v ? "\"" + *v + "\"" : std::string("nothing")));
      }
      options.threads = static_cast<unsigned>(*n);
    } else if (is("--traversal")) {
      const std::optional<std::string> v = value("--traversal");
      const auto t = v ? parse_traversal(*v) : std::nullopt;
      if (!t) {
        return error("--traversal needs \"plain\" or \"fast\", got " +
                     (v ? "\"" + *v + "\"" : std::string("nothing")));
      }
      options.traversal = *t;
    } else if (is("--isa")) {
      // rule: FAST.ISA.DISPATCH
      const std::optional<std::string> v = value("--isa");
      if (v && *v == "auto") {
        options.isa = std::nullopt;
      } else {
        const auto isa = v ? parse_isa(*v) : std::nullopt;
        if (!isa) {
          return error("--isa needs \"scalar\", \"avx2\", \"avx512\" or \"auto\", got " +
                       (v ? "\"" + *v + "\"" : std::string("nothing")));
        }
        if (!isa_supported(*isa)) {
          return error("--isa " + *v + ": this processor (or this build) cannot run " + *v +
                       " (" + std::string(kMaxIsaVariable) + " may cap it); use --isa auto (here " +
                       std::string(to_string(best_isa())) + ")");
        }
        options.isa = *isa;
      }
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("render: unknown option \"" + a + "\"");
    } else if (scene_path) {
      return usage_error("render: more than one scene file");
    } else {
      scene_path = a;
    }
  }
  // rule: FAST.ISA.DISPATCH
  if (const char* cap = std::getenv(kMaxIsaVariable); cap != nullptr && *cap != '\0' && !parse_isa(cap)) {
    return error(std::string(kMaxIsaVariable) + " needs \"scalar\", \"avx2\" or \"avx512\", got \"" +
                 cap + "\"");
  }
  if (!scene_path) return usage_error("render: missing SCENE.json");
  if (!fragments_path && !png_path && !resolve_path) {
    return usage_error("render: give --fragments OUT.json, --png OUT.png or --resolve OUT.png");
  }
  const int to_stdout = (fragments_path && *fragments_path == "-") + (png_path && *png_path == "-") +
                        (resolve_path && *resolve_path == "-");
  if (to_stdout > 1) {
    return usage_error("render: only one of --fragments, --png and --resolve can be standard output");
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

  // rule: MSAA.LIMITS, MSAA.RESOLVE.AVERAGE
  // The resolve's sample buffer is checked before any work; resolve() checks it again.
  if (resolve_path) {
    const std::int64_t samples = std::int64_t{scene.width} * scene.height * scene.msaa.count();
    if (samples > kMaxResolveSamples) {
      return error("--resolve: the " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
                   " target with " + std::to_string(scene.msaa.count()) + " samples has " +
                   std::to_string(samples) + " samples, more than " +
                   std::to_string(kMaxResolveSamples) + " (limit MSAA.LIMITS)");
    }
  }

  OutputFile fragments_file, png_file, resolve_file;
  if (fragments_path) {
    if (auto err = fragments_file.open(*fragments_path)) return error(*err);
  }
  if (png_path) {
    if (auto err = png_file.open(*png_path)) return error(*err);
  }
  if (resolve_path) {
    if (auto err = resolve_file.open(*resolve_path)) return error(*err);
  }

  // Fragments are streamed primitive by primitive in the (prim, y, x, seg) order of
  // SCENE.OUTPUT.FRAGMENTS: a triangle's as the traversal finds them (memory independent of
  // their number), a point's or line's after the kernel sorts that one primitive's list. The
  // coverage map (for the picture) is width * height.
  std::optional<io::FragmentWriter> writer;
  if (fragments_path) writer.emplace(fragments_file.get());
  std::unique_ptr<io::CoverageMap> coverage;
  if (png_path) {
    coverage = std::make_unique<io::CoverageMap>(scene.width, scene.height);
    if (io::samples_visible(scene, picture_scale)) coverage->record_samples(scene.msaa.count());
  }
  // The resolve needs every fragment (at most --max-fragments of them).
  std::vector<Fragment> all;
  bool in_order = true;
  std::uint64_t fragment_count = 0;
  // rule: SCENE.INPUT.LIMITS
  // The work limit: counted while streaming; the first fragment beyond it stops the traversal
  // (the exception unwinds out of the kernel's walk) and the outputs, still under their
  // temporary names, are removed by ~OutputFile.
  struct TooManyFragments {};
  const auto emit = [&](const Fragment& f) {
    if (++fragment_count > max_fragments) throw TooManyFragments{};
    if (writer)
      in_order = writer->add(f) && in_order;
    if (coverage)
      coverage->add_fragment(f);
    if (resolve_path)
      all.push_back(f);
  };
  const auto too_many_held = [&](std::size_t p) {
    return error("render: primitives[" + std::to_string(p) + "] touches more than " +
                 std::to_string(2 * max_fragments) +
                 " pixels or fragments that must be held to be sorted (limit SCENE.INPUT.LIMITS, 2 x "
                 "--max-fragments); raise it with --max-fragments N");
  };
  // A primitive that is collected before it is emitted holds at most 2 * max_fragments
  // entries: a pixel is held at most twice (once per triangle of a point or quadrilateral
  // segment), so one that needs more has more than max_fragments fragments, except when
  // the sample mask removes the samples it covers (then the limit counts touched pixels).
  try {
    if (options.threads <= 1) {
      for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
        if (!for_each_fragment_bounded(scene, p, 2 * max_fragments, options, emit)) return too_many_held(p);
      }
    } else {
      // rule: FAST.THREADS.DETERMINISTIC
      // A pool created once rasterizes chunks of kChunk consecutive primitives, each chunk into
      // its own buffer (slot u % window), at most `window` chunks ahead of this thread, which
      // emits the buffers in primitive order through the same checks as above: the outputs,
      // the error and the primitive it names are those of one thread. A chunk stops at its first
      // primitive that needs more than it may hold (reported when the chunk is emitted, after
      // the fragments before it) or when its buffer passes max_fragments + 1 fragments (enough
      // to pass the limit wherever it is emitted), so at most 4 * threads such buffers are held.
      constexpr std::size_t kChunk = 64;  // primitives per unit: amortises the hand-over
      struct Unit {
        std::vector<Fragment> fragments;
        std::optional<std::size_t> too_many_held;  // the primitive that did not fit, if any
      };
      struct BufferFull {};
      struct TooManyHeld {
        std::size_t p;
      };
      const std::size_t window = std::size_t{4} * options.threads;
      const std::size_t n_units = (scene.primitives.size() + kChunk - 1) / kChunk;
      std::vector<Unit> units(window);
      try {
        run_ordered(
            n_units, options.threads, window,
            [&](std::size_t u) {
              Unit& unit = units[u % window];
              unit.fragments.clear();
              unit.too_many_held.reset();
              const std::size_t end = std::min(scene.primitives.size(), (u + 1) * kChunk);
              try {
                for (std::size_t p = u * kChunk; p < end; ++p) {
                  const bool fits = for_each_fragment_bounded(
                      scene, p, 2 * max_fragments, options, [&](const Fragment& f) {
                        if (unit.fragments.size() > max_fragments) throw BufferFull{};
                        unit.fragments.push_back(f);
                      });
                  if (!fits) {
                    unit.too_many_held = p;
                    return;
                  }
                }
              } catch (const BufferFull&) {
                // Emitting the buffer passes the limit: nothing after it is needed.
              }
            },
            [&](std::size_t u) {
              const Unit& unit = units[u % window];
              for (const Fragment& f : unit.fragments) emit(f);
              if (unit.too_many_held) throw TooManyHeld{*unit.too_many_held};
            });
      } catch (const TooManyHeld& held) {
        return too_many_held(held.p);
      }
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
  // rule: MSAA.RESOLVE.AVERAGE
  if (resolve_path) {
    const auto resolved = resolve(scene, all);
    if (const auto* err = std::get_if<SceneError>(&resolved)) return error("--resolve: " + err->what());
    const ResolvedImage& r = std::get<ResolvedImage>(resolved);
    std::vector<std::uint8_t> rgba;
    rgba.reserve(r.pixels.size() * 4);
    for (const Rgba8& p : r.pixels) rgba.insert(rgba.end(), p.begin(), p.end());
    if (auto err = io::write_png_rgba(resolve_file.get(), r.width, r.height, rgba)) {
      return error(*resolve_path + ": " + *err);
    }
  }
  // No partial result: when one output cannot be moved into place, the ones already in place
  // are removed.
  std::vector<std::string> committed;
  auto commit = [&](OutputFile& file, const std::optional<std::string>& path) -> std::optional<std::string> {
    if (!path) return std::nullopt;
    if (auto err = file.commit()) {
      std::error_code ec;
      for (const std::string& done : committed) {
        if (done != "-" && std::filesystem::is_regular_file(std::filesystem::symlink_status(done, ec))) {
          std::filesystem::remove(done, ec);
        }
      }
      return err;
    }
    committed.push_back(*path);
    return std::nullopt;
  };
  if (auto err = commit(fragments_file, fragments_path)) return error(*err);
  if (auto err = commit(png_file, png_path)) return error(*err);
  if (auto err = commit(resolve_file, resolve_path)) return error(*err);
  if (to_stdout == 0) {
    std::string outputs;
    for (const auto* p : {&fragments_path, &png_path, &resolve_path}) {
      if (*p) outputs += (outputs.empty() ? " -> " : ", ") + **p;
    }
    std::printf("render: %zu primitives, %llu fragments%s\n", scene.primitives.size(),
                static_cast<unsigned long long>(fragment_count), outputs.c_str());
  }
  return kExitOk;
}

}  // namespace rastrules::cli
