// SPDX-License-Identifier: MIT
// cairo as a 2D library driver: each path is filled with cairo_fill into an A8 image surface,
// with CAIRO_ANTIALIAS_NONE for aliased paths and CAIRO_ANTIALIAS_DEFAULT (or the mode the
// driver's argument names: "cairo:best", ...) for antialiased ones. cairo has no quadratic
// curves: a quadratic is given as the cubic with the same curve, its inner control points
// computed in raw 16.8 units (below).
// Implements: DRIVER.PATH.CAIRO

#include <cairo.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "drivers.hpp"
#include "path_library.hpp"

namespace rastrules::driver {
namespace {

// The antialiased modes the driver's argument may name, as cairo_antialias_t.
struct Mode {
  std::string_view name;
  cairo_antialias_t antialias;
  std::string_view constant; // as cairo's documentation names it
};
constexpr auto kModes = std::to_array<Mode>({
    {"default", CAIRO_ANTIALIAS_DEFAULT, "CAIRO_ANTIALIAS_DEFAULT"},
    {"best", CAIRO_ANTIALIAS_BEST, "CAIRO_ANTIALIAS_BEST"},
    {"good", CAIRO_ANTIALIAS_GOOD, "CAIRO_ANTIALIAS_GOOD"},
    {"fast", CAIRO_ANTIALIAS_FAST, "CAIRO_ANTIALIAS_FAST"},
});

// Returns n / 3 rounded to the nearest integer. n / 3 is never halfway between two integers,
// so there is no tie to break: floor((n + 1) / 3), with the floor taken for negative n too.
std::int64_t nearest_third(std::int64_t n) {
  const std::int64_t m = n + 1;
  return m >= 0 ? m / 3 : -((-m + 2) / 3);
}

// A raw 16.8 coordinate in cairo's user space (pixels): exact in double, and exact again in
// cairo's 24.8 fixed point, which the identity matrix maps it to.
double px(std::int64_t raw) {
  return static_cast<double>(raw) / 256.0;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

class CairoDriver final : public detail::PathLibraryDriver {
public:
  CairoDriver(DriverInfo info, cairo_antialias_t antialias)
      : PathLibraryDriver(std::move(info)), antialias_(antialias) {}

protected:
  // rule: DRIVER.PATH.CAIRO
  std::optional<std::string> raster(const detail::PathJob& job,
                                    std::vector<std::uint8_t>& alpha) override {
    // A new surface per path: cairo's image surfaces start at 0 (transparent), which is the
    // cleared raster DRIVER.PATH.LIBRARY asks for, with no clearing pass of our own.
    std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
        cairo_image_surface_create(CAIRO_FORMAT_A8, job.width, job.height));
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
      return std::string("cairo_image_surface_create: ") +
             cairo_status_to_string(cairo_surface_status(surface.get()));
    std::unique_ptr<cairo_t, ContextDeleter> cr(cairo_create(surface.get()));
    // An opaque source OVER a transparent pixel stores the mask's coverage itself:
    // 1 * m + 0 * (1 - m) = m, so the byte read back is cairo's alpha for the pixel.
    cairo_set_operator(cr.get(), CAIRO_OPERATOR_OVER);
    cairo_set_source_rgba(cr.get(), 0, 0, 0, 1);
    cairo_set_antialias(cr.get(), job.antialiased ? antialias_ : CAIRO_ANTIALIAS_NONE);
    cairo_set_fill_rule(cr.get(), job.path->fill_rule == path::FillRule::kNonZero
                                      ? CAIRO_FILL_RULE_WINDING
                                      : CAIRO_FILL_RULE_EVEN_ODD);
    // The flattening tolerance stays cairo's default (0.1 px): what cairo draws by default.
    cairo_new_path(cr.get());
    for (const path::Contour& c : job.path->contours) {
      path::Point cur = c.start;
      cairo_move_to(cr.get(), px(cur.x), px(cur.y));
      for (const path::Segment& s : c.segments) {
        switch (s.kind) {
        case path::SegmentKind::kLine:
          cairo_line_to(cr.get(), px(s.p[0].x), px(s.p[0].y));
          break;
        case path::SegmentKind::kQuadratic: {
          // The quadratic (p0, q, p1) is the cubic (p0, (p0 + 2q) / 3, (2q + p1) / 3, p1).
          // The thirds are taken in raw units and rounded to the nearest raw unit: exact when
          // 3 divides the sum, else within 1/3 raw unit (1/768 px), and in either case the
          // point cairo's own 24.8 path would hold, so no second rounding follows.
          const path::Point q = s.p[0], e = s.p[1];
          const std::int64_t c1x = nearest_third(std::int64_t{cur.x} + 2 * std::int64_t{q.x});
          const std::int64_t c1y = nearest_third(std::int64_t{cur.y} + 2 * std::int64_t{q.y});
          const std::int64_t c2x = nearest_third(2 * std::int64_t{q.x} + std::int64_t{e.x});
          const std::int64_t c2y = nearest_third(2 * std::int64_t{q.y} + std::int64_t{e.y});
          cairo_curve_to(cr.get(), px(c1x), px(c1y), px(c2x), px(c2y), px(e.x), px(e.y));
          break;
        }
        case path::SegmentKind::kCubic:
          cairo_curve_to(cr.get(), px(s.p[0].x), px(s.p[0].y), px(s.p[1].x), px(s.p[1].y),
                         px(s.p[2].x), px(s.p[2].y));
          break;
        }
        cur = s.p[path::point_count(s.kind) - 1];
      }
      cairo_close_path(cr.get());
    }
    cairo_fill(cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      return std::string("cairo_fill: ") + cairo_status_to_string(cairo_status(cr.get()));
    cairo_surface_flush(surface.get());
    // Rows of an A8 surface are cairo_image_surface_get_stride() bytes apart (a multiple of 4),
    // not width: copy each row's first width bytes.
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const auto stride = static_cast<std::size_t>(cairo_image_surface_get_stride(surface.get()));
    const auto w = static_cast<std::size_t>(job.width);
    for (std::size_t y = 0; y < static_cast<std::size_t>(job.height); ++y)
      std::memcpy(alpha.data() + y * w, data + y * stride, w);
    return std::nullopt;
  }

private:
  cairo_antialias_t antialias_;
};

} // namespace

namespace detail {

// rule: DRIVER.PATH.CAIRO
std::unique_ptr<Driver> open_cairo(std::string_view arg, std::string* error) {
  const Mode* mode = arg.empty() ? &kModes[0] : nullptr;
  for (const Mode& m : kModes)
    if (m.name == arg)
      mode = &m;
  if (mode == nullptr) {
    std::string known;
    for (const Mode& m : kModes)
      known += (known.empty() ? "" : ", ") + std::string(m.name);
    *error = "unknown cairo antialias mode '" + std::string(arg) + "' (known: " + known + ")";
    return nullptr;
  }
  const std::string mode_name(mode->name);
  PathSupport ps;
  ps.samples = ps.area = ps.nonzero = ps.evenodd = ps.quadratics = ps.cubics = true;
  // cairo holds paths in 24.8 fixed point (cairo_fixed_t), the kernel's own 1/256 px.
  ps.grid_raw = 1;
  ps.grid = "24.8";
  // cairo's documentation says only "a bilevel alpha mask" (NONE) and names a quality for the
  // others; what its scan converters do is in the tests (tests/driver/path_library_test.cpp).
  ps.aliased_method = "CAIRO_ANTIALIAS_NONE: a bilevel mask of the polygon flattened at "
                      "tolerance 0.1 px; quadratics as cubics";
  ps.antialiased_method = std::string(mode->constant) +
                          ": 8-bit coverage of the polygon flattened at tolerance 0.1 px; "
                          "quadratics as cubics";
  const std::string name = arg.empty() ? std::string("cairo") : "cairo:" + mode_name;
  // An image surface takes at most 32767 px a side (cairo's MAX_IMAGE_SIZE).
  return std::make_unique<CairoDriver>(
      path_library_info(name,
                        std::string("cairo ") + cairo_version_string() +
                            " (A8 image surface, cairo_fill: CAIRO_ANTIALIAS_NONE for samples, " +
                            std::string(mode->constant) + " for area)",
                        ps, 32767),
      mode->antialias);
}

} // namespace detail
} // namespace rastrules::driver
