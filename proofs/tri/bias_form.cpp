// SPDX-License-Identifier: MIT
// Proof: the traversal's bias form of the edge test equals the rule.
// For every E = formula::edge_value(a, b, p) with a, b, p in the vertex range, and for both
// values of the flag given to formula::edge_bias (a C++ bool, so both constant calls are
// checked): E + edge_bias(inclusive) >= 0 <=> E > 0 || (E == 0 && inclusive), and the sum
// fits int64_t. Also the traversal's sign test (e0 | e1 | e2) >= 0 equals "all three >= 0"
// on int64_t.
// rule: FIX.BIAS.FORM
// Assumes: SNAP.VERTEX.RANGE, TRI.FILL.TOP_LEFT
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "tri/bias_form.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(kBiasForm, "FIX.BIAS.FORM",
                                     {"SNAP.VERTEX.RANGE", "TRI.FILL.TOP_LEFT"});
}
