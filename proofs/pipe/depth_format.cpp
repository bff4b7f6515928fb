// SPDX-License-Identifier: MIT
// Proof: the UNORM depth conversion never leaves its format and rounds to nearest. For every
// double z in [0, 1] (a clamped depth or a clear value) and d16 and d24, the kernel's
// floor(z * max + 0.5) (formula::unorm_rounding_argument on double, max = unorm_max(n), with
// the + 0.5 rounded to double) lies in [0, 2^n - 1], so the uint32_t conversion is exact, and
// equals the spec's floor(fl64(z * max) + 0.5) with the exact + 0.5: the nearest integer to
// fl64(z * max), ties up. d32f: float(z) lies in [0, 1]. Bit-exact IEEE-754 (Z3's
// floating-point theory), every double in range, subnormals included.
// rule: PIPE.DEPTH.FORMAT, PIPE.DEPTH.UNORM_ROUND
// Assumes: PIPE.DEPTH.CLAMP, PIPE.VIEWPORT.RANGE (so 0 <= z <= 1)
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "pipe/pipe_proofs.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PipeModel>(kDepthFormat, "PIPE.DEPTH.FORMAT, PIPE.DEPTH.UNORM_ROUND",
                                   {"PIPE.DEPTH.CLAMP", "PIPE.VIEWPORT.RANGE"},
                                   depth_format_matches_kernel);
}
