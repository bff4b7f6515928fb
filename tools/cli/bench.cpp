// SPDX-License-Identifier: MIT
// rastrules bench --ladder: the precision ladder (spec/bench.md). Runs every rung on the same
// scenes (bench/ladder/), times lavapipe on the small mesh through tools/driver, writes
// DIR/ladder.md, DIR/ladder.json and DIR/ladder.png and prints the table.
// Implements: BENCH.REPORT, BENCH.LAVAPIPE (the call), BENCH.TARGETS (printed)

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>
#include <thread>

#include "cli.hpp"
#include "parser.hpp"
#include "rastrules/bench/ladder.hpp"
#include "rastrules/driver/timing.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/parallel.hpp"

namespace rastrules::cli {
namespace {

// The lavapipe figure of BENCH.LAVAPIPE for one ladder scene.
// rule: BENCH.LAVAPIPE
bench::LavapipeFigure time_lavapipe(const bench::LadderScene& s, int repeats) {
  bench::LavapipeFigure f;
  Scene scene;
  scene.width = s.width;
  scene.height = s.height;
  for (const auto& t : s.triangles)
    scene.primitives.push_back(make_triangle(t));
  const driver::CoverageTiming t = driver::time_lavapipe_coverage(scene, repeats);
  f.available = t.available;
  f.why_not = t.why_not;
  f.device = t.device;
  f.includes = t.includes;
  f.repeats = t.repeats;
  f.seconds = t.seconds_median;
  f.samples_passed = t.samples_passed;
  return f;
}

} // namespace

// rule: BENCH.REPORT
int run_bench(const Args& args) {
  CommandLine cl("bench",
                 "The precision ladder (spec/bench.md): the same scenes rasterized by float, "
                 "double, scanline, 4-bit/32-bit, the reference (plain and fast), 16-bit/128-bit "
                 "and the exact oracle, with speed (ratios to the reference), errors, "
                 "watertightness, translation invariance and lavapipe's time; prints the table "
                 "(-q: no progress on standard error).");
  bool ladder = false;
  bench::LadderConfig config;
  config.threads = std::max(1u, std::thread::hardware_concurrency());
  std::optional<std::string> out_dir, threads, seed;
  cl.flag("--ladder", ladder, "run the precision ladder (the only benchmark; required)");
  cl.value("--out", out_dir, "DIR", "also write DIR/ladder.md, ladder.json and ladder.png",
           "--out: must name a directory, got nothing");
  cl.flag("--quick", config.quick, "shorter timings");
  cl.value("--seed", seed, "N", "the scenes' seed",
           "--seed: must be an integer in [0, 1000000000], got nothing");
  cl.value("--threads", threads, "N",
           "time the fast path on N threads too (default: one per processor)",
           "--threads needs an integer in [1, " + std::to_string(kMaxThreads) + "], got nothing");
  if (const auto stop = cl.parse(args, "bench: "))
    return *stop;
  if (threads) {
    // rule: BENCH.METRIC.THROUGHPUT
    const auto n = parse_int(*threads, 1, kMaxThreads);
    if (!n)
      return error("--threads needs an integer in [1, " + std::to_string(kMaxThreads) + "], got " +
                   shown_value(threads));
    config.threads = static_cast<unsigned>(*n);
  }
  if (out_dir && out_dir->empty())
    return error("--out: must name a directory");
  if (seed) {
    const auto n = parse_int(*seed, 0, 1000000000);
    if (!n)
      return error("--seed: must be an integer in [0, 1000000000], got " + shown_value(seed));
    config.seed = static_cast<std::uint64_t>(*n);
  }
  if (!ladder)
    return usage_error("bench: missing --ladder (the only benchmark: bench --ladder [--out DIR] "
                       "[--quick] [--seed N] [--threads N])");
  config.min_seconds = config.quick ? 0.02 : 0.2;

  std::filesystem::path dir;
  if (out_dir) {
    dir = *out_dir;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
      return error("--out: cannot create directory \"" + *out_dir + "\"" +
                   (ec ? ": " + ec.message() : std::string()));
  }

  const int lavapipe_repeats = config.quick ? 5 : 21;
  const bench::LadderReport report = bench::run_ladder(
      config, [&](const bench::LadderScene& s) { return time_lavapipe(s, lavapipe_repeats); },
      [](const std::string& line) {
        if (verbosity() != Verbosity::kQuiet)
          std::fprintf(stderr, "bench: %s\n", line.c_str());
      });
  const std::string md = bench::to_markdown(report);
  std::fputs(md.c_str(), stdout);
  std::fflush(stdout);
  if (!out_dir)
    return kExitOk;

  if (auto err = write_text(dir / "ladder.md", md))
    return error(*err);
  if (auto err = write_text(dir / "ladder.json", bench::to_json(report)))
    return error(*err);
  const bench::Plot plot = bench::make_plot(report);
  io::Image image(plot.width, plot.height, io::Rgb{255, 255, 255});
  for (int y = 0; y < plot.height; ++y)
    for (int x = 0; x < plot.width; ++x) {
      const auto c = plot.at(x, y);
      image.set(x, y, io::Rgb{c[0], c[1], c[2]});
    }
  OutputFile png;
  const std::string png_path = (dir / "ladder.png").string();
  if (auto err = png.open(png_path))
    return error(*err);
  if (auto err = io::write_png(png.get(), image))
    return error(png_path + ": " + *err);
  if (auto err = png.commit())
    return error(*err);
  if (verbosity() != Verbosity::kQuiet)
    std::fprintf(stderr, "bench: wrote %s/ladder.md, ladder.json, ladder.png in %.1f s\n",
                 dir.string().c_str(), report.seconds_total);
  return kExitOk;
}

} // namespace rastrules::cli
