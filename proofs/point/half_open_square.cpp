// SPDX-License-Identifier: MIT
// Proof: a point covers exactly the samples of its half-open square, each at most once.
// For every centre c in POINT.RANGE and every 16.8 sample p in the vertex range, under each of
// the four fill conventions, the kernel's two point triangles (formula::point_z_triangles, the
// template point_triangles instantiates) are clockwise and in range, cover p iff p lies in the
// half-open square of side 1 px centred on c, never both cover p, and the other diagonal would
// give the same coverage.
// rule: POINT.COVER.HALF_OPEN, POINT.RANGE, POINT.SHAPE.TWO_TRIANGLES, POINT.SHAPE.SQUARE
// Assumes: POINT.RANGE, SNAP.VERTEX.RANGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
// TRI.ORIENT.NORMALISE Expected: PROVED. Exit status 0 iff every theorem is PROVED; a
// counterexample is printed otherwise.

#include "point/half_open_square.hpp"
#include "point/point_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PointKernelModel>(
      kHalfOpenSquare,
      "POINT.COVER.HALF_OPEN, POINT.RANGE, POINT.SHAPE.TWO_TRIANGLES, POINT.SHAPE.SQUARE",
      {"POINT.RANGE", "SNAP.VERTEX.RANGE", "TRI.FILL.TOP_LEFT", "TRI.FILL.CONVENTION",
       "TRI.ORIENT.NORMALISE"});
}
