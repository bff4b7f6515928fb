// SPDX-License-Identifier: MIT
// Proof: the kernel's D3D diamond-exit formulas (formula::d3d_contains, d3d_meets, d3d_exits,
// whose meets test is a Fourier-Motzkin elimination of the segment parameter) equal the
// geometric rule in the spec's words, for x-major and y-major lines, over all real positions:
// the end point test equals membership in the half-open test area, and "meets" holds iff some
// point a + t (b - a), t in [0, 1], lies in the test area, in both directions:
//   "such a point exists => meets" in one nlsat query with t free;
//   "meets => such a point exists" with an explicit witness t* (the midpoint of the largest
//   lower and the smallest upper bound on t, or, y-major, the parameter of the right corner),
//   in lemmas (FM, ORDER, BACK0-5, SPEC, CORNER, DEFS; see diamond_exit.hpp) whose
//   conclusions are then chained: that last step is checked on the Boolean skeleton (every
//   arithmetic atom a fresh Boolean), so it uses no arithmetic at all. Z3 4.8.12 times out on
//   this direction as a single query.
// Also the Vulkan point test area (vk_contains equals "interior, right edges, right corner").
// Not proved: the reverse direction for the Vulkan touch test vk_meets (only tested, through
// the whole line kernel against the exact oracle, by properties/line/line_props.cpp).
// rule: LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.DIAMOND.GEOMETRY, LINE.VK.TEST_AREA
// Assumes: none (the statement is over the reals; integrality is not needed; the kernel's
// int64_t evaluation is exact by diamond_no_overflow.cpp). Trust base beyond Z3: the
// Boolean-skeleton construction (boolean_skeleton in diamond_exit.hpp; an abstraction, so a
// tautology of the skeleton is a tautology of the formula).
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include <iostream>

#include "line/diamond_exit.hpp"
#include "support/prover.hpp"

int main() {
  using namespace rastrules::proofs;
  Domain dom;
  Prover pr(dom, "line/diamond_exit_matches_spec",
            "LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.DIAMOND.GEOMETRY, LINE.VK.TEST_AREA", {},
            kernel_constants());
  NraProver nra(dom.ctx());
  prove_d3d_diamond_exit<DiamondKernelModel>(pr, nra);
  prove_d3d_meets_witness<DiamondKernelModel>(pr, nra);
  prove_vk_point_area<DiamondKernelModel>(pr);
  std::size_t nra_ok = 0;
  for (const auto& r : nra.results())
    nra_ok += r.second == Status::kProved;
  std::cout << "nonlinear and division theorems (NraProver): " << nra_ok << " passed, "
            << nra.results().size() - nra_ok << " failed\n";
  const int status = pr.finish();
  return (status == 0 && nra.all_proved()) ? 0 : 1;
}
