// SPDX-License-Identifier: MIT
// What each pipeline stage costs, and what each optimization saves (PIPE.EFFECTS.ON_DEMAND,
// PIPE.OPT.*). The same scene of medium triangles is run with one more stage at a time; the
// "ratio" benchmarks time two variants alternately in the same iterations and report their
// quotient, so that the comparison is made in one run on one machine.
// rule: PIPE.EFFECTS.ON_DEMAND, PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace rp = rastrules::pipe;

constexpr std::int32_t kSize = 512;

// n triangles of about 20 x 20 px at random places and depths, given in clip space with w in
// [1, 4] (x, y, z scaled by w) or, when window is set, as their window-space images.
rastrules::Scene make_scene(int n, bool window, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-0.95f, 0.95f), off(-0.08f, 0.08f), depth(0.05f, 0.95f),
      wdist(1.0f, 4.0f);
  rastrules::Scene s;
  s.width = kSize;
  s.height = kSize;
  for (int i = 0; i < n; ++i) {
    const float cx = pos(rng), cy = pos(rng), z = depth(rng);
    rastrules::Primitive p;
    p.type = rastrules::PrimitiveType::kTriangle;
    for (int k = 0; k < 3; ++k) {
      const float x = cx + off(rng), y = cy + off(rng), zz = z + off(rng) * 0.5f;
      if (window) {
        p.v[static_cast<std::size_t>(k)] = {(x + 1.0f) * kSize * 0.5f, (1.0f - y) * kSize * 0.5f};
        p.z.push_back(zz);
      } else {
        const float w = wdist(rng);
        p.pos.push_back({x * w, y * w, zz * w, w});
      }
    }
    s.primitives.push_back(p);
  }
  return s;
}

enum Stage : int {
  kKernelOnly,   // rastrules::render of the window-space scene: no pipeline at all
  kCoverageOnly, // the pipeline on the same scene: coverage only
  kClipSpace,    // + transform-free clip-space input, clipping, divide, viewport
  kDepth,        // + depth test and write (d24, less)
  kAttributes,   // + 4 perspective attributes
  kMsaa4,        // + 4 samples (depth per sample)
  kCentroid,     // + attributes at the centroid
  kDerivatives,  // + quads, helper lanes and fine derivatives
};
const char* const kStageNames[] = {"kernel_only", "coverage_only", "+clip_space", "+depth",
                                   "+attributes", "+msaa4",        "+centroid",   "+derivatives"};

rastrules::Scene stage_scene(int stage) {
  rastrules::Scene s = make_scene(2000, stage < kClipSpace, 7);
  if (stage >= kDepth)
    s.depth = rp::DepthState{};
  if (stage >= kAttributes) {
    for (const char* n : {"r", "g", "b", "u"})
      s.attributes.push_back(
          rp::AttributeDecl{n, rp::Interpolation::kPerspective,
                            stage >= kCentroid ? rp::Location::kCentroid : rp::Location::kCenter});
    for (auto& p : s.primitives)
      p.attr = {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}};
  }
  if (stage >= kMsaa4)
    set_sample_pattern(s, rastrules::standard_pattern(4));
  if (stage >= kDerivatives)
    s.msaa.derivatives = rastrules::DerivativeMode::kFine;
  return s;
}

// The scene's coverage alone (its primitives without z and w): what rastrules::render draws
// without the pipeline. s has no pipeline state of its own (the kernel-only and coverage stages).
rastrules::Scene kernel_scene(const rastrules::Scene& s) {
  rastrules::Scene k = rastrules::target_of(s);
  for (const auto& p : s.primitives)
    k.primitives.push_back(rastrules::coverage_of(p));
  return k;
}

void BM_PipelineStage(benchmark::State& st) {
  const int stage = static_cast<int>(st.range(0));
  const rastrules::Scene s = stage_scene(stage);
  const rastrules::Scene k = kernel_scene(s);
  std::size_t frags = 0;
  for (auto _ : st) {
    if (stage == kKernelOnly) {
      auto r = rastrules::render(k);
      frags = std::get<std::vector<rastrules::Fragment>>(r).size();
      benchmark::DoNotOptimize(r);
    } else {
      auto r = rp::run_pipeline(s);
      frags = std::get<rp::PipeResult>(r).fragments.size();
      benchmark::DoNotOptimize(r);
    }
  }
  st.SetLabel(kStageNames[stage]);
  st.counters["fragments"] = static_cast<double>(frags);
  st.counters["triangles/s"] = benchmark::Counter(static_cast<double>(s.primitives.size()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PipelineStage)->DenseRange(kKernelOnly, kDerivatives)->Unit(benchmark::kMillisecond);

// Times a and b alternately, each iteration once, and reports time(b) / time(a).
template <class A, class B> void ratio(benchmark::State& st, A&& a, B&& b) {
  using clock = std::chrono::steady_clock;
  double ta = 0.0, tb = 0.0;
  for (auto _ : st) {
    const auto t0 = clock::now();
    a();
    const auto t1 = clock::now();
    b();
    const auto t2 = clock::now();
    ta += std::chrono::duration<double>(t1 - t0).count();
    tb += std::chrono::duration<double>(t2 - t1).count();
  }
  st.counters["ratio"] = ta > 0.0 ? tb / ta : 0.0;
}

// A coverage-only scene through the pipeline against the kernel alone: the cost of having the
// other stages in the build when the scene does not call for them.
void BM_CoverageOnlyOverKernel(benchmark::State& st) {
  const rastrules::Scene s = stage_scene(kCoverageOnly);
  const rastrules::Scene k = kernel_scene(s);
  ratio(
      st, [&] { benchmark::DoNotOptimize(rastrules::render(k)); },
      [&] { benchmark::DoNotOptimize(rp::run_pipeline(s)); });
  st.SetLabel("time(pipeline, coverage only) / time(kernel render)");
}
BENCHMARK(BM_CoverageOnlyOverKernel)->Unit(benchmark::kMillisecond);

// Heavy overdraw, front to back (Hi-Z and early-Z reject most fragments), depth and attributes:
// all optimizations against the plain path, and each one alone.
void BM_OptimizationsOverPlain(benchmark::State& st) {
  rastrules::Scene s = make_scene(0, true, 1);
  s.width = s.height = 128;
  // 32 full-target quads (two triangles each) from near to far, 4 attributes.
  for (int i = 0; i < 32; ++i) {
    const float z = 0.1f + 0.01f * static_cast<float>(i);
    const float n = 128.0f;
    for (const auto& t : {std::array<rastrules::FloatPoint, 3>{{{0, 0}, {n, 0}, {0, n}}},
                          std::array<rastrules::FloatPoint, 3>{{{n, 0}, {n, n}, {0, n}}}}) {
      rastrules::Primitive p = rastrules::make_triangle(t);
      p.z = {z, z, z};
      p.attr = {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}};
      s.primitives.push_back(p);
    }
  }
  s.depth = rp::DepthState{};
  for (const char* n : {"r", "g", "b", "u"})
    s.attributes.push_back(
        rp::AttributeDecl{n, rp::Interpolation::kPerspective, rp::Location::kCenter});
  rp::PipeOptions fast;
  const int which = static_cast<int>(st.range(0));
  if (which > 0) {
    fast = rp::PipeOptions::plain();
    fast.render.traversal = rastrules::Traversal::kFast;
    if (which == 1)
      fast.binning = true;
    if (which == 2)
      fast.hiz = true;
    if (which == 3)
      fast.early_z = true;
    if (which == 4)
      fast.fast_clear = true;
  }
  const rp::PipeOptions plain = [] {
    rp::PipeOptions o = rp::PipeOptions::plain();
    o.render.traversal = rastrules::Traversal::kFast; // the same coverage traversal on both sides
    return o;
  }();
  ratio(
      st, [&] { benchmark::DoNotOptimize(rp::run_pipeline(s, plain)); },
      [&] { benchmark::DoNotOptimize(rp::run_pipeline(s, fast)); });
  static const char* const names[] = {"all", "binning", "hiz", "early_z", "fast_clear"};
  st.SetLabel(std::string("time(") + names[which] + ") / time(plain)");
}
BENCHMARK(BM_OptimizationsOverPlain)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

} // namespace
