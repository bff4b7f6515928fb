// SPDX-License-Identifier: MIT
// Helpers of the fast traversal's examples: the instruction sets this processor runs, and the
// fast and plain walks collected as lists.

#pragma once

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "rastrules/isa.hpp"
#include "rastrules/raster/fast.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/raster/walk_msaa.hpp"
#include "support.hpp"

namespace rastrules::test {

inline constexpr Isa kAllIsas[] = {Isa::kScalar, Isa::kAvx2, Isa::kAvx512};

// The instruction sets this build and processor run (FAST.ISA.DISPATCH); scalar always.
inline std::vector<Isa> supported_isas() {
  std::vector<Isa> out;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa))
      out.push_back(isa);
  return out;
}

inline std::vector<Pixel> fast_pixels(const TriangleSetup& t, std::int32_t w, std::int32_t h,
                                      Isa isa) {
  std::vector<Pixel> out;
  raster::walk_triangle_fast(t, w, h, isa, [&](std::int32_t x, std::int32_t y) {
    out.push_back(Pixel{x, y});
  });
  return out;
}

using MaskedPixel = std::tuple<std::int32_t, std::int32_t, std::uint32_t>; // y, x, mask

inline std::vector<MaskedPixel> plain_samples(const TriangleSetup& t, const SamplePattern& p,
                                              std::int32_t w, std::int32_t h) {
  std::vector<MaskedPixel> out;
  raster::walk_triangle_samples(t, p, w, h, [&](std::int32_t x, std::int32_t y, std::uint32_t m) {
    out.emplace_back(y, x, m);
  });
  return out;
}

inline std::vector<MaskedPixel> fast_samples(const TriangleSetup& t, const SamplePattern& p,
                                             std::int32_t w, std::int32_t h, Isa isa) {
  std::vector<MaskedPixel> out;
  raster::walk_triangle_samples_fast(
      t, p, w, h, isa,
      [&](std::int32_t x, std::int32_t y, std::uint32_t m) { out.emplace_back(y, x, m); });
  return out;
}

inline std::string isa_name(Isa isa) {
  return std::string(to_string(isa));
}

} // namespace rastrules::test
