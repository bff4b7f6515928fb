// SPDX-License-Identifier: MIT
// The ladder's plot (BENCH.REPORT): decisions per second relative to the reference (medium
// triangles) against the error fraction, log scales, one labelled point per rung, drawn with a
// 5x7 bitmap font at twice its size. Drawing is for people: nothing is read back from it.
// Implements: BENCH.REPORT (plot)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "rastrules/bench/ladder.hpp"
#include "rastrules/io/text.hpp"

namespace rastrules::bench {

namespace {

// The plot's canvas: an io::Image (white) drawn with colours given as RGB arrays.
struct Canvas {
  io::Image img;
  Canvas(int w, int h) : img(w, h, io::Rgb{255, 255, 255}) {}
  static io::Rgb rgb(std::array<std::uint8_t, 3> c) { return io::Rgb{c[0], c[1], c[2]}; }
  void rect(int x0, int y0, int x1, int y1, std::array<std::uint8_t, 3> c) {
    img.fill_rect(x0, y0, x1, y1, rgb(c));
  }
  // Text with its top-left corner at (x, y), glyphs drawn `scale` times their size.
  void text(int x, int y, const std::string& s, std::array<std::uint8_t, 3> c, int scale = 2) {
    io::draw_text(img, x, y, s, rgb(c), scale);
  }
  // A one-pixel line (for labels' leaders).
  void line_to(int x0, int y0, int x1, int y1, std::array<std::uint8_t, 3> c) {
    img.line(x0, y0, x1, y1, rgb(c));
  }
  static int text_width(const std::string& s, int scale = 2) { return io::text_width(s, scale); }
  [[nodiscard]] Plot plot() const { return Plot{img.width(), img.height(), img.rgb()}; }
};

std::string pow10_label(int e) {
  if (e == 0)
    return "1";
  return "1e" + std::to_string(e);
}

} // namespace

std::array<std::uint8_t, 3> Plot::at(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x)) *
                        3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

// rule: BENCH.REPORT
Plot make_plot(const LadderReport& r) {
  constexpr int kW = 960, kH = 640, kLeft = 110, kRight = 40, kTop = 70, kBottom = 90;
  Canvas cv(kW, kH);
  const std::array<std::uint8_t, 3> black{0, 0, 0}, grey{215, 215, 215};
  // x: error fraction, 10^-7 .. 1; a rung without errors sits on the "0" column left of it.
  constexpr int kXMin = -7, kXMax = 0;
  // y: decisions per second relative to the reference, medium triangles.
  double lo = 1.0, hi = 1.0;
  for (const RungResult& rr : r.rungs) {
    const double v = rr.medium_ratio();
    if (v > 0) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  const int y_min = static_cast<int>(std::floor(std::log10(lo)));
  int y_max = static_cast<int>(std::ceil(std::log10(hi)));
  if (y_max == y_min)
    ++y_max;
  const int px0 = kLeft + 60, px1 = kW - kRight, py0 = kTop, py1 = kH - kBottom;
  const auto map_x = [&](double err) {
    if (err <= 0)
      return kLeft + 20;
    const double l = std::clamp(std::log10(err), double(kXMin), double(kXMax));
    return px0 + static_cast<int>((l - kXMin) / (kXMax - kXMin) * (px1 - px0));
  };
  const auto map_y = [&](double v) {
    const double l = std::log10(v);
    return py1 - static_cast<int>((l - y_min) / (y_max - y_min) * (py1 - py0));
  };
  // Grid and ticks.
  for (int e = kXMin; e <= kXMax; ++e) {
    const int x = map_x(std::pow(10.0, e));
    cv.rect(x, py0, x + 1, py1, grey);
    const std::string s = pow10_label(e);
    cv.text(x - Canvas::text_width(s) / 2, py1 + 10, s, black);
  }
  cv.text(kLeft + 20 - 6, py1 + 10, "0", black);
  for (int e = y_min; e <= y_max; ++e) {
    const int y = map_y(std::pow(10.0, e));
    cv.rect(kLeft, y, px1, y + 1, grey);
    const std::string s = pow10_label(e);
    cv.text(kLeft - 10 - Canvas::text_width(s), y - 7, s, black);
  }
  // Axes.
  cv.rect(kLeft, py1, px1, py1 + 2, black);
  cv.rect(kLeft, py0, kLeft + 2, py1 + 2, black);
  cv.text(px0, kH - 40, "error fraction (decisions differing from exact), log; 0 at left", black);
  cv.text(kLeft, 20, "decisions/s relative to reference (medium triangles), log", black);
  // Points.
  const std::array<std::array<std::uint8_t, 3>, 9> colours = {{{200, 30, 30},
                                                               {230, 120, 0},
                                                               {160, 120, 0},
                                                               {120, 60, 160},
                                                               {0, 110, 200},
                                                               {0, 150, 110},
                                                               {90, 90, 90},
                                                               {0, 0, 0},
                                                               {200, 0, 160}}};
  // Labels right of their point, vertically centred; a label that would overlap one already
  // placed moves down (then up) until it is free, with a leader line back to its point.
  struct Box {
    int x0, y0, x1, y1;
  };
  std::vector<Box> placed;
  const auto overlaps = [&](const Box& b) {
    for (const Box& o : placed)
      if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1)
        return true;
    return false;
  };
  // Each rung with a medium-scene ratio, at its place in the plot, in its colour (the colour
  // follows the rung's index, so it does not change when another rung has no point).
  struct Marker {
    const RungResult* rung;
    int x, y;
    std::array<std::uint8_t, 3> colour;
  };
  std::vector<Marker> markers;
  for (std::size_t k = 0; k < r.rungs.size(); ++k) {
    const RungResult& rr = r.rungs[k];
    const double v = rr.medium_ratio();
    if (v <= 0)
      continue;
    // limit has no error figure: drawn on the "0" column.
    const double err = has_coverage(rr.rung) ? rr.error_fraction() : 0.0;
    markers.push_back({&rr, map_x(err), map_y(v), colours[k % colours.size()]});
  }
  for (const Marker& m : markers) {
    cv.rect(m.x - 5, m.y - 5, m.x + 6, m.y + 6, m.colour);
    placed.push_back({m.x - 5, m.y - 5, m.x + 6, m.y + 6});
  }
  for (const Marker& m : markers) {
    const int x = m.x, y = m.y;
    const auto c = m.colour;
    const std::string label(to_string(m.rung->rung));
    const int w = Canvas::text_width(label);
    Box b{x + 12, y - 7, x + 12 + w, y + 7};
    for (int step = 1; overlaps(b) && step < 40; ++step) {
      const int dy = ((step + 1) / 2) * 16 * (step % 2 == 1 ? 1 : -1);
      b = {x + 12, y - 7 + dy, x + 12 + w, y + 7 + dy};
    }
    if (b.y0 != y - 7)
      cv.line_to(x + 6, y, b.x0 - 2, (b.y0 + b.y1) / 2, c);
    cv.text(b.x0, b.y0, label, c);
    placed.push_back(b);
  }
  return cv.plot();
}

} // namespace rastrules::bench
