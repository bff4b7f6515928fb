// SPDX-License-Identifier: MIT
// rastrules showcase: render the built-in scenes, write their files and pictures, and
// compare every fragment list with the exact oracle (properties/oracle).

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <tuple>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "showcase_scenes.hpp"

namespace rastrules::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

oracle::Scene to_oracle(const Scene& s) {
  oracle::Scene o;
  o.width = s.width;
  o.height = s.height;
  o.state.cull = std::string(to_string(s.state.cull));
  o.state.front_face = std::string(to_string(s.state.front_face));
  o.state.fill = std::string(to_string(s.state.fill));
  o.triangles.reserve(s.primitives.size());
  for (const Primitive& p : s.primitives) o.triangles.push_back(p.v);
  return o;
}

// Returns whether two scenes hold the same state and bit-identical coordinates.
bool same_scene(const Scene& a, const Scene& b) {
  if (a.width != b.width || a.height != b.height || a.state.cull != b.state.cull ||
      a.state.front_face != b.state.front_face || a.state.fill != b.state.fill ||
      a.primitives.size() != b.primitives.size()) {
    return false;
  }
  for (std::size_t p = 0; p < a.primitives.size(); ++p) {
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 2; ++k) {
        if (std::bit_cast<std::uint32_t>(a.primitives[p].v[i][k]) !=
            std::bit_cast<std::uint32_t>(b.primitives[p].v[i][k])) {
          return false;
        }
      }
    }
  }
  return true;
}

std::optional<std::string> write_text(const std::filesystem::path& path, const std::string& text) {
  OutputFile f;
  if (auto err = f.open(path.string())) return err;
  if (std::fwrite(text.data(), 1, text.size(), f.get()) != text.size()) return path.string() + ": write failed";
  return f.commit();
}

std::optional<std::string> write_picture(const std::filesystem::path& path, const PreparedScene& scene,
                                         const std::vector<Fragment>& fragments) {
  io::CoverageMap coverage(scene.width, scene.height);
  for (const Fragment& f : fragments) coverage.add(f.prim, f.x, f.y);
  const io::Image image =
      io::draw_picture(scene, coverage, io::default_picture_scale(scene.width, scene.height));
  OutputFile f;
  if (auto err = f.open(path.string())) return err;
  if (auto err = io::write_png(f.get(), image)) return path.string() + ": " + *err;
  return f.commit();
}

// Returns up to `limit` lines describing fragments found by only one side.
std::vector<std::string> differences(const std::vector<Fragment>& kernel,
                                     const std::vector<oracle::Fragment>& exact, std::size_t limit) {
  std::vector<std::string> out;
  std::size_t i = 0, j = 0;
  auto key = [](auto& f) { return std::tuple(f.prim, f.y, f.x); };
  auto text = [](const char* who, auto& f) {
    return std::string(who) + ": prim " + std::to_string(f.prim) + " pixel (" + std::to_string(f.x) +
           ", " + std::to_string(f.y) + ")";
  };
  while ((i < kernel.size() || j < exact.size()) && out.size() < limit) {
    if (j == exact.size() || (i < kernel.size() && key(kernel[i]) < key(exact[j]))) {
      out.push_back(text("only the kernel covers", kernel[i++]));
    } else if (i == kernel.size() || key(exact[j]) < key(kernel[i])) {
      out.push_back(text("only the oracle covers", exact[j++]));
    } else {
      ++i;
      ++j;
    }
  }
  return out;
}

}  // namespace

int run_showcase(const Args& args) {
  std::optional<std::string> out_dir;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      print_usage(stdout);
      return kExitOk;
    } else if (a == "--out" && i + 1 < args.size()) {
      out_dir = args[++i];
    } else if (a.rfind("--out=", 0) == 0) {
      out_dir = a.substr(6);
    } else if (a == "--out") {
      return usage_error("--out needs a directory");
    } else {
      return usage_error("showcase: unexpected argument \"" + a + "\"");
    }
  }
  if (!out_dir || out_dir->empty()) return usage_error("showcase: missing --out DIR");
  const std::filesystem::path dir(*out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    return error(*out_dir + ": cannot create the directory" + (ec ? ": " + ec.message() : std::string()));
  }

  const std::vector<ShowcaseScene> scenes = showcase_scenes();
  std::printf("%-18s %6s %9s %10s %10s  %s\n", "scene", "prims", "fragments", "kernel ms", "oracle ms",
              "agree");
  int agree = 0;
  std::vector<std::string> notes;
  for (const ShowcaseScene& sc : scenes) {
    const Clock::time_point k0 = Clock::now();
    auto prepared = prepare(sc.scene);
    if (auto* err = std::get_if<SceneError>(&prepared)) {
      return error("internal error: showcase scene " + sc.name + ": " + err->what());
    }
    const PreparedScene& ps = std::get<PreparedScene>(prepared);
    const std::vector<Fragment> kernel = rasterize(ps);
    const double kernel_ms = ms_since(k0);

    std::vector<oracle::Fragment> exact;
    std::optional<std::string> oracle_error;
    const Clock::time_point o0 = Clock::now();
    try {
      exact = oracle::render(to_oracle(sc.scene));
    } catch (const std::exception& e) {
      oracle_error = e.what();
    }
    const double oracle_ms = ms_since(o0);

    bool same = !oracle_error && kernel.size() == exact.size();
    for (std::size_t i = 0; same && i < kernel.size(); ++i) {
      same = kernel[i].prim == exact[i].prim && kernel[i].x == exact[i].x && kernel[i].y == exact[i].y &&
             kernel[i].mask == 1u;
    }
    if (oracle_error) notes.push_back(sc.name + ": the oracle failed: " + *oracle_error);
    if (!same && !oracle_error) {
      for (const std::string& d : differences(kernel, exact, 10)) notes.push_back(sc.name + ": " + d);
    }

    // The scene file must read back to exactly this scene (SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32).
    const std::string scene_text = io::write_scene(sc.scene);
    const auto reread = io::read_scene(scene_text);
    if (!std::holds_alternative<Scene>(reread) || !same_scene(std::get<Scene>(reread), sc.scene)) {
      same = false;
      notes.push_back(sc.name + ": the written scene file does not read back to the same scene");
    }
    for (const auto& err : {write_text(dir / (sc.name + ".scene.json"), scene_text),
                            write_text(dir / (sc.name + ".fragments.json"), io::fragments_to_json(kernel)),
                            write_picture(dir / (sc.name + ".png"), ps, kernel)}) {
      if (err) return error(*err);
    }
    if (same) ++agree;
    std::printf("%-18s %6zu %9zu %10.3f %10.3f  %s\n", sc.name.c_str(), sc.scene.primitives.size(),
                kernel.size(), kernel_ms, oracle_ms, same ? "yes" : "NO");
  }
  for (const std::string& n : notes) std::printf("  %s\n", n.c_str());
  const int differ = static_cast<int>(scenes.size()) - agree;
  std::printf("showcase: %zu scenes, %d agree with the oracle, %d differ; pictures in %s\n", scenes.size(),
              agree, differ, dir.string().c_str());
  std::fflush(stdout);
  return differ == 0 ? kExitOk : kExitDifference;
}

}  // namespace rastrules::cli
