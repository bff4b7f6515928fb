// SPDX-License-Identifier: MIT
// The mutation self-check runner: runs obligation templates against deliberately broken models
// and passes only if each broken model is REFUTED by at least one theorem (a model that
// survives means the proofs cannot see that kind of bug). Each run gets a fresh Domain and
// Prover, so variable names never clash between runs.

#pragma once

#include <cstddef>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// One broken model and the obligations that must refute it.
struct MutantRun {
  std::string name;
  std::function<void(Prover&)> prove;
};

// Runs every mutant (report header "<area> [mutant: <name>]"), prints one summary line per
// mutant and the totals, and returns the process exit status: 0 iff no mutant survived.
inline int run_mutation_selfcheck(const std::string& area, const std::vector<MutantRun>& runs,
                                  const std::vector<Constant>& constants) {
  int survived = 0;
  std::vector<std::string> summary;
  for (const MutantRun& r : runs) {
    std::cout << "\n=== mutant: " << r.name << "\n";
    Domain dom;
    Prover pr(dom, area + " [mutant: " + r.name + "]", "(self-check)", {}, constants);
    r.prove(pr);
    int refuted = 0;
    for (const auto& result : pr.results())
      refuted += result.second == Status::kRefuted ? 1 : 0;
    survived += refuted > 0 ? 0 : 1;
    summary.push_back(std::string(refuted > 0 ? "REFUTED  " : "SURVIVED ") + r.name + " (" +
                      std::to_string(refuted) + " of " + std::to_string(pr.results().size()) +
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
