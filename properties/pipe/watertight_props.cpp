// SPDX-License-Identifier: MIT
// Property: a clip-space mesh (a grid of triangles sharing edges, consistently wound) that
// crosses the near plane z = 0, the far plane, the w plane (vertices behind the eye) and the
// guard band is drawn by run_pipeline with every sample covered at most once, and exactly once
// inside the mesh's exactly clipped screen image: the oracle clips every triangle exactly,
// projects it exactly, and tags each edge of the result as lying on a clip plane, on an outer
// edge of the mesh or on an edge two triangles share. A sample farther than 1/32 px from every
// plane and outer edge is inside the image (covered exactly once) when it lies inside some
// triangle's polygon or near a shared edge, and outside it (covered never) otherwise; samples
// near the image's boundary are only required to be covered at most once. Shared edges are
// where clipping could crack a mesh (PIPE.CLIP.POLYGON computes intersections from the inside
// endpoint so that both triangles make the same vertex).
// Implements (properties for): PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.VOLUME

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"
#include "pipe_scene.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace ps = rastrules::pipe_scene;
namespace op = rastrules::oracle::pipe;
namespace om = rastrules::oracle::msaa;
namespace kp = rastrules::pipe;

// Samples within this distance (raw units) of the image's boundary may go either way.
constexpr std::int64_t kNearRaw = 8; // 1/32 px

struct ClipMesh {
  std::int32_t width = 0, height = 0;
  std::uint32_t samples = 1;
  std::vector<kp::Vec4f> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
};

void showValue(const ClipMesh& m, std::ostream& os) {
  os << "target " << m.width << "x" << m.height << ", " << m.samples << " samples\n";
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    os << "  v" << i << " " << pg::fs(m.vertices[i]) << "\n";
  for (const auto& t : m.triangles)
    os << "  tri " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

// NDC coordinates of the grid lines: near the view, or far outside the guard band.
rc::Gen<std::vector<float>> grid_lines(std::size_t n) {
  return rc::gen::exec([n] {
    std::vector<float> u;
    for (std::size_t i = 0; i < n; ++i) {
      if (*rc::gen::inRange(0, 6) == 0) {
        u.push_back(std::ldexp(static_cast<float>(*rc::gen::inRange(1024, 2048)) / 1024.0f,
                               *rc::gen::inRange(11, 17)) *
                    (*rc::gen::arbitrary<bool>() ? 1.0f : -1.0f));
      } else {
        u.push_back(static_cast<float>(*rc::gen::inRange(-448, 449)) / 256.0f);
      }
    }
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end()), u.end());
    RC_PRE(u.size() == n);
    return u;
  });
}

// Two kinds of mesh, neither folding over itself on screen (so that no sample is legitimately
// covered twice): (1) a grid whose vertices project to the NDC grid lines u_i x v_j with a
// random w > 0 per vertex and z/w = a + b s + c t (+ jitter) crossing the near and far planes;
// (2) a plane in view space, Zv = alpha + beta X + gamma Y, through a perspective projection
// (x, y, z, w) = (X, Y, (Zv - n) F / (F - n), Zv), part of it behind the eye (w < 0, clipped at
// the w plane, then at the near plane) and near its horizon (across the guard band).
rc::Gen<ClipMesh> clip_mesh() {
  return rc::gen::exec([] {
    ClipMesh m;
    m.width = *rc::gen::inRange(4, 17);
    m.height = *rc::gen::inRange(4, 17);
    m.samples = *rc::gen::element(1u, 4u);
    const std::size_t nx = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
    const std::size_t ny = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
    if (*rc::gen::inRange(0, 3) != 0) {
      const std::vector<float> u = *grid_lines(nx + 1), v = *grid_lines(ny + 1);
      const float a = static_cast<float>(*rc::gen::inRange(-128, 256)) / 256.0f;
      const float b = static_cast<float>(*rc::gen::inRange(-256, 257)) / 256.0f;
      const float c = static_cast<float>(*rc::gen::inRange(-256, 257)) / 256.0f;
      for (std::size_t j = 0; j <= ny; ++j) {
        for (std::size_t i = 0; i <= nx; ++i) {
          const float w = *rc::gen::element(1.0f, 0.5f, 2.0f, 4.0f, 0.25f, 1.5f);
          const float s = static_cast<float>(i) / static_cast<float>(nx);
          const float t = static_cast<float>(j) / static_cast<float>(ny);
          const float zn =
              a + b * s + c * t + static_cast<float>(*rc::gen::inRange(-8, 9)) / 256.0f;
          m.vertices.push_back(kp::Vec4f{u[i] * w, v[j] * w, zn * w, w});
        }
      }
    } else {
      const auto coord = [] { return static_cast<float>(*rc::gen::inRange(-1024, 1025)) / 256.0f; };
      std::vector<float> xs, ys;
      for (std::size_t i = 0; i <= nx; ++i)
        xs.push_back(coord());
      for (std::size_t j = 0; j <= ny; ++j)
        ys.push_back(coord());
      std::sort(xs.begin(), xs.end());
      std::sort(ys.begin(), ys.end());
      RC_PRE(std::adjacent_find(xs.begin(), xs.end()) == xs.end());
      RC_PRE(std::adjacent_find(ys.begin(), ys.end()) == ys.end());
      const float alpha = static_cast<float>(*rc::gen::inRange(64, 1281)) / 256.0f;
      const float beta = static_cast<float>(*rc::gen::inRange(-512, 513)) / 256.0f;
      const float gamma = static_cast<float>(*rc::gen::inRange(-512, 513)) / 256.0f;
      const float near = *rc::gen::element(0.125f, 0.5f, 0.0625f), far = 100.0f;
      const float zscale = far / (far - near);
      for (std::size_t j = 0; j <= ny; ++j) {
        for (std::size_t i = 0; i <= nx; ++i) {
          const float zv = alpha + beta * xs[i] + gamma * ys[j];
          m.vertices.push_back(kp::Vec4f{xs[i], ys[j], (zv - near) * zscale, zv});
        }
      }
    }
    const auto id = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t p00 = id(i, j), p10 = id(i + 1, j), p01 = id(i, j + 1),
                          p11 = id(i + 1, j + 1);
        if (*rc::gen::arbitrary<bool>()) {
          m.triangles.push_back({p00, p10, p11});
          m.triangles.push_back({p00, p11, p01});
        } else {
          m.triangles.push_back({p00, p10, p01});
          m.triangles.push_back({p10, p11, p01});
        }
      }
    }
    return m;
  });
}

// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.VOLUME
RC_GTEST_PROP(PipeWatertight, ClippedMeshCoversEachSampleOnceInsideItsImage, ()) {
  const ClipMesh m = *pg::full_size(clip_mesh());
  rastrules::Scene s;
  s.width = m.width;
  s.height = m.height;
  set_sample_pattern(s, rastrules::standard_pattern(m.samples));
  for (const auto& t : m.triangles) {
    rastrules::Primitive p;
    p.pos = {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    s.primitives.push_back(p);
  }
  const auto res = kp::run_pipeline(s);
  if (const auto* e = std::get_if<rastrules::SceneError>(&res))
    RC_FAIL("rejected: " + e->what());
  const kp::PipeResult& r = std::get<kp::PipeResult>(res);
  // Coverage count per sample.
  const std::size_t n = m.samples;
  std::vector<int> count(static_cast<std::size_t>(m.width * m.height) * n, 0);
  std::vector<std::uint32_t> who(count.size(), 0);
  for (const rastrules::Fragment& f : r.fragments) {
    for (std::size_t k = 0; k < n; ++k) {
      if ((f.mask & (1u << k)) == 0)
        continue;
      const std::size_t idx = (static_cast<std::size_t>(f.y * m.width + f.x)) * n + k;
      ++count[idx];
      who[idx] = f.prim;
    }
  }
  // The exact image: each triangle's exactly clipped polygon, edges tagged. An edge of the
  // mesh is inside the image when the polygons of both its triangles keep a piece of it.
  const op::Viewport vp = ps::viewport_of(s);
  struct Poly {
    op::ExactRegion region;
    std::vector<std::pair<std::size_t, std::size_t>> mesh_edge; // per edge; (0, 0) on a plane
    std::vector<bool> boundary;
    std::array<std::int64_t, 4> box;
  };
  std::vector<Poly> polys;
  std::map<std::pair<std::size_t, std::size_t>, int> kept;
  bool clipped = false;
  for (const auto& t : m.triangles) {
    const std::array<kp::Vec4f, 3> tri{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    const op::Volume vol = op::clip_volume({tri[0], tri[1], tri[2]}, vp, true);
    op::ExactRegion region = op::ExactRegion::clipped_polygon(tri, vol, vp);
    if (region.size() < 3) {
      clipped = true;
      continue;
    }
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    std::map<std::pair<std::size_t, std::size_t>, bool> seen;
    for (const int o : region.edge_origins()) {
      if (o < 0) {
        clipped = true;
        edges.emplace_back(0, 0);
        continue;
      }
      const auto k = static_cast<std::size_t>(o);
      edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
      if (!seen[edges.back()])
        ++kept[edges.back()];
      seen[edges.back()] = true;
    }
    const auto box = region.bounds_raw();
    polys.push_back(Poly{std::move(region), std::move(edges), {}, box});
  }
  const std::pair<std::size_t, std::size_t> plane{0, 0};
  bool cut_shared = false; // a plane cuts an edge two triangles share: where cracks would be
  for (Poly& p : polys) {
    const std::size_t ne = p.mesh_edge.size();
    for (std::size_t e = 0; e < ne; ++e) {
      const auto& me = p.mesh_edge[e];
      p.boundary.push_back(me == plane || kept[me] < 2);
      if (me != plane && kept[me] >= 2 &&
          (p.mesh_edge[(e + 1) % ne] == plane || p.mesh_edge[(e + ne - 1) % ne] == plane))
        cut_shared = true;
    }
  }
  const std::vector<om::Offset> pattern = om::standard_pattern(m.samples);
  int inside = 0, near = 0, shared = 0;
  for (std::int32_t y = 0; y < m.height; ++y) {
    for (std::int32_t x = 0; x < m.width; ++x) {
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t idx = (static_cast<std::size_t>(y * m.width + x)) * n + k;
        const op::Raw2 smp = ps::offset_raw(x, y, pattern[k]);
        const std::string at = "sample " + std::to_string(k) + " of pixel (" + std::to_string(x) +
                               ", " + std::to_string(y) + ") at raw " + pg::rs(smp);
        if (count[idx] > 1)
          RC_FAIL(at + " covered " + std::to_string(count[idx]) + " times");
        bool near_boundary = false, in_image = false, near_shared = false;
        for (const Poly& p : polys) {
          if (smp[0] < p.box[0] - kNearRaw || smp[0] > p.box[2] + kNearRaw ||
              smp[1] < p.box[1] - kNearRaw || smp[1] > p.box[3] + kNearRaw)
            continue;
          for (std::size_t e = 0; e < p.boundary.size(); ++e) {
            if (!p.region.near_edge(smp, kNearRaw, e))
              continue;
            if (p.boundary[e])
              near_boundary = true;
            else
              in_image = near_shared = true; // near a shared edge, away from the boundary
          }
          if (p.region.strictly_inside(smp))
            in_image = true;
        }
        if (near_boundary) {
          ++near;
          continue;
        }
        inside += in_image ? 1 : 0;
        shared += near_shared ? 1 : 0;
        const int want = in_image ? 1 : 0;
        if (count[idx] != want)
          RC_FAIL(at + (in_image ? " inside" : " outside") +
                  " the mesh's exact image (farther than "
                  "1/32 px from its boundary) but covered " +
                  std::to_string(count[idx]) + " times" +
                  (count[idx] ? " (by triangle " + std::to_string(who[idx]) + ")" : ""));
      }
    }
  }
  RC_CLASSIFY(clipped, "clipped");
  RC_CLASSIFY(inside > 0, "samples inside the image");
  RC_CLASSIFY(near > 0, "samples near the boundary");
  RC_CLASSIFY(cut_shared && shared > 0, "samples near shared edges cut by a plane");
}

} // namespace
