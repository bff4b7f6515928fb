// SPDX-License-Identifier: MIT
// Running the ladder: every rung on the same scenes in the same run, timed until a minimum
// time, checked against the exact answer; the translation sweep; the speed targets.
// Implements: BENCH.METRIC.THROUGHPUT, BENCH.METRIC.ERROR, BENCH.METRIC.WATERTIGHT,
//             BENCH.METRIC.TRANSLATION, BENCH.TARGETS

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include <cstdlib>
#include <unistd.h>

#include "limit.hpp"
#include "rastrules/bench/ladder.hpp"
#include "rastrules/isa.hpp"

namespace rastrules::bench {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string m = line.substr(colon + 1);
        while (!m.empty() && m.front() == ' ')
          m.erase(m.begin());
        return m;
      }
    }
  }
  return "unknown";
}

// Times `body` until at least min_seconds have passed (at least one repeat, at most 10000);
// returns the median time of one repeat and the number of repeats.
// rule: BENCH.METRIC.THROUGHPUT
template <class Body> std::pair<double, int> time_median(double min_seconds, Body&& body) {
  std::vector<double> times;
  const auto start = Clock::now();
  do {
    const auto t0 = Clock::now();
    body();
    times.push_back(seconds_since(t0));
  } while (seconds_since(start) < min_seconds && times.size() < 10000);
  return {median(times), static_cast<int>(times.size())};
}

volatile std::uint64_t g_sink = 0; // keeps timed results alive

} // namespace

// rule: BENCH.LAVAPIPE
std::pair<unsigned, std::string> lavapipe_threads() {
  if (const char* v = std::getenv("LP_NUM_THREADS"); v != nullptr && *v != '\0') {
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    if (end != nullptr && *end == '\0' && n >= 0 && n <= 256)
      return {n == 0 ? 1u : static_cast<unsigned>(n),
              "LP_NUM_THREADS=" + std::string(v) +
                  (n == 0 ? " (rasterizes on the calling thread)" : "")};
    return {0u, "LP_NUM_THREADS=\"" + std::string(v) + "\" is not an integer in [0, 256]: unknown"};
  }
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  return {online > 0 ? static_cast<unsigned>(online) : 0u,
          "llvmpipe's default: one per online processor (LP_NUM_THREADS unset)"};
}

double RungResult::medium_ratio() const {
  for (const auto& f : families)
    if (f.scene == "medium")
      return f.ratio_to_reference;
  return 0.0;
}

const RungResult* LadderReport::find(Rung r) const {
  for (const auto& x : rungs)
    if (x.rung == r)
      return &x;
  return nullptr;
}

LadderReport run_ladder(const LadderConfig& c, const LavapipeTimer& lavapipe,
                        const std::function<void(const std::string&)>& progress) {
  const auto t_start = Clock::now();
  const auto say = [&](const std::string& s) {
    if (progress)
      progress(s);
  };
  LadderReport rep;
  rep.config = c;
  rep.date = utc_now();
  rep.cpu = cpu_model();
  rep.isa = std::string(to_string(best_isa()));
  rep.limit_isa = std::string(limit_isa());
  rep.limit_lanes = limit_lanes();
  // The batch counter's rows: sixteen lanes with AVX-512, eight with AVX2 (FAST.BATCH.LANES16).
  rep.batch_lanes = best_isa() == Isa::kAvx512 ? 16 : best_isa() == Isa::kAvx2 ? 8 : 1;
  rep.threads = std::max(1u, c.threads);
  const LadderScenes scenes = make_scenes(c);
  for (const Rung r : all_rungs())
    rep.rungs.push_back(RungResult{r, {}, {}, {}, 0, 0, 0});

  // rule: BENCH.METRIC.THROUGHPUT, BENCH.METRIC.ERROR, BENCH.METRIC.WATERTIGHT
  for (const LadderScene& s : scenes.timed) {
    rep.scenes.push_back(s.name);
    const std::uint64_t decisions = count_decisions(s);
    say("scene " + s.name + ": " + std::to_string(s.triangles.size()) + " triangles, " +
        std::to_string(decisions) + " decisions");
    Coverage exact;
    run_rung(Rung::kExact, s, &exact);
    double ref_dps = 0.0;
    for (RungResult& rr : rep.rungs) {
      FamilyResult f;
      f.scene = s.name;
      f.triangles = s.triangles.size();
      f.decisions = decisions;
      const auto [sec, reps] = time_median(c.min_seconds, [&] {
        f.covered = run_rung(rr.rung, s, nullptr);
        g_sink = g_sink + f.covered;
      });
      f.seconds = sec;
      f.repeats = reps;
      f.decisions_per_second = sec > 0 ? static_cast<double>(decisions) / sec : 0.0;
      f.triangles_per_second = sec > 0 ? static_cast<double>(f.triangles) / sec : 0.0;
      if (rr.rung == Rung::kReference)
        ref_dps = f.decisions_per_second;
      if (has_coverage(rr.rung)) {
        Coverage cov;
        if (rr.rung == Rung::kExact)
          cov = exact;
        else
          run_rung(rr.rung, s, &cov);
        f.errors = symmetric_difference(cov, exact);
        f.watertight = watertight_violations(s, cov);
        rr.total_errors += *f.errors;
        rr.total_watertight += *f.watertight;
      }
      rr.total_decisions += decisions;
      if (s.name == "small" && rr.rung == Rung::kReference)
        rep.reference_small_covered = f.covered;
      rr.families.push_back(f);
      say("  " + std::string(to_string(rr.rung)) + ": " + std::to_string(reps) + " repeats");
    }
    for (RungResult& rr : rep.rungs) {
      FamilyResult& f = rr.families.back();
      f.ratio_to_reference = ref_dps > 0 ? f.decisions_per_second / ref_dps : 0.0;
    }
    // rule: BENCH.METRIC.THROUGHPUT
    if (rep.find(Rung::kReferenceFast) != nullptr) {
      FamilyResult f;
      f.scene = s.name;
      f.triangles = s.triangles.size();
      f.decisions = decisions;
      FastPool pool(rep.threads); // created once, outside the timed repeats
      const auto [sec, reps] = time_median(c.min_seconds, [&] {
        f.covered = pool.count(s);
        g_sink = g_sink + f.covered;
      });
      f.seconds = sec;
      f.repeats = reps;
      f.decisions_per_second = sec > 0 ? static_cast<double>(decisions) / sec : 0.0;
      f.triangles_per_second = sec > 0 ? static_cast<double>(f.triangles) / sec : 0.0;
      f.ratio_to_reference = ref_dps > 0 ? f.decisions_per_second / ref_dps : 0.0;
      rep.fast_threaded.push_back(f);
      say("  reference-fast x" + std::to_string(rep.threads) + ": " + std::to_string(reps) +
          " repeats");
    }
  }

  // rule: BENCH.METRIC.TRANSLATION
  say("translation sweep");
  const LadderScene& base = scenes.translate_base;
  std::vector<Coverage> exact_at;
  for (const std::int32_t t : scenes.sweep) {
    rep.sweep_t.push_back(t);
    Coverage e;
    run_rung(Rung::kExact, translated(base, t, base.width, base.height), &e);
    exact_at.push_back(std::move(e));
  }
  rep.sweep_note = "t = 0 and 2^k px for k = 0..13 (top 8192): the mesh must stay inside the "
                   "largest target the kernel accepts (16384 px a side, SCENE.TARGET.LIMITS)";
  for (RungResult& rr : rep.rungs) {
    if (!has_coverage(rr.rung))
      continue;
    Coverage at0;
    for (std::size_t i = 0; i < scenes.sweep.size(); ++i) {
      const std::int32_t t = scenes.sweep[i];
      const LadderScene s = translated(base, t, base.width, base.height);
      Coverage cov;
      if (rr.rung == Rung::kExact)
        cov = exact_at[i];
      else
        run_rung(rr.rung, s, &cov);
      SweepPoint p;
      p.t = t;
      p.errors = symmetric_difference(cov, exact_at[i]);
      p.watertight = watertight_violations(s, cov);
      if (i == 0)
        at0 = cov;
      else
        p.translation = symmetric_difference(shifted_back(cov, t), at0);
      rr.sweep.push_back(p);
    }
    rr.range = exact_range(rr.sweep);
  }

  // rule: BENCH.LAVAPIPE
  for (const LadderScene& s : scenes.timed) {
    if (s.name != "small")
      continue;
    if (lavapipe) {
      say("lavapipe");
      rep.lavapipe = lavapipe(s);
    } else {
      rep.lavapipe.why_not = "not run";
    }
    rep.lavapipe.triangles = s.triangles.size();
    const auto [lt, source] = lavapipe_threads();
    rep.lavapipe.threads = lt;
    rep.lavapipe.threads_source = source;
  }
  rep.seconds_total = seconds_since(t_start);
  return rep;
}

// rule: BENCH.TARGETS
std::vector<TargetCheck> check_targets(const LadderReport& r) {
  std::vector<TargetCheck> out;
  const RungResult* fast = r.find(Rung::kReferenceFast);
  const RungResult* limit = r.find(Rung::kLimit);
  const auto family = [](const RungResult* rr, const std::string& name) -> const FamilyResult* {
    if (rr == nullptr)
      return nullptr;
    for (const auto& f : rr->families)
      if (f.scene == name)
        return &f;
    return nullptr;
  };
  const auto fmt = [](double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return std::string(buf);
  };
  {
    TargetCheck t{"reference-fast >= 90% of limit's decisions/s on medium triangles, at the same "
                  "lane width",
                  "",
                  {}};
    const FamilyResult* a = family(fast, "medium");
    const FamilyResult* b = family(limit, "medium");
    if (a && b && b->decisions_per_second > 0 && a->decisions_per_second > 0) {
      const double q = a->decisions_per_second / b->decisions_per_second;
      const bool same = r.batch_lanes == r.limit_lanes;
      t.measured = fmt(100.0 * q) + "% of limit (batch rows " + std::to_string(r.batch_lanes) +
                   " lanes, limit " + std::to_string(r.limit_lanes) + ")";
      t.met = same && q >= 0.9;
    } else {
      t.measured = "not measured";
    }
    out.push_back(t);
  }
  // The reference against both float rungs: the scalar one, and the same arithmetic in SIMD
  // lanes (float-simd), so that the ratio shows what exactness costs, not SIMD against scalar.
  for (const Rung fr : {Rung::kFloat, Rung::kFloatSimd}) {
    const std::string fname(to_string(fr));
    TargetCheck t{"reference-fast no slower than " + fname + " (small, medium, large)", "", {}};
    double worst = 0;
    bool ok = true, any = false;
    for (const char* name : {"small", "medium", "large"}) {
      const FamilyResult* a = family(fast, name);
      const FamilyResult* b = family(r.find(fr), name);
      if (!a || !b || b->decisions_per_second <= 0 || a->decisions_per_second <= 0) {
        ok = false;
        continue;
      }
      const double q = a->decisions_per_second / b->decisions_per_second;
      worst = any ? std::min(worst, q) : q;
      any = true;
    }
    if (ok && any) {
      t.measured = "slowest ratio " + fmt(worst) + "x " + fname;
      t.met = worst >= 1.0;
    } else {
      t.measured = "not measured";
    }
    out.push_back(t);
  }
  {
    // Equal resources: rastrules on N threads against lavapipe on its own thread count; when
    // the counts differ, per thread. The single-thread ratio is reported too.
    TargetCheck t{
        "reference-fast >= 20x lavapipe's triangles/s on small triangles (same cores)", "", {}};
    const FamilyResult* one = family(fast, "small");
    const FamilyResult* many = nullptr;
    for (const auto& f : r.fast_threaded)
      if (f.scene == "small")
        many = &f;
    if (one && many && many->triangles_per_second > 0 && r.lavapipe.available &&
        r.lavapipe.seconds > 0 && r.lavapipe.threads > 0) {
      const double lav = static_cast<double>(r.lavapipe.triangles) / r.lavapipe.seconds;
      const double single = one->triangles_per_second / lav;
      double q = 0;
      if (r.lavapipe.threads == r.threads) {
        q = many->triangles_per_second / lav;
        t.measured = fmt(q) + "x lavapipe, both on " + std::to_string(r.threads) + " thread" +
                     (r.threads == 1 ? "" : "s") + " (equal resources)";
      } else {
        q = (many->triangles_per_second / r.threads) / (lav / r.lavapipe.threads);
        t.measured = fmt(q) + "x lavapipe per thread (rastrules " + std::to_string(r.threads) +
                     ", lavapipe " + std::to_string(r.lavapipe.threads) +
                     " threads: the counts differ, each rate divided by its thread count)";
      }
      t.measured += "; single-thread ratio (reference-fast on 1 thread against lavapipe on " +
                    std::to_string(r.lavapipe.threads) + "): " + fmt(single) + "x";
      t.met = q >= 20.0;
    } else if (!r.lavapipe.available) {
      t.measured = "lavapipe: " + r.lavapipe.why_not;
    } else if (r.lavapipe.threads == 0) {
      t.measured = "lavapipe's thread count is unknown (" + r.lavapipe.threads_source + ")";
    } else {
      t.measured = "not measured";
    }
    out.push_back(t);
  }
  return out;
}

} // namespace rastrules::bench
