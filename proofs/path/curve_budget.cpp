// SPDX-License-Identifier: MIT
// Proof: every integer the path kernel's curve crossing test computes fits its C++ type.
// For every quadratic and cubic Bézier with raw coordinates in [-2^23, 2^23] and every sample
// row in that range: the power coefficients, g = y - s.y and its Bernstein coefficients
// (int64_t); the fast path's P(k / 2^30) 2^90, the Lipschitz and Bernstein tests of a root's x,
// their floors (__int128, thresholds narrowed to int64_t); the quadratic rational path's
// discriminant, square root, roots p / q, slope, numerator and threshold; the cubic end path's
// divisions by t and t - 1, h's discriminant, roots, numerator and threshold; the monotone
// pieces' y', its discriminant, the vertex test, a bracket's range and s.y 2^90: all fit, with the
// magnitudes PATH.CURVE.SAMPLE states (rastrules/formula/path_curve.hpp, instantiated on Sym).
// Method: the templates on Sym<std::int64_t> and Sym<__int128> (exact integers with "fits"
// obligations); nonlinear bounds through lemmas P, M, L, A, D (proved first) instantiated as
// hypotheses; hypotheses AND NOT(goal AND obligations) must be unsat.
// rule: PATH.CURVE.SAMPLE
// Assumes: PATH.GEOMETRY, SNAP.VERTEX.RANGE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include "path/curve_budget.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<CurveKernelModel>(kCurveBudget, "PATH.CURVE.SAMPLE",
                                          {"PATH.GEOMETRY", "SNAP.VERTEX.RANGE"});
}
