// SPDX-License-Identifier: MIT
// rastrules_render_split: where `rastrules render` spends its time on many small triangles
// (BENCH.RENDER.SPLIT): the batch counter alone (the kernel's speed), then each stage of the
// command line's path in the same process (read the file, parse, prepare, cover, write JSON or
// binary fragments), then the command line itself end to end with --count, --fragments OUT.bin
// and --fragments OUT.json. Every figure is a median of alternating rounds in one run; ratios
// are against the batch counter of the same run. Speed is reported, never asserted.
// Implements: BENCH.RENDER.SPLIT

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include <sys/wait.h>

#include "fast_list.hpp"
#include "rastrules/io/fragment_binary.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/raster/fast_batch.hpp"
#include "rastrules/scene.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// n small triangles (2 or 3 px legs, integer vertices: about 60 bytes a triangle, so that 10^6
// fit the 64 MiB scene limit) spread over a side x side target, seeded.
std::string small_triangles_scene(std::size_t n, int side, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pos(0, side - 4), leg(2, 3), skew(0, 1);
  std::string s = "{\"target\":{\"width\":" + std::to_string(side) +
                  ",\"height\":" + std::to_string(side) + "},\"primitives\":[\n";
  char buf[128];
  for (std::size_t i = 0; i < n; ++i) {
    const int x = pos(rng), y = pos(rng);
    // Clockwise in window space (y down), as every cull mode keeps.
    std::snprintf(buf, sizeof buf, "%s{\"type\":\"triangle\",\"v\":[[%d,%d],[%d,%d],[%d,%d]]}",
                  i == 0 ? "" : ",\n", x, y, x + leg(rng), y + skew(rng), x + skew(rng),
                  y + leg(rng));
    s += buf;
  }
  return s + "\n]}\n";
}

int run_process(const std::vector<std::string>& args) {
  std::string cmd;
  for (const std::string& a : args)
    cmd += "'" + a + "' ";
  const int status = std::system((cmd + ">/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000000;
  int rounds = 5;
  std::string cli, before;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--triangles" && i + 1 < argc) {
      n = std::strtoull(argv[++i], nullptr, 10);
    } else if (a == "--rounds" && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--rastrules" && i + 1 < argc) {
      cli = argv[++i];
    } else if (a == "--before" && i + 1 < argc) {
      before = argv[++i];
    } else {
      std::fprintf(stderr, "usage: rastrules_render_split [--triangles N] [--rounds R] "
                           "[--rastrules PATH-OF-THE-CLI] [--before PATH-OF-AN-EARLIER-CLI]\n");
      return 2;
    }
  }
  if (n < 1 || n > (std::size_t{1} << 20)) {
    std::fprintf(stderr, "rastrules_render_split: --triangles needs N in [1, 2^20]\n");
    return 2;
  }
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("rastrules-split-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path scene_path = dir / "scene.json";
  {
    const std::string text = small_triangles_scene(n, 1000, 12345);
    std::FILE* f = std::fopen(scene_path.c_str(), "wb");
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
  }

  // The scene once, for the stages that need their input ready.
  auto read0 = rastrules::io::read_scene_file(scene_path.string());
  if (const auto* err = std::get_if<rastrules::SceneError>(&read0)) {
    std::fprintf(stderr, "rastrules_render_split: %s\n", err->what().c_str());
    return 1;
  }
  const std::string text0 = std::get<std::string>(std::move(read0));
  auto parsed0 = rastrules::io::read_scene(text0);
  if (const auto* err = std::get_if<rastrules::SceneError>(&parsed0)) {
    std::fprintf(stderr, "rastrules_render_split: %s\n", err->what().c_str());
    return 1;
  }
  const rastrules::Scene scene0 = std::get<rastrules::Scene>(std::move(parsed0));
  auto checked0 = rastrules::pipe::check_scene(scene0);
  if (const auto* err = std::get_if<rastrules::SceneError>(&checked0)) {
    std::fprintf(stderr, "rastrules_render_split: %s\n", err->what().c_str());
    return 1;
  }
  const rastrules::PreparedScene prepared =
      *std::get<std::optional<rastrules::PreparedScene>>(std::move(checked0));
  std::vector<float> xy;
  for (const auto& p : scene0.primitives)
    for (const auto& v : p.v)
      xy.insert(xy.end(), {v[0], v[1]});

  std::uint64_t fragments = 0;
  std::map<std::string, std::vector<double>> t;
  const rastrules::RenderOptions options;
  std::FILE* null = std::fopen("/dev/null", "wb");
  // The JSON list of render --threads N --fragments, made from the runs in the process.
  const auto json_from_runs = [&](unsigned threads) {
    rastrules::io::FragmentWriter w(null);
    (void)rastrules::cli::write_fast_list(xy, prepared.width, prepared.height, prepared.state,
                                          rastrules::best_isa(), threads, std::uint64_t{1} << 40,
                                          &w, nullptr);
    (void)w.finish();
  };
  const std::vector<std::pair<std::string, std::function<void()>>> stages = {
      {"batch counter (kernel alone)",
       [&] {
         std::vector<std::uint64_t> per(n);
         const auto r = rastrules::raster::fast_count_batch(
             xy, prepared.width, prepared.height, prepared.state, rastrules::best_isa(), per);
         fragments = r.covered;
       }},
      {"batch counter with per-pixel counts (what --count computes)",
       [&] {
         std::vector<std::uint64_t> per(n);
         rastrules::raster::PixelCounts hits(prepared.width, prepared.height);
         (void)rastrules::raster::fast_count_batch(
             xy, prepared.width, prepared.height, prepared.state, rastrules::best_isa(), per, hits);
       }},
      {"batch runs into the binary writer (what --fragments OUT.bin does)",
       [&] {
         rastrules::io::FragmentBinaryWriter w(null,
                                               rastrules::io::fragment_binary_header(prepared));
         // As write_fast_list hands them over: a chunk's runs at once where the batch unit
         // has them so (add_runs), the others one by one.
         const rastrules::raster::RunSink sink{
             &w,
             [](void* c, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t k) {
               (void)static_cast<rastrules::io::FragmentBinaryWriter*>(c)->add_run(
                   tri, y, x, static_cast<std::uint32_t>(k));
             },
             [](void* c, const rastrules::raster::BatchRun* r, std::size_t k) {
               (void)static_cast<rastrules::io::FragmentBinaryWriter*>(c)->add_runs(r, k, 0);
             }};
         (void)rastrules::raster::fast_runs_batch(xy, prepared.width, prepared.height,
                                                  prepared.state, rastrules::best_isa(), sink);
         (void)w.finish();
       }},
      {"batch runs as JSON text, 1 thread (write_fast_list)", [&] { json_from_runs(1); }},
      {"batch runs as JSON text, 2 threads (write_fast_list, units)", [&] { json_from_runs(2); }},
      {"read the file", [&] { (void)rastrules::io::read_scene_file(scene_path.string()); }},
      {"parse coordinates alone (io::read_triangles_fast, render --count)",
       [&] { (void)rastrules::io::read_triangles_fast(text0); }},
      {"parse (io::read_scene)", [&] { (void)rastrules::io::read_scene(text0); }},
      {"parse, general reader alone (before SCENE.INPUT.FAST_READER)",
       [&] { (void)rastrules::io::read_scene_general(text0); }},
      {"prepare (snap, check)", [&] { (void)rastrules::pipe::check_scene(scene0); }},
      {"cover (for_each_fragment, counted)",
       [&] {
         std::uint64_t c = 0;
         for (std::size_t p = 0; p < prepared.primitives.size(); ++p)
           rastrules::for_each_fragment(prepared, p, options,
                                        [&](const rastrules::Fragment&) { ++c; });
       }},
      {"cover + write JSON",
       [&] {
         rastrules::io::FragmentWriter w(null);
         for (std::size_t p = 0; p < prepared.primitives.size(); ++p)
           rastrules::for_each_fragment(prepared, p, options,
                                        [&](const rastrules::Fragment& f) { (void)w.add(f); });
         (void)w.finish();
       }},
      {"cover + write binary",
       [&] {
         rastrules::io::FragmentBinaryWriter w(null,
                                               rastrules::io::fragment_binary_header(prepared));
         for (std::size_t p = 0; p < prepared.primitives.size(); ++p)
           rastrules::for_each_fragment(prepared, p, options,
                                        [&](const rastrules::Fragment& f) { (void)w.add(f); });
         (void)w.finish();
       }},
  };
  std::vector<std::pair<std::string, std::vector<std::string>>> processes;
  if (!cli.empty()) {
    const std::string s = scene_path.string();
    processes = {
        {"rastrules render --count", {cli, "render", s, "--count", (dir / "c.json").string()}},
        {"rastrules render --count --threads 2",
         {cli, "render", s, "--count", (dir / "c2.json").string(), "--threads", "2"}},
        {"rastrules render --fragments OUT.bin",
         {cli, "render", s, "--fragments", (dir / "f.bin").string()}},
        {"rastrules render --fragments OUT.bin --fragments-format binary-v1",
         {cli, "render", s, "--fragments", (dir / "f1.bin").string(), "--fragments-format",
          "binary-v1"}},
        {"rastrules render --fragments OUT.bin --threads 2",
         {cli, "render", s, "--fragments", (dir / "f2.bin").string(), "--threads", "2"}},
        {"rastrules render --fragments OUT.json",
         {cli, "render", s, "--fragments", (dir / "f.json").string()}},
    };
  }
  if (!before.empty()) {
    // Each earlier run beside the same run of this build, first on even rounds and second on
    // odd ones (a run's time depends on what ran just before it: the page cache's writeback of
    // the previous outputs, above all).
    const std::string s = scene_path.string();
    const std::map<std::string, std::pair<std::string, std::vector<std::string>>> earlier = {
        {"rastrules render --count",
         {"earlier rastrules render --count",
          {before, "render", s, "--count", (dir / "ec.json").string()}}},
        {"rastrules render --fragments OUT.bin",
         {"earlier rastrules render --fragments OUT.bin",
          {before, "render", s, "--fragments", (dir / "e.bin").string()}}},
        {"rastrules render --fragments OUT.json",
         {"earlier rastrules render --fragments OUT.json",
          {before, "render", s, "--fragments", (dir / "e.json").string()}}},
    };
    std::vector<std::pair<std::string, std::vector<std::string>>> paired;
    for (auto& p : processes) {
      paired.push_back(p);
      if (const auto e = earlier.find(p.first); e != earlier.end())
        paired.push_back(e->second);
    }
    if (cli.empty()) // no current command line: the earlier one's JSON list alone, as before
      paired.push_back(earlier.at("rastrules render --fragments OUT.json"));
    processes = std::move(paired);
  }
  for (int r = 0; r < rounds; ++r) {
    for (const auto& [name, run] : stages) {
      const auto t0 = Clock::now();
      run();
      t[name].push_back(seconds_since(t0));
    }
    for (std::size_t i = 0; i < processes.size(); ++i) {
      // On odd rounds an earlier run goes before the run it follows on even ones.
      std::size_t k = i;
      if (r % 2 == 1 && i + 1 < processes.size() && processes[i + 1].first.rfind("earlier", 0) == 0)
        k = i + 1;
      else if (r % 2 == 1 && i > 0 && processes[i].first.rfind("earlier", 0) == 0 &&
               processes[i - 1].first.rfind("earlier", 0) != 0)
        k = i - 1;
      const auto& [name, args] = processes[k];
      const auto t0 = Clock::now();
      if (run_process(args) != 0) {
        std::fprintf(stderr, "rastrules_render_split: %s failed\n", name.c_str());
        return 1;
      }
      t[name].push_back(seconds_since(t0));
    }
  }
  std::fclose(null);
  fs::remove_all(dir);

  const double batch = median(t["batch counter (kernel alone)"]);
  std::printf("## rastrules render on %zu small triangles (1000 x 1000, %llu fragments), %s, "
              "medians of %d alternating rounds\n\n",
              n, static_cast<unsigned long long>(fragments),
              std::string(rastrules::to_string(rastrules::best_isa())).c_str(), rounds);
  std::printf("| stage | time | / batch counter |\n| --- | --- | --- |\n");
  const auto row = [&](const std::string& name) {
    const double m = median(t[name]);
    std::printf("| %s | %.1f ms | %.1fx |\n", name.c_str(), m * 1e3, batch > 0 ? m / batch : 0.0);
  };
  for (const auto& [name, run] : stages)
    row(name);
  for (const auto& [name, args] : processes)
    row(name);
  const double one = median(t["batch runs as JSON text, 1 thread (write_fast_list)"]);
  const double two = median(t["batch runs as JSON text, 2 threads (write_fast_list, units)"]);
  std::printf("\nJSON from the runs, in the process: 2 threads %.2fx faster than 1\n",
              two > 0 ? one / two : 0.0);
  return 0;
}
