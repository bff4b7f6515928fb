// SPDX-License-Identifier: MIT
// Properties: the kernel's coverage equals the exact oracle's, on whole scenes (every pixel
// centre of the target) and on samples placed exactly on vertices and edges.
// Implements (properties for): TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
//   TRI.CULL.MODE, TRI.DEGENERATE.ZERO_AREA, SNAP.CULL.AFTER_SNAP, RASTER.TARGET.CLIP

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/compare.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;
using RawTri64 = std::array<std::array<std::int64_t, 2>, 3>;

// Returns whether sample s lies on the closed segment (a, b), exactly (int64 is enough for
// 16.8 coordinates: products stay below 2^50).
bool on_segment(const std::array<std::int64_t, 2>& a, const std::array<std::int64_t, 2>& b,
                const std::array<std::int64_t, 2>& s) {
  const std::int64_t c = (b[0] - a[0]) * (s[1] - a[1]) - (b[1] - a[1]) * (s[0] - a[0]);
  return c == 0 && std::min(a[0], b[0]) <= s[0] && s[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= s[1] && s[1] <= std::max(a[1], b[1]);
}

// Tags the tie classes the scene actually hits at pixel centres of its target, after
// snapping: a centre exactly on an edge, a centre exactly on a vertex.
void tag_ties(const gen::TriScene& s) {
  bool on_edge = false, on_vertex = false, snapped_tie = false;
  for (const gen::GenTriangle& t : s.triangles) {
    RawTri64 r{};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 2; ++k) {
        r[i][k] = rastrules::oracle::snap(t.v[i][k]).value_or(0);
        // v * 256 half-way between two integers: v * 512 is an odd integer (exact in double).
        const double twice = static_cast<double>(t.v[i][k]) * 512.0;
        snapped_tie = snapped_tie || (twice == std::floor(twice) && std::fmod(twice, 2.0) != 0.0);
      }
    }
    for (std::int64_t y = 0; y < s.height; ++y) {
      for (std::int64_t x = 0; x < s.width; ++x) {
        const std::array<std::int64_t, 2> c{256 * x + 128, 256 * y + 128};
        for (std::size_t i = 0; i < 3; ++i) {
          on_vertex = on_vertex || r[i] == c;
          on_edge = on_edge || on_segment(r[i], r[(i + 1) % 3], c);
        }
      }
    }
  }
  RC_CLASSIFY(on_edge, "pixel centre on an edge");
  RC_CLASSIFY(on_vertex, "pixel centre on a vertex");
  RC_CLASSIFY(snapped_tie, "snapping tie");
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION, TRI.CULL.MODE
RC_GTEST_PROP(TriCover, KernelRenderEqualsOracleRender, ()) {
  const gen::TriScene s = *gen::tri_scene(32, 8);
  tag_ties(s);
  const auto k = rastrules::render(gen::to_kernel_scene(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&k)) {
    RC_FAIL("kernel rejected a valid scene: " + err->what());
  }
  const std::vector<rastrules::oracle::Fragment> o =
      rastrules::oracle::render(gen::to_oracle_scene(s));
  const std::string diff =
      gen::describe_difference(std::get<std::vector<rastrules::Fragment>>(k), o);
  if (!diff.empty())
    RC_FAIL(diff);
}

// Samples that sit on the tie: the vertices, raw lattice points on each edge, and the raw
// points next to those (one unit away in x or y, on either side of the edge).
std::vector<gen::RawPoint> tie_samples(const gen::RawTriangle& t) {
  std::vector<gen::RawPoint> out;
  const auto add_with_neighbours = [&out](const gen::RawPoint& p) {
    out.push_back(p);
    for (const auto& d : {std::array<std::int32_t, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const std::int64_t x = std::int64_t{p[0]} + d[0], y = std::int64_t{p[1]} + d[1];
      if (x >= rastrules::kMinVertexRaw && x <= rastrules::kMaxVertexRaw &&
          y >= rastrules::kMinVertexRaw && y <= rastrules::kMaxVertexRaw) {
        out.push_back({static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)});
      }
    }
  };
  for (std::size_t i = 0; i < 3; ++i) {
    add_with_neighbours(t[i]);
    for (const gen::RawPoint& p : gen::points_on_open_segment(t[i], t[(i + 1) % 3], 6)) {
      add_with_neighbours(p);
    }
  }
  return out;
}

// rule: TRI.FILL.TOP_LEFT, TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.CONVENTION, TRI.CULL.MODE
RC_GTEST_PROP(TriFill, CoversEqualsOracleOnVerticesEdgesAndTheirNeighbours, ()) {
  const rastrules::RasterState state = *gen::raster_state();
  const gen::RawTriangle t = *rc::gen::weightedOneOf<gen::RawTriangle>({
      {4, gen::nondegenerate_raw_triangle_near(16, 16)},
      {1, gen::raw_triangle_near(16, 16)},
  });
  const rastrules::TriangleSetup k = rastrules::setup_triangle(gen::to_vec2(t), state);
  const rastrules::oracle::State os = gen::to_oracle_state(state);
  const RawTri64 r = gen::to_oracle_raw(t);
  RC_TAG(std::string(to_string(k.status)));
  std::size_t on_boundary = 0;
  for (const gen::RawPoint& p : tie_samples(t)) {
    const bool kc = rastrules::covers(k, gen::to_vec2(p));
    const bool oc = rastrules::oracle::covers(r, {p[0], p[1]}, os);
    if (kc != oc) {
      std::ostringstream msg;
      msg << "sample (" << p[0] << ", " << p[1] << ") raw: kernel " << kc << ", oracle " << oc;
      RC_FAIL(msg.str());
    }
    for (std::size_t i = 0; i < 3; ++i) {
      on_boundary += on_segment(r[i], r[(i + 1) % 3], {p[0], p[1]}) ? 1u : 0u;
    }
  }
  RC_CLASSIFY(on_boundary > 3, "samples on edges besides the vertices");
}

} // namespace
