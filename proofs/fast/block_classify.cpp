// SPDX-License-Identifier: MIT
// Proof: the block level of the fast traversal (64 x 64 pixels, kFastBlockSize, classified in
// 64-bit lanes before its 16 tiles) decides exactly. The same three theorem families as the
// tile level, instantiated on the block model: for every edge with endpoints in
// SNAP.VERTEX.RANGE and every lane (i, j) of a block, L = lane_offset(i, j, A, B) in int64_t
// satisfies |L| < kBlockLaneBound; a sample is inside the edge iff L >= lane_threshold(q,
// kBlockLaneBound) (the clamp changes no comparison); and lane_max / lane_min over the block
// make rejection and acceptance sound and exact.
// rule: FAST.TILE.CLASSIFY
// Assumes: SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL,
// TRI.FILL.TOP_LEFT
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fast/fast_proofs.hpp"
#include "support/prover.hpp"

#include <string>
#include <vector>

namespace rastrules::proofs {

// The block level: 64-bit lanes over kFastBlockSize x kFastBlockSize pixels, bound
// kBlockLaneBound (formula/lane.hpp). Everything else (formulas, shift, budget) is the tile
// model's.
struct FastBlockModel : FastKernelModel {
  static constexpr const char* kName = "kernel (blocks)";
  using Lane = Sym<std::int64_t>;
  static constexpr std::int64_t kTile = raster::kFastBlockSize;
  static constexpr std::int64_t kBound = formula::kBlockLaneBound;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"kFastBlockSize", raster::kFastBlockSize, Unit::kInteger},
                                 {"kBlockLaneBound", formula::kBlockLaneBound, Unit::kInteger},
                                 {"kEdgeValueMagBits", kEdgeValueMagBits, Unit::kInteger}});
  }
};

} // namespace rastrules::proofs

int main() {
  using namespace rastrules::proofs;
  if (!shift_restatement_matches_cpp())
    return 1;
  const std::vector<std::string> assumes = {"SNAP.VERTEX.RANGE", "FIX.BUDGET.EDGE_VALUE",
                                            "FIX.BIAS.FORM", "FIX.STEP.INCREMENTAL",
                                            "TRI.FILL.TOP_LEFT"};
  // Each family declares its own variables: one domain and report per family.
  int status = run_proof("fast/block_classify (budget)", "FAST.TILE.CLASSIFY", assumes,
                         FastBlockModel::constants(), prove_lane_budget<FastBlockModel>);
  status |= run_proof("fast/block_classify (equivalence)", "FAST.TILE.CLASSIFY", assumes,
                      FastBlockModel::constants(), prove_lane_equivalence<FastBlockModel>);
  status |= run_proof("fast/block_classify (classification)", "FAST.TILE.CLASSIFY", assumes,
                      FastBlockModel::constants(), prove_tile_classify<FastBlockModel>);
  return status;
}
