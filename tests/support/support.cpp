// SPDX-License-Identifier: MIT
// Helpers for the example tests (see support.hpp).

#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rastrules/raster/walk.hpp"
#include "rastrules/snap.hpp"

namespace rastrules::test {

std::ostream& operator<<(std::ostream& os, const Pixel& p) {
  return os << "(" << p.x << ", " << p.y << ")";
}

Subpixel snap_px(double v) {
  const auto f = static_cast<float>(v);
  if (static_cast<double>(f) != v) {
    throw std::invalid_argument("snap_px: " + std::to_string(v) + " is not a float32");
  }
  const SnapResult r = snap_to_subpixel(f);
  if (r.status != SnapStatus::kOk) {
    throw std::invalid_argument("snap_px: " + std::to_string(v) + " " +
                                std::string(to_string(r.status)));
  }
  return r.value;
}

namespace {

Subpixel exact_subpixel(double v) {
  const double scaled = v * kSubpixelOne;
  if (scaled != std::floor(scaled) || scaled < kMinVertexRaw || scaled > kMaxVertexRaw) {
    throw std::invalid_argument("sample_px: " + std::to_string(v) + " is not on the 16.8 grid");
  }
  return Subpixel::from_raw(static_cast<std::int32_t>(scaled));
}

} // namespace

Vec2 sample_px(double x, double y) {
  return Vec2{exact_subpixel(x), exact_subpixel(y)};
}

TriangleSetup triangle_px(Px a, Px b, Px c, const RasterState& state) {
  const std::array<Vec2, 3> v{Vec2{snap_px(a.x), snap_px(a.y)}, Vec2{snap_px(b.x), snap_px(b.y)},
                              Vec2{snap_px(c.x), snap_px(c.y)}};
  return setup_triangle(v, state);
}

std::vector<Pixel> walk_pixels(const TriangleSetup& t, std::int32_t width, std::int32_t height) {
  std::vector<Pixel> out;
  raster::walk_triangle(t, width, height, [&](std::int32_t x, std::int32_t y) {
    out.push_back(Pixel{x, y});
  });
  return out;
}

std::vector<Pixel> centre_pixels(const TriangleSetup& t, std::int32_t width, std::int32_t height) {
  std::vector<Pixel> out;
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      if (covers(t, pixel_center(x, y)))
        out.push_back(Pixel{x, y});
    }
  }
  return out;
}

std::vector<Pixel> pixels_in_picture(std::initializer_list<std::string_view> rows, char mark) {
  std::vector<Pixel> out;
  std::int32_t y = 0;
  for (const std::string_view row : rows) {
    for (std::size_t x = 0; x < row.size(); ++x) {
      if (row[x] == mark)
        out.push_back(Pixel{static_cast<std::int32_t>(x), y});
    }
    ++y;
  }
  return out;
}

std::string picture(const std::vector<Pixel>& pixels, std::int32_t width, std::int32_t height) {
  std::string s;
  for (std::int32_t y = 0; y < height; ++y) {
    s += '\n';
    for (std::int32_t x = 0; x < width; ++x) {
      s += std::find(pixels.begin(), pixels.end(), Pixel{x, y}) != pixels.end() ? '#' : '.';
    }
  }
  return s;
}

Scene scene_px(std::int32_t width, std::int32_t height, const RasterState& state,
               std::initializer_list<std::array<Px, 3>> triangles) {
  Scene s;
  s.width = width;
  s.height = height;
  s.state = state;
  for (const auto& t : triangles) {
    Primitive p;
    for (std::size_t i = 0; i < 3; ++i) {
      p.v[i] = {static_cast<float>(t[i].x), static_cast<float>(t[i].y)};
    }
    s.primitives.push_back(p);
  }
  return s;
}

std::vector<Pixel> pixels_of(const std::vector<Fragment>& fragments, std::uint32_t prim) {
  std::vector<Pixel> out;
  for (const Fragment& f : fragments) {
    if (f.prim == prim)
      out.push_back(Pixel{f.x, f.y});
  }
  return out;
}

} // namespace rastrules::test
