// SPDX-License-Identifier: MIT
// The picture of a difference: expected | actual | difference, side by side, each panel titled,
// pixel coordinates on the axes, and a legend of the colours below.
// Implements: FUZZ.REPORT

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <variant>

#include "legend.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/output_file.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/text.hpp"

namespace rastrules::fuzzer {
namespace {

constexpr int kGap = 12;
constexpr io::Rgb kInk{30, 30, 30};
constexpr io::Rgb kFaint{110, 110, 110};
constexpr io::Rgb kFrame{175, 175, 175};       // the pixel grid's grey
constexpr io::Rgb kMissingFill{170, 200, 255}; // the reference covers it, the driver does not
constexpr io::Rgb kExtraFill{255, 175, 175};   // the driver covers it, the reference does not
constexpr io::Rgb kMissingDot{20, 60, 220};
constexpr io::Rgb kExtraDot{220, 20, 20};
constexpr io::Rgb kCoveredDot{30, 30, 30};
constexpr io::Rgb kOpenDot{160, 160, 160};

std::vector<SampleOffset> sample_offsets(const Scene& scene) {
  return scene.msaa.pattern.positions;
}

void dot(io::Image& img, double cx, double cy, int radius, io::Rgb c) {
  const int x = static_cast<int>(cx), y = static_cast<int>(cy);
  img.fill_rect(x - radius, y - radius, x + radius + 1, y + radius + 1, c);
}

// Sample points of every pixel of a panel: covered samples dark, others grey (or the
// difference colours).
void draw_samples(io::Image& img, const Scene& scene, int scale,
                  const std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>& covered,
                  const std::map<std::pair<std::int32_t, std::int32_t>,
                                 std::pair<std::uint32_t, std::uint32_t>>* diff) {
  const auto offsets = sample_offsets(scene);
  const int radius = scale >= 24 ? 2 : (scale >= 8 ? 1 : 0);
  for (std::int32_t y = 0; y < scene.height; ++y) {
    for (std::int32_t x = 0; x < scene.width; ++x) {
      const auto it = covered.find({x, y});
      const std::uint32_t mask = it == covered.end() ? 0 : it->second;
      std::uint32_t missing = 0, extra = 0;
      if (diff != nullptr) {
        if (const auto d = diff->find({x, y}); d != diff->end())
          std::tie(missing, extra) = d->second;
      }
      for (std::size_t k = 0; k < offsets.size(); ++k) {
        const double cx = (x + 0.5 + offsets[k].x / 16.0) * scale;
        const double cy = (y + 0.5 + offsets[k].y / 16.0) * scale;
        const std::uint32_t bit = std::uint32_t{1} << k;
        io::Rgb c = (mask & bit) != 0 ? kCoveredDot : kOpenDot;
        if ((missing & bit) != 0)
          c = kMissingDot;
        if ((extra & bit) != 0)
          c = kExtraDot;
        if (offsets.size() == 1 && c == kOpenDot)
          continue; // the picture shows the centre already
        dot(img, cx, cy, radius, c);
      }
    }
  }
}

io::Image panel(const PreparedScene& prepared, const Scene& scene,
                const std::vector<Fragment>& fragments, int scale) {
  io::CoverageMap map(scene.width, scene.height);
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> covered;
  for (const Fragment& f : fragments) {
    map.add(f.prim, f.x, f.y);
    covered[{f.x, f.y}] |= f.mask;
  }
  io::Image img = io::draw_picture(prepared, map, scale);
  draw_samples(img, scene, scale, covered, nullptr);
  return img;
}

io::Image difference_panel(const PreparedScene& prepared, const Scene& scene, const Comparison& c,
                           int scale) {
  io::CoverageMap empty(scene.width, scene.height);
  io::Image img = io::draw_picture(prepared, empty, scale);
  std::map<std::pair<std::int32_t, std::int32_t>, std::pair<std::uint32_t, std::uint32_t>> diff;
  for (const DiffEntry& d : c.missing)
    diff[{d.x, d.y}].first |= d.mask;
  for (const DiffEntry& d : c.extra)
    diff[{d.x, d.y}].second |= d.mask;
  // Tint the background of differing pixels, keeping the grid, edges and centres drawn on it.
  for (const auto& [xy, me] : diff) {
    const io::Rgb tint = me.second != 0 ? kExtraFill : kMissingFill;
    for (int iy = xy.second * scale + 1; iy < (xy.second + 1) * scale; ++iy) {
      for (int ix = xy.first * scale + 1; ix < (xy.first + 1) * scale; ++ix) {
        if (img.at(ix, iy) == io::kBackground)
          img.set(ix, iy, tint);
      }
    }
  }
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> agreed;
  for (const Fragment& f : c.expected)
    agreed[{f.x, f.y}] |= f.mask;
  draw_samples(img, scene, scale, agreed, &diff);
  return img;
}

// Returns the first of 1, 2, 5, 10, 20, 50, ... at which labels `width` image pixels wide,
// one every `step` target pixels of `scale` image pixels, do not touch.
int tick_step(int width, int scale) {
  for (int step = 1;; step *= 10) {
    for (const int m : {1, 2, 5})
      if (step * m * scale >= width + 4)
        return step * m;
  }
}

// Lays the three panels out in a figure: a title and a subtitle above each, pixel x
// coordinates above each panel and y coordinates left of the first, the legend below.
// rule: FUZZ.REPORT
io::Image figure(const Scene& scene, const Comparison& c, int scale,
                 const std::array<const io::Image*, 3>& panels) {
  constexpr int kTitle = 2; // titles and the legend at twice the font's size
  constexpr int kMargin = 10;
  constexpr int kLine = io::kGlyphHeight * kTitle;
  const std::array<std::string, 3> titles = {"expected", "actual", "difference"};
  const std::array<std::string, 3> subtitles = {
      "reference, " + std::string(to_string(c.compared_with)) + " fill", "the driver",
      std::to_string(c.missing.size()) + " missing, " + std::to_string(c.extra.size()) + " extra"};
  const int pw = panels[0]->width(), ph = panels[0]->height();
  // Each panel in a column wide enough for its titles.
  int column = pw;
  for (std::size_t k = 0; k < 3; ++k)
    column = std::max({column, io::text_width(titles[k], kTitle), io::text_width(subtitles[k])});
  const std::int32_t w = scene.width, h = scene.height;
  const int y_label = io::text_width(std::to_string(h - 1));
  const int x_step = tick_step(io::text_width(std::to_string(w - 1)), scale);
  const int y_step = tick_step(io::kGlyphHeight, scale);
  const int left = kMargin + y_label + 6;
  const int top = kMargin + kLine + 4 + io::kGlyphHeight + 6 + io::kGlyphHeight + 4;
  const std::vector<LegendLine> lines = difference_legend(scene);
  int legend_w = 0;
  for (const LegendLine& l : lines)
    legend_w = std::max(legend_w, 22 + io::text_width(l.text, kTitle));
  const int legend_top = top + ph + 14;
  const int width = std::max(left + 3 * column + 2 * kGap, kMargin + legend_w) + kMargin;
  const int height = legend_top + static_cast<int>(lines.size()) * (kLine + 5) + kMargin;
  io::Image out(width, height, io::kBackground);
  for (std::size_t k = 0; k < 3; ++k) {
    const int cx = left + static_cast<int>(k) * (column + kGap);
    const int x0 = cx + (column - pw) / 2;
    io::draw_text(out, cx, kMargin, titles[k], kInk, kTitle);
    io::draw_text(out, cx, kMargin + kLine + 4, subtitles[k], kFaint);
    for (int y = 0; y < ph; ++y)
      for (int x = 0; x < pw; ++x)
        out.set(x0 + x, top + y, panels[k]->at(x, y));
    for (std::int32_t i = 0; i < w; i += x_step) {
      const std::string t = std::to_string(i);
      io::draw_text(out, x0 + i * scale + scale / 2 - io::text_width(t) / 2 + 1,
                    top - 4 - io::kGlyphHeight, t, kInk);
    }
    if (k == 0) {
      for (std::int32_t j = 0; j < h; j += y_step) {
        const std::string t = std::to_string(j);
        io::draw_text(out, x0 - 6 - io::text_width(t) + 1,
                      top + j * scale + scale / 2 - io::kGlyphHeight / 2, t, kInk);
      }
    }
  }
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const LegendLine& l = lines[n];
    const int y = legend_top + static_cast<int>(n) * (kLine + 5);
    out.fill_rect(kMargin, y, kMargin + kLine, y + kLine, kFrame);
    out.fill_rect(kMargin + 1, y + 1, kMargin + kLine - 1, y + kLine - 1,
                  l.dot ? io::kBackground : l.colour);
    if (l.dot)
      out.fill_rect(kMargin + kLine / 2 - 3, y + kLine / 2 - 3, kMargin + kLine / 2 + 4,
                    y + kLine / 2 + 4, l.colour);
    io::draw_text(out, kMargin + 22, y, l.text, kInk, kTitle);
  }
  return out;
}

} // namespace

// rule: FUZZ.REPORT
std::vector<LegendLine> difference_legend(const Scene& scene) {
  const bool samples = scene.msaa.pattern.positions.size() > 1;
  std::vector<LegendLine> l = {
      {io::cover_colour(0), false, "pixel covered (in its primitive's colour)"},
      {io::kOverlapMark, false, "pixel covered by more than one primitive (hatched)"},
      {kMissingFill, false, "difference: covered by the reference only (missing)"},
      {kExtraFill, false, "difference: covered by the driver only (extra)"}};
  if (samples) {
    l.push_back({kCoveredDot, true, "sample covered"});
    l.push_back({kOpenDot, true, "sample not covered"});
  } else {
    l.push_back({kCoveredDot, true, "pixel centre covered"});
  }
  l.push_back(
      {kMissingDot, true, samples ? "sample the driver misses" : "centre the driver misses"});
  l.push_back({kExtraDot, true, samples ? "sample the driver adds" : "centre the driver adds"});
  l.push_back({io::edge_colour(0), false,
               "snapped edges and vertices (dashed grey: culled or degenerate)"});
  l.push_back({kFrame, false, "pixel grid: x to the right, y down, pixel (0, 0) at the top left"});
  return l;
}

// rule: FUZZ.REPORT
std::optional<std::string> write_difference_png(const std::string& path, const Scene& scene,
                                                const Comparison& c) {
  // A pipeline scene's primitives are drawn by run_pipeline: the panels show its target and
  // fragments without edges (its clipped, snapped primitives are not the scene's).
  auto prepared = prepare(has_pipeline_state(scene) ? target_of(scene) : scene);
  if (auto* e = std::get_if<SceneError>(&prepared))
    return e->what();
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  // Three panels and two gaps within kMaxPictureSide.
  // Magnified as much as fits, up to kMaxScale image pixels per target pixel (shrunk scenes
  // are often 1x1 or 2x2 targets).
  constexpr int kMaxScale = 96;
  const std::int64_t across =
      (io::kMaxPictureSide - 2 * kGap - 3) / (3 * std::int64_t{scene.width});
  const std::int64_t down = (io::kMaxPictureSide - 1) / std::int64_t{scene.height};
  const int scale = static_cast<int>(std::min<std::int64_t>({across, down, kMaxScale}));
  if (scale < 1 || !io::picture_fits(scene.width, scene.height, scale)) {
    return std::string("the target is too large for a picture");
  }
  const io::Image expected = panel(ps, scene, c.expected, scale);
  const io::Image actual = panel(ps, scene, c.actual, scale);
  const io::Image difference = difference_panel(ps, scene, c, scale);
  const io::Image out = figure(scene, c, scale, {&expected, &actual, &difference});
  // Written under a temporary name: a failed write leaves no truncated picture.
  io::OutputFile file;
  if (auto err = file.open(path))
    return err;
  if (auto err = io::write_png(file.get(), out))
    return path + ": " + *err;
  return file.commit();
}

} // namespace rastrules::fuzzer
