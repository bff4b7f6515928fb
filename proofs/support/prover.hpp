// SPDX-License-Identifier: MIT
// Runs proof obligations with Z3 and prints the report every proof executable shares:
// the constants, the solver version, the assumptions (rule IDs), one line per theorem
// (PROVED | REFUTED | UNKNOWN, seconds), a counterexample in raw fixed-point units and in
// pixels when a theorem is refuted, and a final "N passed, N failed" line.
//
// A theorem is (hypotheses, goal, obligations). It is PROVED when the hypotheses are
// satisfiable (checked first, so that no theorem is vacuous) and
// hypotheses AND NOT(goal AND every obligation) is unsatisfiable. It is REFUTED when that
// query has a model (the counterexample), UNKNOWN otherwise (timeout, solver gave up, or
// unsatisfiable hypotheses).

#pragma once

#include <z3++.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "support/sym.hpp"

namespace rastrules::proofs {

enum class Status { kProved, kRefuted, kUnknown };

// How a theorem's query is solved.
enum class Solver {
  kArithmetic,    // simplify (som) then the SMT core: integer and real arithmetic (the default)
  kFloatingPoint, // simplify then Z3's QF_FP tactic (bit-blasting to SAT): IEEE-754 terms,
                  // bit-vectors and Booleans only (no integers or reals in the query)
};

[[nodiscard]] const char* to_string(Status s);

// A named constant printed in the report header.
struct Constant {
  std::string name;
  std::int64_t value;
  Unit unit;
};

// The constants every report prints, from rastrules/fixed.hpp.
[[nodiscard]] std::vector<Constant> kernel_constants();
// kernel_constants() followed by `more` (a model's own constants, in the order given).
[[nodiscard]] std::vector<Constant> kernel_constants_and(const std::vector<Constant>& more);

// Returns "Z3 <full version>".
[[nodiscard]] std::string solver_version();

// Returns the value of e in model m as an exact decimal, and for fixed-point units the value
// in pixels (or pixel^2) in brackets.
[[nodiscard]] std::string show_value(const z3::model& m, const z3::expr& e, Unit unit);

class Prover {
public:
  // Prints the report header. `rules` is the rule list the proof cites, `assumes` the rule IDs
  // it takes as hypotheses.
  Prover(Domain& dom, std::string obligation, std::string rules, std::vector<std::string> assumes,
         std::vector<Constant> constants);

  [[nodiscard]] Domain& domain() { return dom_; }
  [[nodiscard]] z3::context& ctx() { return dom_.ctx(); }

  // Chooses the solver of the following theorems (and prints it in the report).
  void use_solver(Solver s);

  // Adds a term to show in the counterexample of the next theorem.
  void watch(const std::string& name, const z3::expr& value, Unit unit);

  // Proves one theorem (see the file comment) and prints its line.
  Status prove(const std::string& name, const std::vector<z3::expr>& hypotheses,
               const z3::expr& goal, const std::vector<Obligation>& obligations = {});

  // Records theorem `name` as UNKNOWN without running it (for example because a lemma it
  // relies on was not proved) and prints its line.
  Status skip(const std::string& name, const std::string& reason);

  [[nodiscard]] const std::vector<std::pair<std::string, Status>>& results() const {
    return results_;
  }

  // Prints "N passed, N failed" and returns the process exit status: 0 iff every theorem
  // was PROVED (and at least one was run).
  int finish();

private:
  Domain& dom_;
  Solver solver_ = Solver::kArithmetic;
  std::string obligation_;
  std::vector<Watch> watches_;
  std::vector<std::pair<std::string, Status>> results_;
};

// Runs one report: a fresh Domain and a Prover that prints the header (see the constructor),
// then prove(pr). Returns the report's exit status (Prover::finish): 0 iff every theorem was
// PROVED.
template <class Prove>
int run_proof(std::string obligation, std::string rules, std::vector<std::string> assumes,
              std::vector<Constant> constants, Prove&& prove) {
  Domain dom;
  Prover pr(dom, std::move(obligation), std::move(rules), std::move(assumes), std::move(constants));
  prove(pr);
  return pr.finish();
}

// Per-query time limit in seconds: RASTRULES_PROOF_TIMEOUT from the environment, else 30.
[[nodiscard]] double query_timeout_seconds();

} // namespace rastrules::proofs
