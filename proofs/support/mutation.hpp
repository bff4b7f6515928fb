// SPDX-License-Identifier: MIT
// The mutation self-check that every <area>/mutants.cpp defines (mutation_selfcheck: groups of
// runs made with refute) and support/mutation_main.cpp runs: runs obligation templates
// against deliberately broken models and passes only if each run (one broken model, one
// obligation) is REFUTED by at least one theorem (a model that survives means the proofs cannot
// see that kind of bug). Each run gets a fresh Domain and Prover, so variable names never clash
// between runs.

#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "support/obligation.hpp"
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

// The runs of the broken models Mutants..., in that order, against one obligation
// ("<area>/<file>"). `prove` is a generic lambda `[]<class F>(Prover& pr) { ... }` that runs the
// obligation on model F (returning nothing, or TheoremResults as MutantRun's prove_fn may).
template <class... Mutants, class Prove>
std::vector<MutantRun> refute(const std::string& obligation, Prove prove) {
  return {MutantRun(Mutants::kName, obligation,
                    [prove](Prover& pr) { return prove.template operator()<Mutants>(pr); })...};
}
// The same for an obligation's own proof (support/obligation.hpp).
template <class... Mutants, class Prove>
std::vector<MutantRun> refute(const ProofObligation<Prove>& obligation) {
  return refute<Mutants...>(obligation.file, obligation.prove);
}

// A mutant's name (its kName) given as a template argument: a string literal.
template <std::size_t N> struct MutantName {
  // Implicit, so that a literal is the template argument.
  constexpr MutantName(const char (&name)[N]) { std::copy_n(name, N, text); } // NOLINT
  char text[N];
};

// Broken models that several areas build from their own model Base, named in the area's words.
// Base with its accumulator type replaced by Sym<Rep> (e.g. int32_t, as a SIMD lane might use).
template <class Base, class Rep, MutantName Name> struct AccumulatorOf : Base {
  static constexpr const char* kName = Name.text;
  using Acc = Sym<Rep>;
};
// Base with its coordinate range replaced by [-2^Bits, 2^Bits) raw units.
template <class Base, int Bits, MutantName Name> struct CoordinateRangeOf : Base {
  static constexpr const char* kName = Name.text;
  static constexpr std::int64_t kMinRaw = -(std::int64_t{1} << Bits);
  static constexpr std::int64_t kMaxRaw = (std::int64_t{1} << Bits) - 1;
};

// One area's mutation self-check: its runs in order (groups, as refute returns them), and the
// constants and assumed rules every run's report lists.
struct MutationSelfcheck {
  std::string area;
  std::vector<std::vector<MutantRun>> groups;
  std::vector<Constant> constants;
  std::vector<std::string> assumes = {};
};

// Each <area>/mutants.cpp defines the self-check it runs; support/mutation_main.cpp runs it.
MutationSelfcheck mutation_selfcheck();

// Runs every mutant of `check` in order (report header "<obligation> [mutant: <name>]", with its
// assumes and constants), prints one summary line per run and the totals, and returns the
// process exit status: 0 iff no run survived (and at least one ran).
inline int run_mutation_selfcheck(const MutationSelfcheck& check) {
  std::vector<MutantRun> runs;
  for (const std::vector<MutantRun>& group : check.groups)
    runs.insert(runs.end(), group.begin(), group.end());
  int survived = 0;
  std::vector<std::string> summary;
  for (const MutantRun& r : runs) {
    const std::string run_name = r.name + " / " + r.obligation;
    std::cout << "\n=== mutant: " << run_name << "\n";
    std::vector<Constant> k = check.constants;
    k.insert(k.end(), r.extra_constants.begin(), r.extra_constants.end());
    Domain dom;
    Prover pr(dom, r.obligation + " [mutant: " + r.name + "]", "(self-check)", check.assumes, k);
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
  std::cout << "\nmutation self-check (" << check.area << "):\n";
  for (const std::string& line : summary)
    std::cout << "  " << line << "\n";
  std::cout << (summary.size() - static_cast<std::size_t>(survived)) << " mutant runs refuted, "
            << survived << " survived\n";
  return (survived == 0 && !runs.empty()) ? 0 : 1;
}

} // namespace rastrules::proofs
