// SPDX-License-Identifier: MIT
// Pictures of a rendered scene.

#include "rastrules/io/picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
constexpr Rgb kSampleMark{40, 40, 40};
constexpr Rgb kSharedPixel{228, 228, 228};
constexpr Rgb kHelperMark{150, 0, 150};
constexpr Rgb kCentroidMark{200, 0, 0};

// The number of samples a picture shows per pixel (the pattern's, at most 32).
std::uint32_t coverage_sample_count(const PreparedScene& scene) {
  return std::min<std::uint32_t>(scene.msaa.count(), 32);
}

std::uint8_t mix(std::uint8_t a, std::uint8_t b, int percent_a) {
  return static_cast<std::uint8_t>((a * percent_a + b * (100 - percent_a)) / 100);
}

// Image coordinate of a snapped coordinate (raw 16.8) at `scale` image pixels per pixel.
double to_image(std::int32_t raw, int scale) {
  return static_cast<double>(raw) * scale / kSubpixelOne;
}

} // namespace

int default_picture_scale(std::int32_t width, std::int32_t height) {
  const std::int32_t side = std::max(width, height);
  if (side <= 0)
    return 0;
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
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
         static_cast<std::size_t>(x);
}

void CoverageMap::add(std::uint32_t prim, std::int32_t x, std::int32_t y,
                      std::optional<std::uint32_t> coverage_q16) {
  const std::size_t i = index(x, y);
  if (coverage_q16) {
    // Antialiased: blended over what earlier antialiased fragments left, white at first
    // (srcColor * alpha + dstColor * (1 - alpha), alpha = coverage), not counted as overlap.
    if (aa_.empty())
      aa_.assign(first_.size(), kBackground);
    if (aa_seen_.empty())
      aa_seen_.assign(first_.size(), 0);
    const Rgb src = kPalette[prim % kPalette.size()];
    const int percent = static_cast<int>((std::uint64_t{*coverage_q16} * 100 + 32768) >> 16);
    Rgb& dst = aa_[i];
    dst = Rgb{mix(src.r, dst.r, percent), mix(src.g, dst.g, percent), mix(src.b, dst.b, percent)};
    aa_seen_[i] = 1;
    return;
  }
  if (count_[i] == 0)
    first_[i] = prim;
  if (count_[i] < 255)
    ++count_[i];
}

void CoverageMap::record_samples(std::uint32_t sample_count) {
  const std::size_t pixels = first_.size();
  sample_count_ = sample_count;
  owner_.assign(pixels * sample_count, 0);
  helper_.assign(pixels, 0);
  sample_overlap_.assign(pixels, 0);
  has_centroid_.assign(pixels, 0);
  centroid_.assign(pixels, SampleOffset{});
}

void CoverageMap::add_fragment(const Fragment& f) {
  const std::size_t i = index(f.x, f.y);
  if (sample_count_ != 0) {
    if (f.helper) {
      helper_[i] = 1;
    } else {
      for (std::uint32_t k = 0; k < sample_count_ && k < 32; ++k) {
        if (((f.mask >> k) & 1u) == 0)
          continue;
        std::uint32_t& owner = owner_[i * sample_count_ + k];
        if (owner != 0)
          sample_overlap_[i] = 1;
        owner = f.prim + 1;
      }
      if (f.centroid) {
        has_centroid_[i] = 1;
        centroid_[i] = f.centroid->offset;
      }
    }
  }
  if (f.helper)
    return;
  if (f.sample && last_counted_ && last_counted_->prim == f.prim && last_counted_->x == f.x &&
      last_counted_->y == f.y && last_counted_->seg == f.seg) {
    return;
  }
  last_counted_ = f;
  // rule: SCENE.OUTPUT.AREA
  // A path's exact area is blended like an antialiased line's coverage (to 1/65536, at least
  // 1/65536 so that a pixel of tiny area still shows).
  if (f.area) {
    const auto q16 = static_cast<std::uint32_t>(
        std::clamp<long>(std::lround(f.area.approx() * 65536.0), 1L, 65536L));
    add(f.prim, f.x, f.y, q16);
    return;
  }
  add(f.prim, f.x, f.y, f.coverage_q16);
}

std::uint32_t CoverageMap::sample_owner(std::int32_t x, std::int32_t y, std::uint32_t k) const {
  return owner_[index(x, y) * sample_count_ + k];
}

bool CoverageMap::helper(std::int32_t x, std::int32_t y) const {
  return helper_[index(x, y)] != 0;
}

bool CoverageMap::sample_overlap(std::int32_t x, std::int32_t y) const {
  return sample_overlap_[index(x, y)] != 0;
}

std::optional<SampleOffset> CoverageMap::centroid(std::int32_t x, std::int32_t y) const {
  if (has_centroid_[index(x, y)] == 0)
    return std::nullopt;
  return centroid_[index(x, y)];
}

bool samples_visible(const PreparedScene& scene, int scale) {
  const MultisampleState& ms = scene.msaa;
  const bool multisampled = ms.count() > 1 || ms.has_centroid || ms.wants_quads();
  return multisampled && scale >= kMinSampleScale;
}

std::optional<Rgb> CoverageMap::aa_colour(std::int32_t x, std::int32_t y) const {
  if (aa_seen_.empty() || aa_seen_[index(x, y)] == 0)
    return std::nullopt;
  return aa_[index(x, y)];
}

std::uint32_t CoverageMap::count(std::int32_t x, std::int32_t y) const {
  return count_[index(x, y)];
}
std::uint32_t CoverageMap::first(std::int32_t x, std::int32_t y) const {
  return first_[index(x, y)];
}

Rgb cover_colour(std::uint32_t prim) {
  const Rgb c = kPalette[prim % kPalette.size()];
  return Rgb{mix(c.r, 255, 45), mix(c.g, 255, 45), mix(c.b, 255, 45)};
}

Rgb edge_colour(std::uint32_t prim) {
  const Rgb c = kPalette[prim % kPalette.size()];
  return Rgb{mix(c.r, 0, 75), mix(c.g, 0, 75), mix(c.b, 0, 75)};
}

namespace {

// Whether a picture at scale s shows sample points rather than pixel centres.
bool shows_samples(const CoverageMap& coverage, int s) {
  return coverage.has_samples() && s >= kMinSampleScale;
}

// Draws an overlapping pixel with top-left image corner (x0, y0): light red with a red hatch
// and border (all red below 4 image pixels per pixel).
void draw_overlap_pixel(Image& img, int x0, int y0, int s) {
  img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, kOverlapColour);
  if (s < 4) {
    img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, kOverlapMark);
    return;
  }
  const int border = std::max(1, s / 16);
  for (int y = 0; y <= s; ++y) {
    for (int x = 0; x <= s; ++x) {
      const bool edge =
          x < border + 1 || y < border + 1 || x > s - border - 1 || y > s - border - 1;
      if (edge || (x + y) % 6 < 2)
        img.set(x0 + x, y0 + y, kOverlapMark);
    }
  }
}

// Draws covered pixels in the primitive's colour, antialiased ones in their blend, and
// overlaps as draw_overlap_pixel does.
void draw_coverage(Image& img, const PreparedScene& scene, const CoverageMap& coverage, int s) {
  for (std::int32_t j = 0; j < scene.height; ++j) {
    for (std::int32_t i = 0; i < scene.width; ++i) {
      const std::uint32_t n = coverage.count(i, j);
      const int x0 = i * s, y0 = j * s;
      if (n == 0) {
        if (const std::optional<Rgb> aa = coverage.aa_colour(i, j)) {
          img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, *aa);
        }
        continue;
      }
      if (n == 1) {
        img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, cover_colour(coverage.first(i, j)));
        continue;
      }
      // Multisampled: primitives sharing a pixel on different samples is no overlap; the
      // sample points show who covers what. Only a sample covered twice is hatched.
      if (shows_samples(coverage, s) && !coverage.sample_overlap(i, j)) {
        img.fill_rect(x0, y0, x0 + s + 1, y0 + s + 1, kSharedPixel);
        continue;
      }
      draw_overlap_pixel(img, x0, y0, s);
    }
  }
}

// Draws the pixel grid (from 3 image pixels per pixel) and the pixel centres as small crosses
// (COORD.PIXEL.CENTER; from 6, and not where the picture shows sample points instead).
void draw_grid_and_centres(Image& img, const PreparedScene& scene, const CoverageMap& coverage,
                           int s) {
  if (s >= 3) {
    for (std::int32_t i = 0; i <= scene.width; ++i)
      img.fill_rect(i * s, 0, i * s + 1, img.height(), kGrid);
    for (std::int32_t j = 0; j <= scene.height; ++j)
      img.fill_rect(0, j * s, img.width(), j * s + 1, kGrid);
  }
  if (s >= 6 && !shows_samples(coverage, s)) {
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
}

// Draws the segment a-b at scale s, dashed when dash > 0.
void draw_segment(Image& img, Vec2 a, Vec2 b, Rgb c, int dash, int s) {
  img.line(to_image(a.x.raw(), s), to_image(a.y.raw(), s), to_image(b.x.raw(), s),
           to_image(b.y.raw(), s), c, dash);
}

// Draws the edges of primitive p at their snapped positions: solid for drawn primitives,
// dashed grey for culled and degenerate ones; a point's square outline; a line's segments
// (and a quadrilateral line's two triangles).
void draw_edges(Image& img, const PreparedPrimitive& prim, std::uint32_t p, int s) {
  const Rgb colour = edge_colour(p);
  // rule: SCENE.PRIM.PATH
  // A path's outline: its lines, its curves as 32 chords each (a picture, not a decision),
  // and each contour's closing line (PATH.CONTOUR.CLOSE) dashed.
  if (prim.type == PrimitiveType::kPath) {
    auto at = [&](const path::Point& q) { return std::array{to_image(q.x, s), to_image(q.y, s)}; };
    for (const path::Contour& c : prim.path->contours) {
      path::Point cur = c.start;
      for (const path::Segment& seg : c.segments) {
        const std::size_t n = path::point_count(seg.kind);
        std::array<std::array<double, 2>, 4> ctl{at(cur), at(seg.p[0]), at(seg.p[1]), at(seg.p[2])};
        const int pieces = seg.kind == path::SegmentKind::kLine ? 1 : 32;
        std::array<double, 2> prev = ctl[0];
        for (int k = 1; k <= pieces; ++k) {
          const double t = static_cast<double>(k) / pieces, u = 1.0 - t;
          std::array<double, 2> q{};
          for (std::size_t a = 0; a < 2; ++a) {
            q[a] = n == 1   ? u * ctl[0][a] + t * ctl[1][a]
                   : n == 2 ? u * u * ctl[0][a] + 2 * u * t * ctl[1][a] + t * t * ctl[2][a]
                            : u * u * u * ctl[0][a] + 3 * u * u * t * ctl[1][a] +
                                  3 * u * t * t * ctl[2][a] + t * t * t * ctl[3][a];
          }
          img.line(prev[0], prev[1], q[0], q[1], colour, 0);
          prev = q;
        }
        cur = seg.p[n - 1];
      }
      if (!(cur == c.start)) {
        const auto a = at(cur), b = at(c.start);
        img.line(a[0], a[1], b[0], b[1], colour, 3);
      }
    }
    return;
  }
  if (prim.type == PrimitiveType::kPoint) {
    const Vec2 c = prim.v[0];
    auto corner = [&](std::int32_t dx, std::int32_t dy) {
      return Vec2{Subpixel::from_raw(c.x.raw() + dx), Subpixel::from_raw(c.y.raw() + dy)};
    };
    const std::int32_t h = kSubpixelHalf;
    const std::array<Vec2, 4> sq = {corner(-h, -h), corner(h, -h), corner(h, h), corner(-h, h)};
    for (std::size_t e = 0; e < 4; ++e)
      draw_segment(img, sq[e], sq[(e + 1) % 4], colour, 0, s);
    return;
  }
  for (const PreparedTriangle& pt : prim.triangles) {
    const TriangleSetup& t = pt.setup;
    const bool drawn = t.status == TriangleStatus::kRasterized;
    const Rgb c = drawn ? colour : kInactiveEdge;
    const bool quad = prim.type != PrimitiveType::kTriangle;
    for (std::size_t e = 0; e < 3; ++e) {
      draw_segment(img, t.snapped[e], t.snapped[(e + 1) % 3], c, drawn && !quad ? 0 : 3, s);
    }
  }
  if (prim.type == PrimitiveType::kLine || prim.type == PrimitiveType::kLineStrip) {
    for (std::size_t i = 0; i + 1 < prim.v.size(); ++i)
      draw_segment(img, prim.v[i], prim.v[i + 1], colour, 0, s);
  }
}

// Draws pixel (i, j)'s multisampling marks: a helper lane outlined dashed, its first n sample
// points hollow, covered samples filled in their primitive's colour, the centroid as a small
// cross.
// rule: SCENE.OUTPUT.MSAA
void draw_pixel_samples(Image& img, const PreparedScene& scene, const CoverageMap& coverage,
                        std::int32_t i, std::int32_t j, std::uint32_t n, int s) {
  const int sr = std::max(2, s / 14);
  const int x0 = i * s, y0 = j * s;
  if (coverage.helper(i, j)) {
    const int m = std::max(2, s / 10);
    const double a = x0 + m, b = y0 + m, c = x0 + s - m, d = y0 + s - m;
    img.line(a, b, c, b, kHelperMark, 3);
    img.line(c, b, c, d, kHelperMark, 3);
    img.line(c, d, a, d, kHelperMark, 3);
    img.line(a, d, a, b, kHelperMark, 3);
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    const SampleOffset o = scene.msaa.pattern.positions[k];
    const int cx = x0 + s / 2 + (o.x * s) / 16, cy = y0 + s / 2 + (o.y * s) / 16;
    const std::uint32_t owner = coverage.sample_owner(i, j, k);
    if (owner != 0)
      img.disc(cx, cy, sr, edge_colour(owner - 1), true);
    img.disc(cx, cy, sr, kSampleMark, false);
  }
  if (const std::optional<SampleOffset> c = coverage.centroid(i, j)) {
    const int cx = x0 + s / 2 + (c->x * s) / 16, cy = y0 + s / 2 + (c->y * s) / 16;
    const int arm = sr + 1;
    img.fill_rect(cx - arm, cy, cx + arm + 1, cy + 1, kCentroidMark);
    img.fill_rect(cx, cy - arm, cx + 1, cy + arm + 1, kCentroidMark);
  }
}

// Draws primitive p's vertices as small squares, grey for a culled or degenerate triangle.
void draw_vertices(Image& img, const PreparedPrimitive& prim, std::uint32_t p, int s) {
  const int r = std::max(1, s / 16);
  const bool inactive = prim.type == PrimitiveType::kTriangle &&
                        prim.triangles[0].setup.status != TriangleStatus::kRasterized;
  const Rgb c = inactive ? kInactiveEdge : edge_colour(p);
  for (const Vec2& v : prim.v) {
    const double x = to_image(v.x.raw(), s), y = to_image(v.y.raw(), s);
    if (x < -r || y < -r || x > img.width() + r || y > img.height() + r)
      continue;
    const int xi = static_cast<int>(x + 0.5), yi = static_cast<int>(y + 0.5);
    img.fill_rect(xi - r, yi - r, xi + r + 1, yi + r + 1, c);
  }
}

} // namespace

std::vector<LegendEntry> picture_legend(bool samples, bool aa) {
  std::vector<LegendEntry> l = {
      {cover_colour(0), false, "pixel covered by one primitive (one colour per primitive)"},
      {kOverlapMark, false, "pixel covered by more than one primitive (hatched red)"},
      {edge_colour(0), false, "snapped edges and vertices (squares) of a drawn primitive"},
      {kInactiveEdge, false,
       "dashed grey: culled or degenerate triangles, quadrilateral lines' "
       "triangles"},
      {kGrid, false, "pixel grid: x to the right, y down, pixel (0, 0) at the top left"}};
  if (samples) {
    l.push_back({kSampleMark, true,
                 "sample point (hollow), filled in the colour of the "
                 "primitive that covers it"});
    l.push_back({kSharedPixel, false, "pixel shared by primitives on different samples"});
    l.push_back({kHelperMark, false, "dashed purple: a helper lane of a 2x2 quad"});
    l.push_back({kCentroidMark, true, "centroid (small red cross)"});
  } else {
    l.push_back({kCentre, true, "pixel centre (small cross)"});
  }
  if (aa) {
    const Rgb half{mix(kPalette[0].r, 255, 50), mix(kPalette[0].g, 255, 50),
                   mix(kPalette[0].b, 255, 50)};
    l.push_back({half, false, "antialiased line or path area: its colour blended by coverage"});
  }
  return l;
}

Image draw_picture(const PreparedScene& scene, const CoverageMap& coverage, int scale) {
  const int s = scale;
  Image img(scene.width * s + 1, scene.height * s + 1, kBackground);
  draw_coverage(img, scene, coverage, s);
  draw_grid_and_centres(img, scene, coverage, s);
  for (std::size_t p = 0; p < scene.primitives.size(); ++p)
    draw_edges(img, scene.primitives[p], static_cast<std::uint32_t>(p), s);
  if (shows_samples(coverage, s)) {
    const std::uint32_t n = std::min(coverage_sample_count(scene), coverage.sample_count());
    for (std::int32_t j = 0; j < scene.height; ++j)
      for (std::int32_t i = 0; i < scene.width; ++i)
        draw_pixel_samples(img, scene, coverage, i, j, n, s);
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p)
    draw_vertices(img, scene.primitives[p], static_cast<std::uint32_t>(p), s);
  return img;
}

Image draw_depth_picture(std::int32_t width, std::int32_t height, std::uint32_t samples,
                         const std::vector<double>& depth01, int scale) {
  const int s = scale;
  Image img(width * s + 1, height * s + 1, kBackground);
  const std::size_t n = samples;
  for (std::int32_t j = 0; j < height; ++j) {
    for (std::int32_t i = 0; i < width; ++i) {
      const std::size_t base = (static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(i)) *
                               n;
      double sum = 0.0;
      for (std::size_t k = 0; k < n && base + k < depth01.size(); ++k) {
        sum += std::clamp(depth01[base + k], 0.0, 1.0);
      }
      const auto g = static_cast<std::uint8_t>(std::lround(255.0 * sum / static_cast<double>(n)));
      img.fill_rect(i * s, j * s, i * s + s + 1, j * s + s + 1, Rgb{g, g, g});
    }
  }
  if (s >= 3) {
    for (std::int32_t i = 0; i <= width; ++i)
      img.fill_rect(i * s, 0, i * s + 1, img.height(), kGrid);
    for (std::int32_t j = 0; j <= height; ++j)
      img.fill_rect(0, j * s, img.width(), j * s + 1, kGrid);
  }
  return img;
}

} // namespace rastrules::io
