// SPDX-License-Identifier: MIT
// Proof: the kernel's diamond-exit formulas (d3d_exits for both axes, vk_exits) evaluated on
// std::int64_t never overflow for end points within 2^24 raw of the pixel centre, which
// covers every vertex in SNAP.VERTEX.RANGE against every pixel of a target within
// SCENE.TARGET.LIMITS; so the kernel computes them exactly.
// rule: LINE.D3D.EXIT, LINE.VK.EXIT
// Assumes: SNAP.VERTEX.RANGE, SCENE.TARGET.LIMITS
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include <cstdint>

#include "line/diamond_exit.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_proof("line/diamond_no_overflow", "LINE.D3D.EXIT, LINE.VK.EXIT",
                   {"SNAP.VERTEX.RANGE", "SCENE.TARGET.LIMITS"}, kernel_constants(),
                   prove_diamond_no_overflow<Sym<std::int64_t>>);
}
