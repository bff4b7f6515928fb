// SPDX-License-Identifier: MIT
// The picture of a difference: expected | actual | difference, side by side.
// Implements: FUZZ.REPORT

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>
#include <variant>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/output_file.hpp"
#include "rastrules/io/picture.hpp"

namespace rastrules::fuzzer {
namespace {

constexpr int kGap = 12;
constexpr io::Rgb kGapColour{90, 90, 90};
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

} // namespace

// rule: FUZZ.REPORT
std::optional<std::string> write_difference_png(const std::string& path, const Scene& scene,
                                                const Comparison& c) {
  auto prepared = prepare(scene);
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
  const int pw = expected.width(), ph = expected.height();
  io::Image out(3 * pw + 2 * kGap, ph, kGapColour);
  int x0 = 0;
  for (const io::Image* p : {&expected, &actual, &difference}) {
    for (int y = 0; y < ph; ++y) {
      for (int x = 0; x < pw; ++x)
        out.set(x0 + x, y, p->at(x, y));
    }
    x0 += pw + kGap;
  }
  // Written under a temporary name: a failed write leaves no truncated picture.
  io::OutputFile file;
  if (auto err = file.open(path))
    return err;
  if (auto err = io::write_png(file.get(), out))
    return path + ": " + *err;
  return file.commit();
}

} // namespace rastrules::fuzzer
