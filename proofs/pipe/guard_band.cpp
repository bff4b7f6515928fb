// SPDX-License-Identifier: MIT
// Proof: the guard band leaves room for rounding before the snap range ends. With
// G = rastrules::pipe::kGuardBand (its exact value): every window coordinate within G + 1 px
// of the origin (a guard-band point moved by at most 1 px of float rounding) snaps, by any
// round-to-nearest, inside SNAP.VERTEX.RANGE; so does every coordinate within G + 1023 px;
// every point of the largest target lies at least 15360 px inside the band.
// rule: PIPE.CLIP.GUARD_BAND_SNAP
// Assumes: PIPE.CLIP.VOLUME, SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SCENE.TARGET.LIMITS; that the
// float32 divide and viewport transform of a point inside the volume is within 1 px of its
// exact window position (not proved here)
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "pipe/pipe_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PipeModel>(
      kGuardBand, "PIPE.CLIP.GUARD_BAND_SNAP",
      {"PIPE.CLIP.VOLUME", "SNAP.VERTEX.ROUND", "SNAP.VERTEX.RANGE", "SCENE.TARGET.LIMITS"});
}
