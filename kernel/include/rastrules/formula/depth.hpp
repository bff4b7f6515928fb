// SPDX-License-Identifier: MIT
// The UNORM depth conversion (PIPE.DEPTH.FORMAT), generic over the floating-point type Real so
// that the same source is evaluated in double by the kernel (compiled with -ffp-contract=off)
// and on Z3's IEEE-754 terms by the proofs (proofs/pipe/depth_format.cpp).
// Implements: PIPE.DEPTH.FORMAT (d16, d24)

#pragma once

#include <cstdint>

namespace rastrules::formula {

// The bits of the UNORM depth formats.
inline constexpr int kDepthD16Bits = 16;
inline constexpr int kDepthD24Bits = 24;

// Returns the largest stored value of an n-bit UNORM format, 2^n - 1 (d16: 65535,
// d24: 16777215), which stands for depth 1.0.
constexpr std::uint32_t unorm_max(int bits) {
  return (std::uint32_t{1} << bits) - std::uint32_t{1};
}

// Returns z * max + 0.5 evaluated in Real ("+0.5 and truncate"): the stored value of a clamped
// depth z in [0, 1] is floor(unorm_rounding_argument(z, Real(unorm_max(n)))), which lies in
// [0, max] and equals the spec's floor(fl64(z * max) + 0.5) with the exact + 0.5 (proved for
// d16 and d24 in proofs/pipe/depth_format.cpp).
// rule: PIPE.DEPTH.FORMAT
template <class Real> constexpr Real unorm_rounding_argument(Real z, Real max) {
  return z * max + Real(0.5);
}

} // namespace rastrules::formula
