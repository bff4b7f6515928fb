// SPDX-License-Identifier: MIT
// Proof: the kernel's D3D diamond-exit formulas (formula::d3d_contains, d3d_meets, d3d_exits,
// whose meets test is a Fourier-Motzkin elimination of the segment parameter) equal the
// geometric rule in the spec's words, for x-major and y-major lines, over all real positions:
// the end point test equals membership in the half-open test area, and "meets" holds iff some
// point a + t (b - a), t in [0, 1], lies in the test area, proved in the direction
// "such a point exists => meets" (the converse times out in Z3 4.8.12 with the quantifier and
// with an explicit witness alike; properties/line/line_props.cpp checks it against the exact
// oracle). Also the Vulkan point test area (vk_contains equals "interior, right edges, right
// corner").
// rule: LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.DIAMOND.GEOMETRY, LINE.VK.TEST_AREA
// Assumes: none (the statement is over the reals; integrality is not needed; the kernel's
// int64_t evaluation is exact by diamond_no_overflow.cpp)
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
  prove_vk_point_area<DiamondKernelModel>(pr);
  std::size_t nra_ok = 0;
  for (const auto& r : nra.results()) nra_ok += r.second == Status::kProved;
  std::cout << "nonlinear theorems (qfnra-nlsat): " << nra_ok << " passed, "
            << nra.results().size() - nra_ok << " failed\n";
  const int status = pr.finish();
  return (status == 0 && nra.all_proved()) ? 0 : 1;
}
