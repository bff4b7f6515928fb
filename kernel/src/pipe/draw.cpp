// SPDX-License-Identifier: MIT
// Stage 5 of run_pipeline: every drawn primitive (a triangle, point or line, or one segment of
// a strip) with what shading reads: its snapped vertices, window depths after the depth bias,
// clip w, attribute values, flat values and the conservative depth bounds of Hi-Z.
// Implements: PIPE.DEPTH.BIAS, PIPE.OPT.HIZ, PIPE.BARY.LINE, PIPE.INTERP.FLAT
#include <algorithm>
#include <cmath>
#include <limits>

#include "stages.hpp"

namespace rastrules::pipe::detail {

namespace {

// Drawn primitive `segment` of coverage primitive p.
Drawn draw_one(const Scene& s, const PreparedPrimitive& pr, const Source& src, std::size_t segment,
               const Viewport& vp) {
  const DepthFormat fmt = s.depth ? s.conventions.depth : DepthFormat::kD24;
  Drawn d;
  const bool strip = pr.type == PrimitiveType::kLineStrip;
  d.type = strip ? PrimitiveType::kLine : pr.type;
  const std::size_t first = strip ? segment : 0; // the segment's first vertex
  const std::size_t nv = strip ? 2 : std::min<std::size_t>(src.v.size(), 3);
  if (strip)
    d.v = {pr.v[segment], pr.v[segment + 1]};
  else
    d.v = pr.v;
  for (std::size_t j = 0; j < nv; ++j) {
    d.z[j] = src.v[first + j].z;
    d.w[j] = src.v[first + j].w;
  }
  // rule: PIPE.DEPTH.BIAS
  if (s.depth && pr.type == PrimitiveType::kTriangle && s.depth->bias.enabled()) {
    const float b = depth_bias({pr.v[0], pr.v[1], pr.v[2]}, d.z, s.depth->bias, fmt);
    for (float& zi : d.z) {
      zi = zi + b;
      if (std::isinf(zi)) // saturates like every float32 step of the bias (PIPE.DEPTH.BIAS)
        zi = std::copysign(std::numeric_limits<float>::max(), zi);
    }
  }
  for (std::size_t a = 0; a < s.attributes.size(); ++a) {
    std::array<float, 3> v{};
    for (std::size_t j = 0; j < nv; ++j)
      v[j] = src.attr[first + j][a];
    d.a.push_back(v);
  }
  // rule: PIPE.OPT.HIZ
  // A covered sample of a triangle is a convex combination of its vertices, so its depth lies
  // in [min Zi, max Zi] up to the rounding of PIPE.DEPTH.INTERP (relative 2^-50 of the largest
  // |Zi|); the monotone conversion keeps the bounds. Lines extrapolate at their ends: none.
  if (s.depth && (pr.type == PrimitiveType::kTriangle || pr.type == PrimitiveType::kPoint)) {
    const std::size_t k = pr.type == PrimitiveType::kPoint ? 1 : 3;
    double zlo = d.z[0], zhi = d.z[0], zabs = 0.0;
    for (std::size_t j = 0; j < k; ++j) {
      zlo = std::min(zlo, static_cast<double>(d.z[j]));
      zhi = std::max(zhi, static_cast<double>(d.z[j]));
      zabs = std::max(zabs, std::fabs(static_cast<double>(d.z[j])));
    }
    const double margin = std::ldexp(zabs, -46) + std::ldexp(1.0, -1000);
    d.lo = to_depth_format(zlo - margin, vp.min_depth, vp.max_depth, fmt);
    d.hi = to_depth_format(zhi + margin, vp.min_depth, vp.max_depth, fmt);
    d.bounded = true;
  }
  return d;
}

} // namespace

std::vector<Drawn> draw(const Scene& s, const PreparedScene& ps, const std::vector<Source>& sources,
                        const Links& links, const Viewport& vp, std::vector<DrawnPrimitive>& out) {
  std::vector<Drawn> drawn;
  drawn.reserve(links.first_drawn.back());
  out.reserve(links.first_drawn.back());
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    const Source& src = sources[p];
    const bool strip = ps.primitives[p].type == PrimitiveType::kLineStrip;
    for (std::size_t k = 0; k < src.flat.size(); ++k) {
      drawn.push_back(draw_one(s, ps.primitives[p], src, k, vp));
      const Drawn& d = drawn.back();
      out.push_back(DrawnPrimitive{
          d.type, static_cast<std::uint32_t>(src.prim), src.part,
          strip ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(k)) : std::nullopt, d.v,
          d.z, d.w, d.a, src.flat[k]});
    }
  }
  return drawn;
}

} // namespace rastrules::pipe::detail
