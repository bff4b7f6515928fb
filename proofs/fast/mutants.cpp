// SPDX-License-Identifier: MIT
// Self-check: the fast-traversal obligations can fail. Runs prove_lane_budget,
// prove_lane_equivalence, prove_tile_classify, and the batch unit's prove_batch_small_i32,
// prove_lane_bits and prove_batch_snap_simd against deliberately broken models, each
// derived from FastKernelModel with one member replaced, and passes only if every mutant is
// REFUTED (with a counterexample). A mutant that survives means the proof cannot see that kind
// of bug.
// Cites no rule: it is evidence about the proofs, not about the kernel.
// Assumes: SNAP.VERTEX.RANGE (as the obligations do)
// Expected: every mutant REFUTED; exit status 0 iff so.

#include "fast/batch_proofs.hpp"
#include "fast/fast_proofs.hpp"
#include "support/mutation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {
namespace {

// Tiles of 64 x 64 pixels with the same lane bound: 63 (|A| + |B|) reaches 2^31, so L leaves
// int32_t and |L| < 2^30 fails.
struct Tile64 : FastKernelModel {
  static constexpr const char* kName = "tile 64 x 64 with kLaneBound 2^30";
  static constexpr std::int64_t kTile = 64;
};

// Coordinates one bit wider than SNAP.VERTEX.RANGE ([-2^24, 2^24)) with 32 x 32 tiles: 31 (|A|
// + |B|) reaches 2^31.
struct WideCoordsTile32 : FastKernelModel {
  static constexpr const char* kName = "coordinates in [-2^24, 2^24) with tile 32 x 32";
  static constexpr std::int64_t kMinRaw = 2 * std::int64_t{kMinVertexRaw};
  static constexpr std::int64_t kMaxRaw = 2 * (std::int64_t{kMaxVertexRaw} + 1) - 1;
  static constexpr std::int64_t kTile = 32;
};

// Lanes of 16 bits: A alone does not fit.
struct Int16Lanes : FastKernelModel {
  static constexpr const char* kName = "int16_t lanes";
  using Lane = Sym<std::int16_t>;
};

// The threshold clamped to [-2^20, 2^20]: a lane offset above 2^20 passes a threshold that
// was clamped down from a larger -q.
struct Clamp20 : FastKernelModel {
  static constexpr const char* kName = "threshold clamp bound 2^20";
  static constexpr std::int64_t kBound = std::int64_t{1} << 20;
};

// q one too large: q = floor((E0 + bias) / 256) + 1.
struct QOffByOne : FastKernelModel {
  static constexpr const char* kName = "q = floor((E0 + bias) / 256) + 1";
  static z3::expr shift_characterisation(const z3::expr& e_biased, const z3::expr& q,
                                         const z3::expr& r) {
    z3::context& ctx = q.ctx();
    const z3::expr d = ctx.int_val(kDivisor);
    return e_biased == d * (q - 1) + r && 0 <= r && r < d;
  }
};

// The shift by 7 bits instead of kSubpixelBits: q = floor((E0 + bias) / 128).
struct Shift7 : FastKernelModel {
  static constexpr const char* kName = "q = (E0 + bias) >> 7";
  static z3::expr shift_characterisation(const z3::expr& e_biased, const z3::expr& q,
                                         const z3::expr& r) {
    z3::context& ctx = q.ctx();
    const z3::expr d = ctx.int_val(kDivisor / 2);
    return e_biased == d * q + r && 0 <= r && r < d;
  }
};

// The bias forgotten (0 for every edge): a sample exactly on a non-inclusive edge is inside.
struct BiasDropped : FastKernelModel {
  static constexpr const char* kName = "edge_bias always 0";
  template <class S> static S edge_bias(bool) { return S(0); }
};

// lane_max taking the corner of min(B, 0) instead of max(B, 0): a tile is rejected although a
// lane in its other row is inside.
struct LaneMaxWrongCorner : FastKernelModel {
  static constexpr const char* kName = "lane_max uses min(B, 0)";
  template <class L> static L lane_max(const L& a, const L& b, const L& last) {
    const L zero(0);
    return select(a > zero, a, zero) * last + select(b < zero, b, zero) * last;
  }
};

// lane_min over lanes 0 .. kTile - 2 (one lane short): a tile is accepted although its last
// row or column has a lane outside.
struct LaneMinShort : FastKernelModel {
  static constexpr const char* kName = "lane_min over kTile - 1 lanes";
  template <class L> static L lane_min(const L& a, const L& b, const L& last) {
    return formula::lane_min<L>(a, b, last - L(1), SymSelect{});
  }
};

// The batch unit's small triangles twice as wide (spans below 128 px): lane values reach 2^30
// (and rows exceed 64 pixels, differences 2^14, the area 2^29).
struct BatchSpanTwice : BatchKernelModel {
  static constexpr const char* kName = "small span twice kBatchSmallSpan";
  static constexpr std::int64_t kSpan = 2 * BatchKernelModel::kSpan;
};

// The rule's lane magnitude one bit tighter (2^29): the lanes' reach gives values above it, so
// the 2^30 budget is checked, not vacuous.
struct BatchLaneBits29 : BatchKernelModel {
  static constexpr const char* kName = "lane values claimed below 2^29";
  static constexpr int kLaneBits = 29;
};

// cover_one (two halves of eight lanes) taken for rows of up to 24 pixels: pixels 16..23 are
// never tested.
struct BatchOneUpTo24 : BatchKernelModel {
  static constexpr const char* kName = "cover_one for rows of up to 24 px";
  static constexpr std::int64_t kOneMaxCols = 24;
};

// The pixel bounds shifted by 7 bits: px0..px1 are not the pixels whose centres lie in the box.
struct BatchShift7 : BatchKernelModel {
  static constexpr const char* kName = "pixel bounds >> 7";
  static constexpr int kShift = kSubpixelBits - 1;
};

// A positive poison (+2^30): a dead lane passes the sign test when the other edges do.
struct BatchPoisonPositive : BatchKernelModel {
  static constexpr const char* kName = "poison +2^30";
  static constexpr std::int64_t kPoison = std::int64_t{1} << 30;
};

// The AVX-512 unit's tail counting lane m when m <= rest: one pixel past the row's end.
struct Lanes16TailPastEnd : BatchLanes16Model {
  static constexpr const char* kName = "cover16's tail mask one lane too wide";
  static z3::expr chunk_counted(const z3::expr& c, const z3::expr& full, const z3::expr& m,
                                const z3::expr& rest) {
    return c < full || (c == full && m <= rest);
  }
};

// Its step claimed below 2^25, as the AVX2 unit's 8 x 256 A: 16 x 256 A is not.
struct Lanes16StepBits25 : BatchLanes16Model {
  static constexpr const char* kName = "16 x 256 A claimed below 2^25";
  static constexpr int kStepBits = 25;
};

// Rounding v * 256 towards zero instead of to nearest even (_MM_FROUND_TO_ZERO).
struct SnapRoundTowardZero : SnapKernelModel {
  static constexpr const char* kName = "roundToIntegral towards zero";
  static z3::expr round_mode(z3::context& ctx) { return z3::expr(ctx, Z3_mk_fpa_rtz(ctx)); }
};

// The accepted interval one unit wider at the top: 2^23 is accepted, the kernel rejects it.
struct SnapHighestTooLarge : SnapKernelModel {
  static constexpr const char* kName = "accepts r <= 2^23";
  static constexpr float kHighest = static_cast<float>(std::int64_t{kMaxVertexRaw} + 1);
};

// The scale 128 (kSubpixelBits - 1): the lane snaps to 1/128 px.
struct SnapScale128 : SnapKernelModel {
  static constexpr const char* kName = "scale 128.0f";
  static constexpr float kScale = static_cast<float>(kSubpixelOne / 2);
};

} // namespace

MutationSelfcheck mutation_selfcheck() {
  return {"fast",
          {refute<Tile64>(kLaneBudget),
           // The same tile size breaks the decision too: some |L| exceeds the clamp bound.
           refute<Tile64>(kLaneEquivalence), refute<WideCoordsTile32, Int16Lanes>(kLaneBudget),
           refute<Clamp20, QOffByOne, Shift7, BiasDropped>(kLaneEquivalence),
           refute<LaneMaxWrongCorner, LaneMinShort>(kTileClassify),
           refute<BatchSpanTwice, BatchLaneBits29, BatchOneUpTo24, BatchShift7>(kBatchSmallI32),
           refute<BatchPoisonPositive>(kLaneBits),
           refute<Lanes16TailPastEnd, Lanes16StepBits25>(kBatchSmallI32),
           refute<SnapRoundTowardZero, SnapHighestTooLarge, SnapScale128>(kBatchSnapSimd)},
          FastKernelModel::constants(),
          {"SNAP.VERTEX.RANGE"}};
}

} // namespace rastrules::proofs
