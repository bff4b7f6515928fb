// SPDX-License-Identifier: MIT
// One proof obligation as a value, so that its proof's main and the mutation self-checks
// (support/mutation.hpp) run the same template under the same name. Each obligation header
// defines one next to its template.

#pragma once

#include <string>
#include <utility>
#include <vector>

#include "support/prover.hpp"

namespace rastrules::proofs {

// The report name "<area>/<file>" and `prove`, a generic lambda `[]<class F>(Prover& pr) { ... }`
// that states the obligation's theorems for model F.
template <class Prove> struct ProofObligation {
  std::string file;
  Prove prove;
};

// Runs the obligation's proof on model F: one report that proves `rules` and assumes `assumes`,
// with F's constants. Returns its exit status (run_proof). A proof that restates kernel code
// passes the check of that restatement against the compiled kernel (it prints what differs):
// when the check fails, nothing is proved and the exit status is 1.
template <class F, class Prove>
int run_obligation(const ProofObligation<Prove>& o, std::string rules,
                   std::vector<std::string> assumes,
                   bool (*restatement_matches_kernel)() = nullptr) {
  if (restatement_matches_kernel != nullptr && !restatement_matches_kernel())
    return 1;
  return run_proof(o.file, std::move(rules), std::move(assumes), F::constants(),
                   [&](Prover& pr) { o.prove.template operator()<F>(pr); });
}

} // namespace rastrules::proofs
