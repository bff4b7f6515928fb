// SPDX-License-Identifier: MIT
// Pictures of a rendered scene.

#include "rastrules/io/picture.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace rastrules::io {
namespace {

// Distinct colours for primitives; red is kept for overlaps and grey for the grid.
constexpr std::array<Rgb, 10> kPalette = {{{31, 119, 180},
                                           {255, 127, 14},
                                           {44, 160, 44},
                                           {148, 103, 189},
                                           {140, 86, 75},
                                           {227, 119, 194},
                                           {188, 189, 34},
                                           {23, 190, 207},
                                           {57, 59, 121},
                                           {99, 121, 57}}};

constexpr Rgb kGrid{175, 175, 175};
constexpr Rgb kCentre{80, 80, 80};
constexpr Rgb kInactiveEdge{120, 120, 120};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, int percent_a) {
  return static_cast<std::uint8_t>((a * percent_a + b * (100 - percent_a)) / 100);
}

// Image coordinate of a snapped coordinate (raw 16.8) at `scale` image pixels per pixel.
double to_image(std::int32_t raw, int scale) {
  return static_cast<double>(raw) * scale / kSubpixelOne;
}

}  // namespace

int default_picture_scale(std::int32_t width, std::int32_t height) {
  const std::int32_t side = std::max(width, height);
  if (side <= 0) return 0;
  return std::min<int>(kDefaultPixelScale, (kMaxPictureSide - 1) / side);
}

bool picture_fits(std::int32_t width, std::int32_t height, int scale) {
  const std::int64_t side = std::max(width, height);
  return scale >= 1 && side * scale + 1 <= kMaxPictureSide;
}

CoverageMap::CoverageMap(std::int32_t width, std::int32_t height)
    : width_(width), height_(height),
      first_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0),
      count_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {}

std::size_t CoverageMap::index(std::int32_t x, std::int32_t y) const {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
}

void CoverageMap::add(std::uint32_t prim, std::int32_t x, std::int32_t y) {
  const std::size_t i = index(x, y);
  if (count_[i] == 0) first_[i] = prim;
  if (count_[i] < 255) ++count_[i];
}

std::uint32_t CoverageMap::count(std::int32_t x, std::int32_t y) const { return count_[index(x, y)]; }
std::uint32_t CoverageMap::first(std::int32_t x, std::int32_t y) const { return first_[index(x, y)]; }

Rgb cover_colour(std::uint32_t prim) {
  const Rgb c = kPalette[prim % kPalette.size()];
  return Rgb{mix(c.r, 255, 45), mix(c.g, 255, 45), mix(c.b, 255, 45)};
}

Rgb edge_colour(std::uint32_t prim) {
  const Rgb c = kPalette[prim % kPalette.size()];
  return Rgb{mix(c.r, 0, 75), mix(c.g, 0, 75), mix(c.b, 0, 75)};
}

Image draw_picture(const PreparedScene& scene, const CoverageMap& coverage, int scale) {
  const int s = scale;
  Image img(scene.width * s + 1, scene.height * s + 1, kBackground);

  // Covered pixels: the primitive's colour; overlaps: light red with a red hatch and border.
  for (std::int32_t j = 0; j < scene.height; ++j) {
    for (std::int32_t i = 0; i < scene.width; ++i) {
      const std::uint32_t n = coverage.count(i, j);
      if (n == 0) continue;
      const int x0 = i * s, y0 = j * s;
      if (n == 1) {
        img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, cover_colour(coverage.first(i, j)));
        continue;
      }
      img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, kOverlapColour);
      if (s < 4) {
        img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, kOverlapMark);
        continue;
      }
      const int border = std::max(1, s / 16);
      for (int y = 0; y <= s; ++y) {
        for (int x = 0; x <= s; ++x) {
          const bool edge = x < border + 1 || y < border + 1 || x > s - border - 1 || y > s - border - 1;
          if (edge || (x + y) % 6 < 2) img.set(x0 + x, y0 + y, kOverlapMark);
        }
      }
    }
  }

  // Pixel grid.
  if (s >= 3) {
    for (std::int32_t i = 0; i <= scene.width; ++i) img.fill_rect(i * s, 0, i * s + 1, img.height(), kGrid);
    for (std::int32_t j = 0; j <= scene.height; ++j) img.fill_rect(0, j * s, img.width(), j * s + 1, kGrid);
  }

  // Pixel centres, as small crosses (COORD.PIXEL.CENTER).
  if (s >= 6) {
    const int arm = std::max(1, s / 10);
    for (std::int32_t j = 0; j < scene.height; ++j) {
      for (std::int32_t i = 0; i < scene.width; ++i) {
        const int cx = i * s + s / 2, cy = j * s + s / 2;
        for (int k = -arm; k <= arm; ++k) {
          img.set(cx + k, cy + k, kCentre);
          img.set(cx + k, cy - k, kCentre);
        }
      }
    }
  }

  // Edges at their snapped positions: solid for drawn primitives, dashed grey for culled and
  // degenerate ones. Then the vertices.
  for (std::size_t p = 0; p < scene.triangles.size(); ++p) {
    const TriangleSetup& t = scene.triangles[p];
    const bool drawn = t.status == TriangleStatus::kRasterized;
    const Rgb c = drawn ? edge_colour(static_cast<std::uint32_t>(p)) : kInactiveEdge;
    for (std::size_t e = 0; e < 3; ++e) {
      const Vec2 a = t.snapped[e];
      const Vec2 b = t.snapped[(e + 1) % 3];
      img.line(to_image(a.x.raw(), s), to_image(a.y.raw(), s), to_image(b.x.raw(), s),
               to_image(b.y.raw(), s), c, drawn ? 0 : 3);
    }
  }
  const int r = std::max(1, s / 16);
  for (std::size_t p = 0; p < scene.triangles.size(); ++p) {
    const TriangleSetup& t = scene.triangles[p];
    const Rgb c = t.status == TriangleStatus::kRasterized ? edge_colour(static_cast<std::uint32_t>(p))
                                                          : kInactiveEdge;
    for (const Vec2& v : t.snapped) {
      const double x = to_image(v.x.raw(), s), y = to_image(v.y.raw(), s);
      if (x < -r || y < -r || x > img.width() + r || y > img.height() + r) continue;
      const int xi = static_cast<int>(x + 0.5), yi = static_cast<int>(y + 0.5);
      img.fill_rect(xi - r, yi - r, xi + r + 1, yi + r + 1, c);
    }
  }
  return img;
}

}  // namespace rastrules::io
