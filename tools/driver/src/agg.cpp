// SPDX-License-Identifier: MIT
// Anti-Grain Geometry as a 2D library driver (its headers say 2.4; Debian's libagg-dev is
// 2.6.1, its pkg-config file says 2.7.0): each path goes into an agg::path_storage, through
// agg::conv_curve (AGG's own curve flattening) into an agg::rasterizer_scanline_aa, whose
// cells (24.8 subpixels) are swept into an 8-bit gray raster: with agg::scanline_u8 and a
// linear gamma for antialiased paths, with agg::scanline_bin and AGG's threshold gamma at 0.5
// (its aliased mode) for aliased paths.
// Implements: DRIVER.PATH.AGG

#include <agg_basics.h>
#include <agg_color_gray.h>
#include <agg_conv_curve.h>
#include <agg_gamma_functions.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_gray.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_bin.h>
#include <agg_scanline_u.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "drivers.hpp"
#include "path_library.hpp"
#include "rastrules/fixed.hpp"

#ifndef RASTRULES_AGG_VERSION
#define RASTRULES_AGG_VERSION "2.4"
#endif

namespace rastrules::driver {
namespace {

// A raw 16.8 coordinate in AGG's user space (pixels): exact in double, and mapped back to the
// same integer by the rasterizer's 24.8 conversion (iround(v * 256)).
double px(std::int32_t raw) {
  return static_cast<double>(raw) / 256.0;
}

using Pixels = agg::pixfmt_gray8;
using Base = agg::renderer_base<Pixels>;

class AggDriver final : public detail::PathLibraryDriver {
public:
  explicit AggDriver(DriverInfo info) : PathLibraryDriver(std::move(info)) {}

protected:
  // rule: DRIVER.PATH.AGG
  std::optional<std::string> raster(const detail::PathJob& job,
                                    std::vector<std::uint8_t>& alpha) override {
    agg::path_storage storage;
    for (const path::Contour& c : job.path->contours) {
      storage.move_to(px(c.start.x), px(c.start.y));
      for (const path::Segment& s : c.segments) {
        switch (s.kind) {
        case path::SegmentKind::kLine:
          storage.line_to(px(s.p[0].x), px(s.p[0].y));
          break;
        case path::SegmentKind::kQuadratic:
          storage.curve3(px(s.p[0].x), px(s.p[0].y), px(s.p[1].x), px(s.p[1].y));
          break;
        case path::SegmentKind::kCubic:
          storage.curve4(px(s.p[0].x), px(s.p[0].y), px(s.p[1].x), px(s.p[1].y), px(s.p[2].x),
                         px(s.p[2].y));
          break;
        }
      }
      storage.close_polygon();
    }
    // AGG's defaults: curve_div subdivision at approximation_scale 1 (distance tolerance
    // 0.5 px), no angle tolerance, no cusp limit; what AGG draws when asked for nothing else.
    agg::conv_curve<agg::path_storage> curves(storage);

    // No clip box: the cells are AGG's arithmetic on the whole path. A clip box would cut
    // edges at rounded intersections; the renderer clips spans to the raster instead.
    agg::rasterizer_scanline_aa<> ras;
    ras.filling_rule(job.path->fill_rule == path::FillRule::kNonZero ? agg::fill_non_zero
                                                                     : agg::fill_even_odd);
    ras.add_path(curves);

    // The raster is the gray8 rendering buffer itself: rows of width bytes, from the top
    // (a positive stride). An opaque white (255) source blended over 0 with cover c stores
    // lerp(0, 255, c) = c exactly, so the byte is AGG's alpha for the pixel.
    agg::rendering_buffer rbuf(alpha.data(), static_cast<unsigned>(job.width),
                               static_cast<unsigned>(job.height), job.width);
    Pixels pixels(rbuf);
    Base base(pixels);
    const agg::gray8 white(255, 255);
    if (job.antialiased) {
      // Linear: the alpha is AGG's cover (the cell area in 1/256 px, clamped to 255).
      ras.gamma(agg::gamma_none());
      agg::scanline_u8 sl;
      agg::renderer_scanline_aa_solid<Base> ren(base);
      ren.color(white);
      agg::render_scanlines(ras, sl, ren);
    } else {
      // scanline_bin marks every pixel whose alpha after the gamma is nonzero. With a linear
      // gamma that is any pixel an edge touches; AGG's aliased rendering (its rasterizers
      // demo) thresholds the cover instead: gamma_threshold(0.5) maps cover c to 0 when
      // c / 255 < 0.5, so a pixel is set from cover 128 up, that is, when at least half of it
      // is covered (the cover counts 1/256 px).
      ras.gamma(agg::gamma_threshold(0.5));
      agg::scanline_bin sl;
      agg::renderer_scanline_bin_solid<Base> ren(base);
      ren.color(white);
      agg::render_scanlines(ras, sl, ren);
    }
    return std::nullopt;
  }
};

} // namespace

namespace detail {

// rule: DRIVER.PATH.AGG
std::unique_ptr<Driver> open_agg(std::string_view arg, std::string* error) {
  if (!arg.empty()) {
    *error = "driver 'agg' takes no argument";
    return nullptr;
  }
  PathSupport ps;
  ps.samples = ps.area = ps.nonzero = ps.evenodd = ps.quadratics = ps.cubics = true;
  // poly_subpixel_shift 8: AGG's rasterizer works on 24.8 integers, the kernel's 1/256 px.
  ps.grid_raw = 1;
  ps.grid = "24.8";
  ps.aliased_method = "scanline_bin with gamma_threshold(0.5): pixels whose cell cover is at "
                      "least half; curves flattened by conv_curve (0.5 px)";
  ps.antialiased_method = "signed-area cells per scanline, cover = area in 1/256 px clamped to "
                          "255, linear gamma; curves flattened by conv_curve (0.5 px)";
  // AGG sets no limit of its own below the kernel's.
  return std::make_unique<AggDriver>(
      path_library_info("agg",
                        "Anti-Grain Geometry (libagg " RASTRULES_AGG_VERSION
                        ", rasterizer_scanline_aa, 24.8 subpixels: "
                        "scanline_bin for samples, scanline_u8 for area)",
                        ps, kMaxTargetSide));
}

} // namespace detail
} // namespace rastrules::driver
