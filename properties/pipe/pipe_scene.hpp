// SPDX-License-Identifier: MIT
// Whole pipeline scenes for the properties: printing a scene so that a counterexample can be
// rebuilt, the oracle's viewport of a scene and raw sample positions from the oracle's pattern
// tables. The check of run_pipeline's fragments against the oracle is check::check_pipeline
// (check/), the one kernel-against-oracle checker.

#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "pipe_gen.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::pipe_scene {

namespace op = rastrules::oracle::pipe;
namespace om = rastrules::oracle::msaa;
namespace kp = rastrules::pipe;
namespace pg = rastrules::pipe_gen;
using Raw2 = op::Raw2;

// ---------------------------------------------------------------------------------------------
// Printing

inline std::string interpolation_name(kp::Interpolation i) {
  switch (i) {
  case kp::Interpolation::kPerspective:
    return "perspective";
  case kp::Interpolation::kLinear:
    return "linear";
  case kp::Interpolation::kFlat:
    return "flat";
  }
  return "?";
}
inline std::string location_name(kp::Location l) {
  switch (l) {
  case kp::Location::kCenter:
    return "center";
  case kp::Location::kCentroid:
    return "centroid";
  case kp::Location::kSample:
    return "sample";
  }
  return "?";
}
inline std::string cull_name(CullMode c) {
  return c == CullMode::kNone ? "none" : (c == CullMode::kBack ? "back" : "front");
}

inline void show(const rastrules::Scene& s, std::ostream& os) {
  const Scene& b = s;
  os << "scene: target " << b.width << "x" << b.height << ", cull " << cull_name(b.cull)
     << ", front " << (b.conventions.front_face == FrontFace::kClockwise ? "cw" : "ccw")
     << ", fill " << static_cast<int>(b.conventions.fill) << ", samples " << b.msaa.count()
     << ", shading " << (b.msaa.shading == ShadingRate::kSample ? "sample" : "pixel")
     << ", centroid rule " << (b.conventions.centroid == CentroidRule::kD3D11 ? "d3d11" : "d3d10")
     << ", provoking " << (s.conventions.provoking == kp::Provoking::kFirst ? "first" : "last")
     << ", line mode " << to_string(b.conventions.line_mode) << ", sample mask "
     << b.msaa.sample_mask << ", quads " << (b.msaa.quads ? "on" : "off") << ", derivatives "
     << to_string(b.msaa.derivatives) << "\n";
  if (s.viewport) {
    os << "  viewport ";
    kp::showValue(*s.viewport, os);
    os << "\n";
  }
  const auto mat = [&](const char* name, const std::optional<kp::Mat4f>& m) {
    if (m)
      os << "  " << name << " " << pg::fs(*m) << "\n";
  };
  mat("model", s.model);
  mat("view", s.view);
  mat("projection", s.projection);
  if (s.depth) {
    const kp::DepthState& d = *s.depth;
    os << "  depth " << pg::depth_format_name(s.conventions.depth) << " "
       << pg::compare_name(d.func) << (d.write ? " write" : " no-write") << " clear "
       << pg::fs(d.clear) << (d.clip ? " clip" : " no-clip") << "\n";
  }
  for (const kp::AttributeDecl& a : s.attributes)
    os << "  attribute " << a.name << " " << interpolation_name(a.interpolation) << " "
       << location_name(a.location) << "\n";
  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    const rastrules::Primitive& p = s.primitives[i];
    os << "  prim " << i << " " << to_string(p.type) << (p.aa ? " aa" : "") << ":";
    if (!p.pos.empty()) {
      for (const kp::Vec4f& v : p.pos)
        os << " pos " << pg::fs(v);
    } else {
      for (const FloatPoint& v : p.v)
        os << " v " << pg::fs(v);
      if (!p.z.empty())
        os << " z " << pg::fs(p.z);
      if (!p.w.empty())
        os << " w " << pg::fs(p.w);
    }
    for (const auto& a : p.attr)
      os << " attr " << pg::fs(a);
    os << "\n";
  }
}
inline std::string show(const rastrules::Scene& s) {
  std::ostringstream os;
  show(s, os);
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// The oracle's viewport of a scene

inline op::Viewport viewport_of(const rastrules::Scene& s) {
  if (s.viewport)
    return pg::to_oracle(*s.viewport);
  return op::Viewport{0.0f, 0.0f, static_cast<float>(s.width), static_cast<float>(s.height),
                      0.0f, 1.0f};
}

// ---------------------------------------------------------------------------------------------
// Sample positions, from the oracle's pattern tables

inline Raw2 centre_raw(std::int32_t x, std::int32_t y) {
  return {256 * std::int64_t{x} + 128, 256 * std::int64_t{y} + 128};
}
inline Raw2 offset_raw(std::int32_t x, std::int32_t y, const om::Offset& o) {
  const Raw2 c = centre_raw(x, y);
  return {c[0] + 16 * std::int64_t{o.x}, c[1] + 16 * std::int64_t{o.y}};
}

} // namespace rastrules::pipe_scene
