// SPDX-License-Identifier: MIT
// The mutation self-check runner every <area>/mutants.cpp uses: runs obligation templates
// against deliberately broken models and passes only if each run (one broken model, one
// obligation) is REFUTED by at least one theorem (a model that survives means the proofs cannot
// see that kind of bug). Each run gets a fresh Domain and Prover, so variable names never clash
// between runs.

#pragma once

#include <cstddef>
#include <functional>
#include <iostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// The theorems one prover ran, as Prover::results() lists them.
using TheoremResults = std::vector<std::pair<std::string, Status>>;

// One broken model and the obligation that must refute it.
struct MutantRun {
  // `prove_fn` runs the obligation on the run's Prover: any callable taking a Prover&. One that
  // also proves theorems with a prover of its own (line's NraProver) returns that prover's
  // results, and they count too.
  template <class Prove>
  MutantRun(std::string mutant, std::string obligation_file, Prove prove_fn,
            std::vector<Constant> more_constants = {})
      : name(std::move(mutant)), obligation(std::move(obligation_file)),
        extra_constants(std::move(more_constants)) {
    if constexpr (std::is_void_v<std::invoke_result_t<Prove&, Prover&>>) {
      prove = [fn = std::move(prove_fn)](Prover& pr) {
        fn(pr);
        return TheoremResults{};
      };
    } else {
      prove = std::move(prove_fn);
    }
  }

  std::string name;       // the broken model (its kName)
  std::string obligation; // the obligation, as "<area>/<file>", e.g. "fast/lane_budget"
  std::function<TheoremResults(Prover&)> prove;
  // Printed after the self-check's constants (selftest: edge_value_no_overflow's model range).
  std::vector<Constant> extra_constants;
};

// Runs every mutant (report header "<obligation> [mutant: <name>]", with `assumes` and
// `constants`), prints one summary line per run and the totals, and returns the process exit
// status: 0 iff no run survived (and at least one ran).
inline int run_mutation_selfcheck(const std::string& area, const std::vector<MutantRun>& runs,
                                  const std::vector<Constant>& constants,
                                  const std::vector<std::string>& assumes = {}) {
  int survived = 0;
  std::vector<std::string> summary;
  for (const MutantRun& r : runs) {
    const std::string run_name = r.name + " / " + r.obligation;
    std::cout << "\n=== mutant: " << run_name << "\n";
    std::vector<Constant> k = constants;
    k.insert(k.end(), r.extra_constants.begin(), r.extra_constants.end());
    Domain dom;
    Prover pr(dom, r.obligation + " [mutant: " + r.name + "]", "(self-check)", assumes, k);
    TheoremResults results = r.prove(pr);
    results.insert(results.begin(), pr.results().begin(), pr.results().end());
    int refuted = 0;
    for (const auto& result : results)
      refuted += result.second == Status::kRefuted ? 1 : 0;
    survived += refuted > 0 ? 0 : 1;
    summary.push_back(std::string(refuted > 0 ? "REFUTED  " : "SURVIVED ") + run_name + " (" +
                      std::to_string(refuted) + " of " + std::to_string(results.size()) +
                      " theorems refuted)");
  }
  std::cout << "\nmutation self-check (" << area << "):\n";
  for (const std::string& line : summary)
    std::cout << "  " << line << "\n";
  std::cout << (summary.size() - static_cast<std::size_t>(survived)) << " mutant runs refuted, "
            << survived << " survived\n";
  return (survived == 0 && !runs.empty()) ? 0 : 1;
}

} // namespace rastrules::proofs
