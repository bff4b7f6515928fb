// SPDX-License-Identifier: MIT
// What accuracy costs in time: the kernel's fast path against its own direct evaluation and
// against the exact oracle, on the same scenes, reported as ratios measured in one run.
// Points and aliased lines: the kernel's scene path against the point and line oracles.
// rule: RASTER.WALK.BBOX, TRI.COVER.SAMPLE, SCENE.PRIM.POINT, SCENE.PRIM.LINE

#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/scene.hpp"

namespace {

// Returns a random coordinate in pixels from coord (in 1/256 px), moved to the pixel centre
// when on_centre (the ties a quarter of every scene's primitives have).
float grid_coord(std::mt19937& rng, std::uniform_int_distribution<int>& coord, bool on_centre) {
  int raw = coord(rng);
  if (on_centre)
    raw = (raw / 256) * 256 + 128;
  return static_cast<float>(raw) / 256.0f;
}

// Runs count() once per benchmark iteration and reports its last result as the "fragments"
// counter.
template <class Count> void measure_fragments(benchmark::State& st, Count count) {
  std::size_t n = 0;
  for (auto _ : st) {
    n = count();
    benchmark::DoNotOptimize(n);
  }
  st.counters["fragments"] = static_cast<double>(n);
}

// Returns the number of fragments the kernel's scene path draws for scene.
std::size_t kernel_fragments(const rastrules::Scene& scene) {
  return std::get<std::vector<rastrules::Fragment>>(rastrules::render(scene)).size();
}

// A deterministic scene: n triangles with vertices on the 1/256 grid, a quarter of them with
// vertices on pixel centres (ties), inside a size x size target with a margin outside it.
rastrules::Scene make_scene(std::int32_t size, int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-4 * 256, (size + 4) * 256);
  rastrules::Scene s;
  s.width = size;
  s.height = size;
  for (int i = 0; i < n; ++i) {
    rastrules::Primitive p;
    for (auto& v : p.v) {
      for (auto& c : v)
        c = grid_coord(rng, coord, i % 4 == 0);
    }
    s.primitives.push_back(p);
  }
  return s;
}

rastrules::oracle::Scene to_oracle(const rastrules::Scene& s) {
  rastrules::oracle::Scene o;
  o.width = s.width;
  o.height = s.height;
  for (const auto& p : s.primitives)
    o.triangles.push_back({p.v[0], p.v[1], p.v[2]});
  return o;
}

void BM_KernelRender(benchmark::State& st) {
  const auto scene = make_scene(static_cast<std::int32_t>(st.range(0)), 16, 1);
  measure_fragments(st, [&] { return kernel_fragments(scene); });
}

// The same coverage decided per pixel with the layer-2 rule (covers()), no stepping, no bias.
void BM_KernelDirectCovers(benchmark::State& st) {
  const auto scene = make_scene(static_cast<std::int32_t>(st.range(0)), 16, 1);
  const auto prepared = std::get<rastrules::PreparedScene>(rastrules::prepare(scene));
  measure_fragments(st, [&] {
    std::size_t n = 0;
    for (const auto& prim : prepared.primitives) {
      const auto& t = prim.triangles[0].setup;
      const auto r = rastrules::raster::pixel_bounds(t, prepared.width, prepared.height);
      for (std::int32_t y = r.y0; y <= r.y1; ++y)
        for (std::int32_t x = r.x0; x <= r.x1; ++x)
          n += rastrules::covers(t, rastrules::pixel_center(x, y)) ? 1u : 0u;
    }
    return n;
  });
}

void BM_OracleRender(benchmark::State& st) {
  const auto scene = to_oracle(make_scene(static_cast<std::int32_t>(st.range(0)), 16, 1));
  measure_fragments(st, [&] { return rastrules::oracle::render(scene).size(); });
}

// n points or n aliased lines (D3D) with positions on the 1/256 grid inside a size x size
// target, a quarter of the coordinates on pixel centres.
rastrules::Scene make_point_or_line_scene(std::int32_t size, int n, rastrules::PrimitiveType type,
                                          std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, size * 256 - 1);
  rastrules::Scene s;
  s.width = size;
  s.height = size;
  const std::size_t count = type == rastrules::PrimitiveType::kPoint ? 1 : 2;
  for (int i = 0; i < n; ++i) {
    rastrules::Primitive p;
    p.type = type;
    p.v.assign(count, {0.0f, 0.0f});
    for (auto& v : p.v) {
      for (auto& c : v)
        c = grid_coord(rng, coord, i % 4 == 0);
    }
    s.primitives.push_back(p);
  }
  return s;
}

std::array<std::int64_t, 2> raw_of(const rastrules::FloatPoint& v) {
  return {static_cast<std::int64_t>(v[0] * 256.0f), static_cast<std::int64_t>(v[1] * 256.0f)};
}

void BM_KernelPoints(benchmark::State& st) {
  const auto scene = make_point_or_line_scene(static_cast<std::int32_t>(st.range(0)), 64,
                                              rastrules::PrimitiveType::kPoint, 2);
  measure_fragments(st, [&] { return kernel_fragments(scene); });
}

// The point oracle decides each pixel of the 3x3 block around the point (a point's square
// reaches no further), exactly.
void BM_OraclePoints(benchmark::State& st) {
  const auto size = static_cast<std::int32_t>(st.range(0));
  const auto scene = make_point_or_line_scene(size, 64, rastrules::PrimitiveType::kPoint, 2);
  measure_fragments(st, [&] {
    std::size_t n = 0;
    for (const auto& p : scene.primitives) {
      const auto c = raw_of(p.v[0]);
      const std::int64_t px = c[0] >> 8, py = c[1] >> 8;
      for (std::int64_t y = py - 1; y <= py + 1; ++y) {
        for (std::int64_t x = px - 1; x <= px + 1; ++x) {
          if (x < 0 || y < 0 || x >= size || y >= size)
            continue;
          n += rastrules::oracle::point_covers(c, {x * 256 + 128, y * 256 + 128}, "top-left") ? 1u
                                                                                              : 0u;
        }
      }
    }
    return n;
  });
}

void BM_KernelLines(benchmark::State& st) {
  const auto scene = make_point_or_line_scene(static_cast<std::int32_t>(st.range(0)), 16,
                                              rastrules::PrimitiveType::kLine, 3);
  measure_fragments(st, [&] { return kernel_fragments(scene); });
}

void BM_OracleLines(benchmark::State& st) {
  const auto size = static_cast<std::int32_t>(st.range(0));
  const auto scene = make_point_or_line_scene(size, 16, rastrules::PrimitiveType::kLine, 3);
  measure_fragments(st, [&] {
    std::size_t n = 0;
    for (const auto& p : scene.primitives) {
      n += rastrules::oracle::aliased_line_pixels(raw_of(p.v[0]), raw_of(p.v[1]), "d3d", size, size)
               .size();
    }
    return n;
  });
}

BENCHMARK(BM_KernelPoints)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OraclePoints)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KernelLines)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OracleLines)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_KernelRender)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KernelDirectCovers)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OracleRender)->Arg(16)->Arg(64)->Unit(benchmark::kMillisecond);

// Prints the usual table, then the ratios of each method to the kernel's fast path, from the
// times measured in this run (never compared with a fixed number).
class RatioReporter : public benchmark::ConsoleReporter {
public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.run_type == Run::RT_Iteration && r.iterations > 0) {
        times_[r.benchmark_name()] = r.GetAdjustedRealTime() *
                                     benchmark::GetTimeUnitMultiplier(benchmark::kNanosecond) /
                                     benchmark::GetTimeUnitMultiplier(r.time_unit);
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    struct Group {
      const char* base;
      std::vector<const char*> others;
    };
    const std::vector<Group> groups = {
        {"BM_KernelRender/", {"BM_KernelDirectCovers/", "BM_OracleRender/"}},
        {"BM_KernelPoints/", {"BM_OraclePoints/"}},
        {"BM_KernelLines/", {"BM_OracleLines/"}}};
    for (const Group& g : groups) {
      std::printf("\nAccuracy cost (time relative to %s, same scene, this run):\n", g.base);
      for (const char* size : {"16", "64"}) {
        const std::string base = std::string(g.base) + size;
        if (!times_.count(base) || times_[base] <= 0)
          continue;
        for (const char* name : g.others) {
          const std::string key = std::string(name) + size;
          if (times_.count(key)) {
            std::printf("  %-26s %10.1fx\n", key.c_str(), times_[key] / times_[base]);
          }
        }
      }
    }
  }

private:
  std::map<std::string, double> times_;
};

} // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 2;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
