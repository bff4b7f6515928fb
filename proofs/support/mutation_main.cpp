// SPDX-License-Identifier: MIT
// The main of every mutation self-check (proof.selftest.*mutants): runs the self-check that
// the area's mutants.cpp defines (support/mutation.hpp). Exit status 0 iff every mutant run is
// REFUTED.

#include "support/mutation.hpp"

int main() {
  return rastrules::proofs::run_mutation_selfcheck(rastrules::proofs::mutation_selfcheck());
}
