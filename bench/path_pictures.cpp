// SPDX-License-Identifier: MIT
// Pictures of the path ladder (BENCH.PATH.PICTURES): exact areas beside FreeType's gray raster
// on the conflation cases, and the ladder's time against error.
// Implements: BENCH.PATH.PICTURES

#include "path_pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <variant>

#include "rastrules/bench/ladder.hpp"
#include "rastrules/io/glyph.hpp"
#include "rastrules/io/text.hpp"
#include "rastrules/path.hpp"

namespace rastrules::bench::paths {

namespace {

namespace kp = rastrules::path;
using io::Image;
using io::Rgb;

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kInk{40, 40, 40};
constexpr Rgb kGrid{215, 215, 215};

// Text with its top-left corner at (x, y) in io's 5x7 font, twice its size unless told.
void text(Image& im, int x, int y, const std::string& s, Rgb c, int scale = 2) {
  io::draw_text(im, x, y, s, c, scale);
}

int text_width(const std::string& s, int scale = 2) {
  return io::text_width(s, scale);
}

// A point in pixels on FreeType's 26.6 grid (raw 16.8, a multiple of 4).
kp::Point at(double x, double y) {
  return {static_cast<std::int32_t>(std::lround(x * 64.0)) * 4,
          static_cast<std::int32_t>(std::lround(y * 64.0)) * 4};
}

kp::Contour polygon(const std::vector<kp::Point>& v) {
  kp::Contour c;
  c.start = v.front();
  for (std::size_t i = 1; i < v.size(); ++i)
    c.segments.push_back({kp::SegmentKind::kLine, {v[i], {}, {}}});
  return c;
}

struct Case {
  std::string label;
  kp::Path path;
  std::int32_t side = 6;
};

std::vector<kp::Point> pentagram(double c, double r) {
  std::vector<kp::Point> v;
  for (int k = 0; k < 5; ++k) {
    const double a = -1.5707963267948966 + 4.0 * 3.141592653589793 * k / 5.0;
    v.push_back(at(c + r * std::cos(a), c + r * std::sin(a)));
  }
  return v;
}

// The showcase's paths-conflation cases, each in its own target, on the 26.6 grid.
std::vector<Case> cases() {
  std::vector<Case> out;
  const std::vector<kp::Point> square{at(1.25, 1.25), at(4.75, 1.25), at(4.75, 4.75),
                                      at(1.25, 4.75)};
  out.push_back(
      {"square twice, evenodd", {kp::FillRule::kEvenOdd, {polygon(square), polygon(square)}}});
  // The diagonal is traversed in the same direction by both triangles, so their windings are
  // +1 and -1: filled everywhere under nonzero, and accumulation cancels along the diagonal.
  out.push_back({"opposite triangles, nonzero",
                 {kp::FillRule::kNonZero,
                  {polygon({at(0.5, 0.5), at(5.5, 5.5), at(0.5, 5.5)}),
                   polygon({at(0.5, 0.5), at(5.5, 5.5), at(5.5, 0.5)})}}});
  out.push_back(
      {"pentagram, evenodd", {kp::FillRule::kEvenOdd, {polygon(pentagram(3.5, 3.2))}}, 7});
  out.push_back(
      {"pentagram, nonzero", {kp::FillRule::kNonZero, {polygon(pentagram(3.5, 3.2))}}, 7});
  out.push_back({"hole, same orientation, nonzero",
                 {kp::FillRule::kNonZero,
                  {polygon({at(0.5, 0.5), at(5.5, 0.5), at(5.5, 5.5), at(0.5, 5.5)}),
                   polygon({at(1.75, 1.75), at(4.25, 1.75), at(4.25, 4.25), at(1.75, 4.25)})}}});
  return out;
}

Rgb shade(double coverage) {
  const auto v =
      static_cast<std::uint8_t>(std::lround(255.0 - 200.0 * std::clamp(coverage, 0.0, 1.0)));
  return {v, v, v};
}

void outline(Image& im, const kp::Path& p, int x0, int y0, int cell, Rgb c) {
  const auto px = [&](kp::Point q) {
    return std::array<double, 2>{x0 + q.x * cell / 256.0, y0 + q.y * cell / 256.0};
  };
  for (const kp::Contour& ct : p.contours) {
    kp::Point a = ct.start;
    for (const kp::Segment& s : ct.segments) {
      const auto u = px(a), v = px(s.p[0]);
      im.line(u[0], u[1], v[0], v[1], c);
      a = s.p[0];
    }
    const auto u = px(a), v = px(ct.start);
    im.line(u[0], u[1], v[0], v[1], c);
  }
}

} // namespace

// rule: BENCH.PATH.PICTURES, PATH.AREA.EXACT
Image conflation_picture(std::vector<std::string>& differing) {
  constexpr int kCell = 22, kGap = 30, kLeft = 150, kTop = 50, kRowGap = 40;
  const std::vector<Case> cs = cases();
  int width = kLeft;
  int side_max = 0;
  for (const Case& c : cs) {
    width += std::max({c.side * kCell, text_width(c.label, 1),
                       text_width("99 px differ, worst 255/255", 1)}) +
             kGap;
    side_max = std::max(side_max, c.side);
  }
  const int row_h = side_max * kCell + kRowGap;
  Image im(width, kTop + 3 * row_h + 40, kWhite);
  text(im, 10, 10, "exact areas (rastrules) vs freetype gray on the same outlines: 8-bit alpha",
       kInk);
  const std::array<std::string, 3> rows{"exact", "freetype", "difference"};
  for (int r = 0; r < 3; ++r)
    text(im, 10, kTop + r * row_h + side_max * kCell / 2 - 7, rows[static_cast<std::size_t>(r)],
         kInk);
  text(im, 10, kTop + 3 * row_h + 5,
       "difference: red = freetype higher, blue = lower, white = within one level", kInk, 1);
  int x0 = kLeft;
  differing.clear();
  for (const Case& c : cs) {
    const std::int32_t n = c.side;
    std::vector<double> exact(static_cast<std::size_t>(n * n), 0.0);
    std::vector<int> exact_alpha(exact.size(), 0);
    for (const kp::AreaCoverage& a : kp::cover_area(c.path, n, n)) {
      const std::size_t k = static_cast<std::size_t>(a.y * n + a.x);
      exact[k] = a.area.convert_to<double>();
      // alpha = floor(area * 255 + 1/2), exactly (SCENE.OUTPUT.AREA)
      const boost::multiprecision::cpp_rational s =
          a.area * 255 + boost::multiprecision::cpp_rational(1, 2);
      exact_alpha[k] = static_cast<int>(boost::multiprecision::cpp_int(
          boost::multiprecision::numerator(s) / boost::multiprecision::denominator(s)));
    }
    auto ft = io::freetype_outline_of(io::Glyph{c.path, n, n, 0, 0});
    if (const auto* e = std::get_if<io::GlyphError>(&ft))
      throw std::runtime_error(e->what());
    io::GlyphBitmap gray;
    std::get<io::FreeTypeGlyph>(ft).render_gray(gray);
    int count = 0, worst = 0;
    for (std::int32_t y = 0; y < n; ++y)
      for (std::int32_t x = 0; x < n; ++x) {
        const std::size_t k = static_cast<std::size_t>(y * n + x);
        const int g = gray.at(x, y), d = g - exact_alpha[k];
        const int cx = x0 + x * kCell, cy = kTop + y * kCell;
        im.fill_rect(cx, cy, cx + kCell, cy + kCell, shade(exact[k]));
        im.fill_rect(cx, cy + row_h, cx + kCell, cy + row_h + kCell, shade(g / 255.0));
        Rgb diff = kWhite;
        if (std::abs(d) > 1) {
          ++count;
          worst = std::max(worst, std::abs(d));
          const auto t =
              static_cast<std::uint8_t>(std::lround(255.0 - 200.0 * std::abs(d) / 255.0));
          diff = d > 0 ? Rgb{255, t, t} : Rgb{t, t, 255};
        }
        im.fill_rect(cx, cy + 2 * row_h, cx + kCell, cy + 2 * row_h + kCell, diff);
      }
    for (int r = 0; r < 3; ++r) {
      const int top = kTop + r * row_h;
      for (int i = 0; i <= n; ++i) {
        im.line(x0 + i * kCell, top, x0 + i * kCell, top + n * kCell, kGrid);
        im.line(x0, top + i * kCell, x0 + n * kCell, top + i * kCell, kGrid);
      }
      outline(im, c.path, x0, top, kCell, Rgb{200, 90, 20});
    }
    text(im, x0, kTop - 14, c.label, kInk, 1);
    const std::string summary = std::to_string(count) + " px differ" +
                                (count > 0 ? ", worst " + std::to_string(worst) + "/255" : "");
    text(im, x0, kTop + 2 * row_h + n * kCell + 6, summary, kInk, 1);
    differing.push_back(c.label + ": " + summary);
    x0 += std::max(
              {n * kCell, text_width(c.label, 1), text_width("99 px differ, worst 255/255", 1)}) +
          kGap;
  }
  return im;
}

// rule: BENCH.PATH.PICTURES
Image ladder_plot(const std::vector<PlotPoint>& points) {
  constexpr int kW = 900, kH = 560, kL = 110, kR = 200, kT = 50, kB = 70;
  // Errors below 1e-9 (the oracle's: the double nearest its exact area) are drawn on the
  // 1e-9 line as open circles.
  constexpr double kFloor = -9;
  Image im(kW, kH, kWhite);
  std::map<std::string, double> ft; // FreeType gray's time per scene
  for (const PlotPoint& p : points)
    if (p.rung == "freetype-gray")
      ft[p.scene] = p.seconds;
  // x: log10(time / FreeType gray's), y: log10(mean error), 0 error on its own line.
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  std::vector<std::array<double, 2>> xy(points.size(), {0, 0});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const PlotPoint& p = points[i];
    const auto f = ft.find(p.scene);
    if (f == ft.end() || f->second <= 0 || p.seconds <= 0)
      continue;
    xy[i][0] = std::log10(p.seconds / f->second);
    xmin = std::min(xmin, xy[i][0]);
    xmax = std::max(xmax, xy[i][0]);
    if (p.mean_error > 0) {
      xy[i][1] = std::max(std::log10(p.mean_error), kFloor);
      ymin = std::min(ymin, xy[i][1]);
      ymax = std::max(ymax, xy[i][1]);
    }
  }
  if (xmin > xmax)
    return im;
  xmin = std::floor(xmin);
  xmax = std::ceil(xmax);
  if (ymin > ymax)
    ymin = ymax = -3;
  ymin = std::floor(ymin);
  ymax = std::ceil(ymax);
  if (xmax == xmin)
    xmax += 1;
  if (ymax == ymin)
    ymax += 1;
  const int zero_y = kH - kB + 25; // the line of exact rungs (error 0)
  const auto sx = [&](double v) { return kL + (v - xmin) / (xmax - xmin) * (kW - kL - kR); };
  const auto sy = [&](double v) { return kT + (ymax - v) / (ymax - ymin) * (kH - kT - kB - 10); };
  text(im, kL, 12, "path ladder: time against error (all scenes)", kInk);
  for (double v = xmin; v <= xmax + 1e-9; v += 1) {
    im.line(sx(v), kT, sx(v), zero_y, kGrid);
    const std::string l = v == 0  ? "1x"
                          : v > 0 ? "1e" + std::to_string(static_cast<int>(v)) + "x"
                                  : "1e" + std::to_string(static_cast<int>(v)) + "x";
    text(im, static_cast<int>(sx(v)) - text_width(l, 1) / 2, zero_y + 8, l, kInk, 1);
  }
  for (double v = ymin; v <= ymax + 1e-9; v += 1) {
    im.line(kL, sy(v), kW - kR, sy(v), kGrid);
    const std::string l = (v == kFloor ? "<=1e" : "1e") + std::to_string(static_cast<int>(v));
    text(im, kL - text_width(l, 1) - 6, static_cast<int>(sy(v)) - 3, l, kInk, 1);
  }
  im.line(kL, zero_y - 4, kW - kR, zero_y - 4, kGrid, 3);
  text(im, kL - text_width("0", 1) - 6, zero_y - 7, "0", kInk, 1);
  text(im, kL, kH - 22, "time relative to freetype gray on the same scene (log)", kInk, 1);
  text(im, 8, kT - 18, "mean error (log; open: below 1e-9)", kInk, 1);
  const std::array<Rgb, 8> palette{Rgb{31, 119, 180},  Rgb{255, 127, 14},  Rgb{44, 160, 44},
                                   Rgb{214, 39, 40},   Rgb{148, 103, 189}, Rgb{140, 86, 75},
                                   Rgb{227, 119, 194}, Rgb{90, 90, 90}};
  std::map<std::string, Rgb> colour;
  for (const PlotPoint& p : points)
    if (!colour.count(p.rung))
      colour[p.rung] = palette[colour.size() % palette.size()];
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!ft.count(points[i].scene) || points[i].seconds <= 0)
      continue;
    const int x = static_cast<int>(std::lround(sx(xy[i][0])));
    const int y =
        points[i].mean_error > 0 ? static_cast<int>(std::lround(sy(xy[i][1]))) : zero_y - 4;
    const bool below = points[i].mean_error > 0 && std::log10(points[i].mean_error) < kFloor;
    im.disc(x, y, 4, colour[points[i].rung], !below);
  }
  int ly = kT;
  for (const auto& [rung, c] : colour) {
    im.disc(kW - kR + 24, ly + 6, 5, c, true);
    text(im, kW - kR + 36, ly, rung, kInk);
    ly += 24;
  }
  return im;
}

} // namespace rastrules::bench::paths
