// SPDX-License-Identifier: MIT
// The deliberately imprecise driver: independent, simple code with planted bugs.
// Implements: DRIVER.IMPRECISE, DRIVER.IMPRECISE.VALUES

#include "rastrules/driver/imprecise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "drivers.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::driver {
namespace {

struct RawPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
};

// rule: DRIVER.IMPRECISE
class ImpreciseDriver final : public Driver {
public:
  ImpreciseDriver(std::string name, ImpreciseBugs bugs) : bugs_(bugs) {
    info_.name = std::move(name);
    std::string what;
    if (bugs_.float_edges)
      what += " float32 edge functions with E >= 0;";
    if (bugs_.fill_bottom_right)
      what += " bottom-right fill convention;";
    if (bugs_.four_bit_subpixel)
      what += " 4 subpixel bits;";
    if (!what.empty())
      what.pop_back();
    info_.description = "built-in imprecise rasterizer (planted bugs:" + what + ")";
    info_.subpixel_bits = bugs_.four_bit_subpixel ? 4 : 8;
    info_.sample_counts = {1};
    info_.max_target_side = kMaxTargetSide;
  }

  [[nodiscard]] const DriverInfo& info() const override { return info_; }

  [[nodiscard]] std::string unsupported(const Scene& scene) const override {
    if (const auto field = first_pipeline_field(scene)) // rule: DRIVER.VALUES
      return "pipeline state (" + *field + ", SCENE.PIPELINE) not supported";
    if (scene.msaa.count() != 1)
      return std::to_string(scene.msaa.count()) + " samples not supported";
    if (scene.msaa.wants_quads() || scene.msaa.has_centroid)
      return "quads and centroids not supported";
    for (const Primitive& p : scene.primitives) {
      if (p.type != PrimitiveType::kTriangle) {
        return std::string(to_string(p.type)) + " primitives not supported (triangles only)";
      }
    }
    return {};
  }

  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    std::vector<Fragment> out;
    for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
      const Primitive& prim = scene.primitives[p];
      if (prim.type != PrimitiveType::kTriangle || prim.v.size() != 3) {
        return DriverError{"primitives[" + std::to_string(p) + "]: not a triangle"};
      }
      std::array<RawPoint, 3> v{};
      for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t k = 0; k < 2; ++k) {
          const auto raw = snap(prim.v[i][k]);
          if (!raw) {
            return DriverError{"primitives[" + std::to_string(p) + "].v[" + std::to_string(i) +
                               "][" + std::to_string(k) + "]: cannot be snapped"};
          }
          (k == 0 ? v[i].x : v[i].y) = *raw;
        }
      }
      draw_triangle(scene, static_cast<std::uint32_t>(p), v, out);
    }
    return out;
  }

private:
  // Rounds to the driver's subpixel grid (half to even, the default rounding mode), in raw
  // units of 1/256 px.
  [[nodiscard]] std::optional<std::int64_t> snap(float value) const {
    if (!std::isfinite(value))
      return std::nullopt;
    const int bits = bugs_.four_bit_subpixel ? 4 : kSubpixelBits;
    const double scaled = std::nearbyint(static_cast<double>(value) * std::ldexp(1.0, bits));
    const double raw = scaled * std::ldexp(1.0, kSubpixelBits - bits);
    if (raw < kMinVertexRaw || raw > kMaxVertexRaw)
      return std::nullopt;
    return static_cast<std::int64_t>(raw);
  }

  [[nodiscard]] static bool bottom_right_inclusive(RawPoint a, RawPoint b) {
    // Clockwise triangle, y down: a horizontal edge running in -x has the interior above it
    // (a bottom edge); a non-horizontal edge running down has the interior to its left.
    if (a.y == b.y)
      return b.x < a.x;
    return b.y > a.y;
  }

  [[nodiscard]] static bool scene_inclusive(RawPoint a, RawPoint b, FillConvention f) {
    const bool top_inclusive = f == FillConvention::kTopLeft || f == FillConvention::kTopRight;
    const bool left_inclusive = f == FillConvention::kTopLeft || f == FillConvention::kBottomLeft;
    if (a.y == b.y)
      return top_inclusive ? (b.x > a.x) : (b.x < a.x);
    return left_inclusive ? (b.y < a.y) : (b.y > a.y);
  }

  void draw_triangle(const Scene& scene, std::uint32_t prim, std::array<RawPoint, 3> v,
                     std::vector<Fragment>& out) const {
    const std::int64_t area =
        (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (area == 0)
      return;
    const bool clockwise = area > 0;
    const bool front = (scene.conventions.front_face == FrontFace::kClockwise) == clockwise;
    if (scene.cull == CullMode::kBack && !front)
      return;
    if (scene.cull == CullMode::kFront && front)
      return;
    if (!clockwise)
      std::swap(v[1], v[2]);
    std::array<bool, 3> inclusive{};
    for (std::size_t i = 0; i < 3; ++i) {
      const RawPoint a = v[i];
      const RawPoint b = v[(i + 1) % 3];
      inclusive[i] = bugs_.fill_bottom_right ? bottom_right_inclusive(a, b)
                                             : scene_inclusive(a, b, scene.conventions.fill);
    }
    std::int64_t min_x = v[0].x, max_x = v[0].x, min_y = v[0].y, max_y = v[0].y;
    for (const RawPoint& p : v) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
    // Pixels whose centre (i * 256 + 128) lies in the bounding box, clipped to the target.
    const std::int64_t x0 =
        std::max<std::int64_t>(0, -floor_div(-(min_x - kSubpixelHalf), kSubpixelOne));
    const std::int64_t x1 =
        std::min<std::int64_t>(scene.width - 1, floor_div(max_x - kSubpixelHalf, kSubpixelOne));
    const std::int64_t y0 =
        std::max<std::int64_t>(0, -floor_div(-(min_y - kSubpixelHalf), kSubpixelOne));
    const std::int64_t y1 =
        std::min<std::int64_t>(scene.height - 1, floor_div(max_y - kSubpixelHalf, kSubpixelOne));
    for (std::int64_t py = y0; py <= y1; ++py) {
      for (std::int64_t px = x0; px <= x1; ++px) {
        const RawPoint s{px * kSubpixelOne + kSubpixelHalf, py * kSubpixelOne + kSubpixelHalf};
        bool in = true;
        for (std::size_t i = 0; i < 3 && in; ++i)
          in = inside(v[i], v[(i + 1) % 3], s, inclusive[i]);
        if (in)
          out.emplace_back(prim, static_cast<std::int32_t>(px), static_cast<std::int32_t>(py));
      }
    }
  }

  [[nodiscard]] bool inside(RawPoint a, RawPoint b, RawPoint s, bool inclusive) const {
    if (bugs_.float_edges) {
      // The planted bug: float32 arithmetic in pixels, and (unless a tie rule is planted as
      // well) every sample with E >= 0 inside, whatever the edge.
      const auto f = [](std::int64_t raw) {
        return static_cast<float>(raw) / static_cast<float>(kSubpixelOne);
      };
      const float e = (f(b.x) - f(a.x)) * (f(s.y) - f(a.y)) - (f(b.y) - f(a.y)) * (f(s.x) - f(a.x));
      if (bugs_.fill_bottom_right)
        return e > 0.0f || (e == 0.0f && inclusive);
      return e >= 0.0f;
    }
    const std::int64_t e = (b.x - a.x) * (s.y - a.y) - (b.y - a.y) * (s.x - a.x);
    return e > 0 || (e == 0 && inclusive);
  }

  ImpreciseBugs bugs_;
  DriverInfo info_;
};

// rule: PIPE.BARY.EXACT, PIPE.BARY.LINE
// The barycentrics of s for a drawn primitive, written again here (the kernel's are private to
// its pipeline): a triangle's edge values, a line's projection parameter, a point's (1, 0, 0).
pipe::Barycentrics bary_at(const pipe::DrawnPrimitive& d, Vec2 s) {
  if (d.type == PrimitiveType::kTriangle && d.snapped.size() == 3)
    return pipe::barycentrics({d.snapped[0], d.snapped[1], d.snapped[2]}, s);
  pipe::Barycentrics b;
  if (d.snapped.size() < 2) {
    b.e = {1, 0, 0};
    b.area = 1;
    return b;
  }
  const std::int64_t dx = d.snapped[1].x.raw() - d.snapped[0].x.raw();
  const std::int64_t dy = d.snapped[1].y.raw() - d.snapped[0].y.raw();
  const std::int64_t num =
      (s.x.raw() - d.snapped[0].x.raw()) * dx + (s.y.raw() - d.snapped[0].y.raw()) * dy;
  b.area = dx * dx + dy * dy;
  b.e = {b.area - num, num, 0};
  return b;
}

// rule: DRIVER.IMPRECISE.VALUES
// The value bugs: the reference's pipeline (coverage, clipping, snapping, barycentrics), with
// one planted mistake in the values it reports.
class ValueBugDriver final : public Driver {
public:
  ValueBugDriver(std::string name, ImpreciseBugs bugs)
      : bugs_(bugs), info_(detail::full_capabilities(std::move(name), "", kSubpixelBits)) {
    std::string what;
    if (bugs_.screen_space)
      what += " perspective attributes interpolated in screen space;";
    if (bugs_.wrong_provoking)
      what += " flat attributes from the other provoking vertex;";
    if (bugs_.d24_truncate)
      what += " D24 depth stored by truncation;";
    what.pop_back();
    info_.description = "built-in imprecise values (planted bugs:" + what + ")";
    info_.values = true;
  }

  [[nodiscard]] const DriverInfo& info() const override { return info_; }
  [[nodiscard]] std::string unsupported(const Scene&) const override { return {}; }

  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    return detail::coverage_of(draw_values(scene));
  }

  [[nodiscard]] ValuesResult draw_values(const Scene& scene) override {
    auto run = pipe::run_pipeline(scene);
    if (const auto* e = std::get_if<SceneError>(&run))
      return DriverError{"invalid scene: " + e->what()};
    pipe::PipeResult& r = std::get<pipe::PipeResult>(run);
    for (std::size_t i = 0; i < r.data.size(); ++i)
      plant(scene, r.fragments[i], r.drawn[r.data[i].drawn], r.data[i]);
    return detail::observable_drawing(std::move(r));
  }

private:
  void plant(const Scene& scene, const Fragment& f, const pipe::DrawnPrimitive& d,
             pipe::FragmentData& out) const {
    if (out.attr.size() == scene.attributes.size()) {
      for (std::size_t k = 0; k < scene.attributes.size(); ++k) {
        const pipe::AttributeDecl& decl = scene.attributes[k];
        if (bugs_.screen_space && decl.interpolation == pipe::Interpolation::kPerspective) {
          Vec2 at = pixel_center(f.x, f.y);
          if (decl.location == pipe::Location::kCentroid && f.centroid)
            at = sample_position(f.x, f.y, f.centroid->offset);
          if (decl.location == pipe::Location::kSample && f.sample)
            at = sample_position(f.x, f.y, scene.msaa.pattern.positions[*f.sample]);
          const pipe::Barycentrics b = bary_at(d, at);
          // The planted bug: no division by w (a zero-length line keeps the flat value).
          out.attr[k] = b.area == 0 ? d.flat[k] : pipe::interpolate_linear(b, d.attr[k]);
        }
        if (bugs_.wrong_provoking && decl.interpolation == pipe::Interpolation::kFlat) {
          if (const auto v = other_provoking(scene, f, d, k))
            out.attr[k] = *v;
        }
      }
    }
    if (bugs_.d24_truncate && scene.depth && scene.conventions.depth == pipe::DepthFormat::kD24) {
      const pipe::Viewport vp =
          scene.viewport.value_or(pipe::Viewport{0.0f, 0.0f, static_cast<float>(scene.width),
                                                 static_cast<float>(scene.height), 0.0f, 1.0f});
      std::size_t n = 0;
      for (std::uint32_t k = 0; k < scene.msaa.count() && n < out.depth.size(); ++k) {
        if ((f.mask >> k & 1u) == 0)
          continue;
        const pipe::Barycentrics b =
            bary_at(d, sample_position(f.x, f.y, scene.msaa.pattern.positions[k]));
        const double z = b.area == 0 ? d.z[0] : pipe::interpolate_depth(b, d.z);
        const double c =
            std::clamp(z, static_cast<double>(vp.min_depth), static_cast<double>(vp.max_depth));
        // The planted bug: floor(z * (2^24 - 1)) instead of floor(z * (2^24 - 1) + 0.5).
        out.depth[n++].unorm = static_cast<std::uint32_t>(std::floor(c * 16777215.0));
      }
    }
  }

  // The value of attribute k at the end of the primitive (or strip segment) that is not its
  // provoking vertex; nullopt for a point, or when the segment is not known.
  static std::optional<float> other_provoking(const Scene& scene, const Fragment& f,
                                              const pipe::DrawnPrimitive& d, std::size_t k) {
    const Primitive& p = scene.primitives[f.prim];
    const std::size_t n = p.attr.size();
    if (n < 2)
      return std::nullopt;
    std::size_t first = 0, last = n - 1;
    if (p.type == PrimitiveType::kLineStrip) {
      const std::optional<std::uint32_t> seg = f.seg ? f.seg : d.seg;
      if (!seg || *seg + 1 >= n)
        return std::nullopt;
      first = *seg;
      last = *seg + 1;
    }
    const bool provoking_first = scene.conventions.provoking == pipe::Provoking::kFirst;
    return p.attr[provoking_first ? last : first][k];
  }

  ImpreciseBugs bugs_;
  DriverInfo info_;
};

} // namespace

bool parse_imprecise_variant(std::string_view name, ImpreciseBugs* bugs) {
  ImpreciseBugs b;
  if (name == "imprecise") {
    b = ImpreciseBugs{true, true, true};
  } else if (name == "imprecise:float-edges") {
    b.float_edges = true;
  } else if (name == "imprecise:fill-bottom-right") {
    b.fill_bottom_right = true;
  } else if (name == "imprecise:4-bit-subpixel") {
    b.four_bit_subpixel = true;
  } else if (name == "imprecise:screen-space") {
    b.screen_space = true;
  } else if (name == "imprecise:provoking-vertex") {
    b.wrong_provoking = true;
  } else if (name == "imprecise:d24-truncate") {
    b.d24_truncate = true;
  } else {
    return false;
  }
  *bugs = b;
  return true;
}

std::vector<std::string> imprecise_driver_names() {
  return {"imprecise",
          "imprecise:float-edges",
          "imprecise:fill-bottom-right",
          "imprecise:4-bit-subpixel",
          "imprecise:screen-space",
          "imprecise:provoking-vertex",
          "imprecise:d24-truncate"};
}

std::unique_ptr<Driver> open_imprecise_driver(std::string_view name, std::string* error) {
  ImpreciseBugs bugs;
  if (!parse_imprecise_variant(name, &bugs)) {
    if (error != nullptr) {
      *error = "unknown imprecise driver \"" + std::string(name) +
               "\" (imprecise, imprecise:float-edges, imprecise:fill-bottom-right, "
               "imprecise:4-bit-subpixel, imprecise:screen-space, imprecise:provoking-vertex, "
               "imprecise:d24-truncate)";
    }
    return nullptr;
  }
  if (bugs.screen_space || bugs.wrong_provoking || bugs.d24_truncate)
    return std::make_unique<ValueBugDriver>(std::string(name), bugs);
  return std::make_unique<ImpreciseDriver>(std::string(name), bugs);
}

namespace detail {
std::unique_ptr<Driver> open_imprecise(std::string_view arg, std::string* error) {
  return open_imprecise_driver(
      arg.empty() ? std::string("imprecise") : "imprecise:" + std::string(arg), error);
}
} // namespace detail

} // namespace rastrules::driver
