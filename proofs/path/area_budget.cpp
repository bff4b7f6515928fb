// SPDX-License-Identifier: MIT
// Proof: every integer the cell method of exact area coverage computes fits its C++ type.
// For every line edge with raw coordinates in [-2^23, 2^23] and every row and column line of a
// target of at most kMaxTargetSide px: x at a row line and y at a column line times the run
// (|.| <= 2^23 |run|), a crossing's column and its positions on the cell's border (on the side
// they belong to), the border order's cross products, the doubling-back test, the common point
// of two segments, the ramp integrals and a cell's part of the integral of w: all fit, with the
// magnitudes PATH.AREA.CELLS states (rastrules/formula/path_area.hpp, instantiated on Sym).
// Method: the templates on Sym<std::int64_t> and Sym<__int128> (exact integers with "fits"
// obligations); nonlinear bounds through lemmas A, P and D (proved first) instantiated as
// hypotheses; hypotheses AND NOT(goal AND obligations) must be unsat.
// rule: PATH.AREA.CELLS
// Assumes: PATH.GEOMETRY, SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include "path/area_budget.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<AreaKernelModel>(
      kAreaBudget, "PATH.AREA.CELLS",
      {"PATH.GEOMETRY", "SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE"});
}
