// SPDX-License-Identifier: MIT
// The precision ladder's rungs as Google Benchmark cases (BENCH.LADDER.RUNGS): every rung on
// the quick-mode scenes of `rastrules bench --ladder --quick`, counters in decisions per
// second. The ladder command (tools/cli/bench.cpp) is the report; these are for profiling.
// rule: BENCH.METRIC.THROUGHPUT

#include <benchmark/benchmark.h>

#include <string>

#include "rastrules/bench/ladder.hpp"

namespace {

const rastrules::bench::LadderScenes& scenes() {
  static const rastrules::bench::LadderScenes s = [] {
    rastrules::bench::LadderConfig c;
    c.quick = true;
    return rastrules::bench::make_scenes(c);
  }();
  return s;
}

void BM_LadderRung(benchmark::State& st, rastrules::bench::Rung rung, std::size_t scene) {
  const auto& s = scenes().timed[scene];
  const auto decisions = rastrules::bench::count_decisions(s);
  std::uint64_t covered = 0;
  for (auto _ : st) {
    covered = rastrules::bench::run_rung(rung, s, nullptr);
    benchmark::DoNotOptimize(covered);
  }
  st.counters["decisions/s"] =
      benchmark::Counter(static_cast<double>(decisions) * static_cast<double>(st.iterations()),
                         benchmark::Counter::kIsRate);
  st.counters["covered"] = static_cast<double>(covered);
}

// Registers rung x scene; `exact` only on the medium mesh (the oracle is slow).
const bool registered = [] {
  for (const auto rung : rastrules::bench::all_rungs()) {
    for (std::size_t i = 0; i < scenes().timed.size(); ++i) {
      if (rung == rastrules::bench::Rung::kExact && scenes().timed[i].name != "medium")
        continue;
      const std::string name = "BM_Ladder/" + std::string(rastrules::bench::to_string(rung)) + "/" +
                               scenes().timed[i].name;
      benchmark::RegisterBenchmark(name.c_str(), BM_LadderRung, rung, i)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  return true;
}();

} // namespace
