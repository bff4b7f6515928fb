// SPDX-License-Identifier: MIT
// rastrules showcase: render the built-in scenes, write their files and pictures, and
// compare every fragment list with the exact oracles (oracle/): triangles with the
// triangle oracle, points with the triangle oracle on their exact squares (or the point
// oracle), aliased lines with the line oracle, antialiased lines with the AA-line oracle
// (pixels exactly, coverage within LINE.AA.PRECISION); multisampled scenes with the exact
// multisampling oracle (oracle/msaa.hpp): every fragment field (mask, sample, helper,
// centroid, derivatives) and the resolved target.

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

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "parser.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "showcase_html.hpp"
#include "showcase_scenes.hpp"

namespace rastrules::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::optional<std::string> write_picture(const std::filesystem::path& path,
                                         const PreparedScene& scene,
                                         const std::vector<Fragment>& fragments) {
  io::CoverageMap coverage(scene.width, scene.height);
  const int scale = io::default_picture_scale(scene.width, scene.height);
  if (io::samples_visible(scene, scale))
    coverage.record_samples(scene.msaa.count());
  for (const Fragment& f : fragments)
    coverage.add_fragment(f);
  const io::Image image = io::draw_picture(scene, coverage, scale);
  OutputFile f;
  if (auto err = f.open(path.string()))
    return err;
  if (auto err = io::write_png(f.get(), image))
    return path.string() + ": " + *err;
  return f.commit();
}

// Writes the resolved target of a multisampled scene (MSAA.RESOLVE.AVERAGE).
std::optional<std::string> write_resolve(const std::filesystem::path& path,
                                         const PreparedScene& scene,
                                         const std::vector<Fragment>& fragments) {
  const auto resolved = resolve(scene, fragments);
  if (const auto* err = std::get_if<SceneError>(&resolved))
    return path.string() + ": " + err->what();
  const ResolvedImage& r = std::get<ResolvedImage>(resolved);
  std::vector<std::uint8_t> rgba;
  for (const Rgba8& p : r.pixels)
    rgba.insert(rgba.end(), p.begin(), p.end());
  OutputFile f;
  if (auto err = f.open(path.string()))
    return err;
  if (auto err = io::write_png_rgba(f.get(), r.width, r.height, rgba))
    return path.string() + ": " + *err;
  return f.commit();
}

} // namespace

int run_showcase(const Args& args) {
  CommandLine cl(
      "showcase",
      "Render the built-in showcase scenes into DIR (scene, fragments and picture of "
      "each, and the resolved target of multisampled ones), compare every one with the "
      "exact oracle and print a summary (-q: the scenes that differ and the last line).");
  std::optional<std::string> out_dir;
  bool as_json = false;
  cl.value("--out", out_dir, "DIR", "the folder written (required)", "--out needs a directory");
  cl.flag("--json", as_json, "the summary as one JSON document instead of the table");
  if (const auto stop = cl.parse(args, "showcase: "))
    return *stop;
  if (!out_dir || out_dir->empty())
    return usage_error("showcase: missing --out DIR");
  const std::filesystem::path dir(*out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    return error(*out_dir + ": cannot create the directory" +
                 (ec ? ": " + ec.message() : std::string()));
  }

  const std::vector<ShowcaseScene> scenes = showcase_scenes();
  // rule: SCENE.INPUT.ERRORS
  // -q: the scenes that differ and the summary line; --json: one document at the end.
  const bool quiet = verbosity() == Verbosity::kQuiet;
  const bool table = !as_json && !quiet;
  if (table) {
    std::printf("%-22s %6s %9s %10s %10s  %s\n", "scene", "prims", "fragments", "kernel ms",
                "oracle ms", "agree");
  }
  nlohmann::ordered_json json_scenes = nlohmann::ordered_json::array();
  int agree = 0;
  std::vector<std::string> notes;
  std::vector<std::string> checked_by_lines;
  std::vector<ShowcaseEntry> entries;
  for (const ShowcaseScene& sc : scenes) {
    const Clock::time_point k0 = Clock::now();
    auto prepared = prepare(sc.scene);
    if (auto* err = std::get_if<SceneError>(&prepared)) {
      return error("internal error: showcase scene " + sc.name + ": " + err->what());
    }
    const PreparedScene& ps = std::get<PreparedScene>(prepared);
    const std::vector<Fragment> kernel = rasterize(ps);
    const double kernel_ms = ms_since(k0);

    check::Mismatches check;
    const Clock::time_point o0 = Clock::now();
    try {
      check = check::check_against_oracle(sc.scene, ps, kernel, check::CheckOptions{10});
    } catch (const std::exception& e) {
      check.count = 1;
      check.mismatches = {std::string("the oracle failed: ") + e.what()};
    }
    const double oracle_ms = ms_since(o0);
    bool same = check.agree();
    for (const std::string& d : check.mismatches)
      notes.push_back(sc.name + ": " + d);
    std::string checked_by;
    for (const std::string& o : check.oracles)
      checked_by += (checked_by.empty() ? "" : ", ") + o;
    checked_by_lines.push_back(sc.name + ": " + (checked_by.empty() ? "no primitive" : checked_by));

    // The scene file must read back to exactly this scene (SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32).
    const std::string scene_text = io::write_scene(sc.scene);
    const auto reread = io::read_scene(scene_text);
    if (!std::holds_alternative<Scene>(reread) ||
        !io::same_scene(std::get<Scene>(reread), sc.scene)) {
      same = false;
      notes.push_back(sc.name + ": the written scene file does not read back to the same scene");
    }
    for (const auto& err :
         {write_text(dir / (sc.name + ".scene.json"), scene_text),
          write_text(dir / (sc.name + ".fragments.json"), io::fragments_to_json(kernel)),
          write_picture(dir / (sc.name + ".png"), ps, kernel)}) {
      if (err)
        return error(*err);
    }
    if (check::multisampled(sc.scene)) {
      if (auto err = write_resolve(dir / (sc.name + ".resolve.png"), ps, kernel))
        return error(*err);
    }
    if (same)
      ++agree;
    const int scale = io::default_picture_scale(ps.width, ps.height);
    entries.push_back({sc.name, sc.description, ps.width, ps.height, sc.scene.primitives.size(),
                       kernel.size(), scale, io::samples_visible(ps, scale),
                       check::multisampled(sc.scene), same,
                       checked_by.empty() ? "no primitive" : checked_by});
    if (table || (quiet && !as_json && !same)) {
      std::printf("%-22s %6zu %9zu %10.3f %10.3f  %s\n", sc.name.c_str(),
                  sc.scene.primitives.size(), kernel.size(), kernel_ms, oracle_ms,
                  same ? "yes" : "NO");
    }
    json_scenes.push_back({{"name", sc.name},
                           {"primitives", sc.scene.primitives.size()},
                           {"fragments", kernel.size()},
                           {"kernel_ms", kernel_ms},
                           {"oracle_ms", oracle_ms},
                           {"agree", same},
                           {"oracles", check.oracles}});
  }
  // rule: FUZZ.REPORT.HTML
  if (auto err = write_showcase_index(dir, entries))
    return error(*err);
  const int differ = static_cast<int>(scenes.size()) - agree;
  if (as_json) {
    nlohmann::ordered_json j;
    j["scenes"] = json_scenes;
    j["notes"] = notes;
    j["agree"] = agree;
    j["differ"] = differ;
    j["out"] = dir.string();
    std::fputs((j.dump(2) + "\n").c_str(), stdout);
    std::fflush(stdout);
    return differ == 0 ? kExitOk : kExitDifference;
  }
  for (const std::string& n : notes)
    std::printf("  %s\n", n.c_str());
  if (!quiet) {
    std::printf("oracles used:\n");
    for (const std::string& n : checked_by_lines)
      std::printf("  %s\n", n.c_str());
  }
  std::printf("showcase: %zu scenes, %d agree with the oracle, %d differ; pictures in %s\n",
              scenes.size(), agree, differ, dir.string().c_str());
  std::fflush(stdout);
  return differ == 0 ? kExitOk : kExitDifference;
}

} // namespace rastrules::cli
