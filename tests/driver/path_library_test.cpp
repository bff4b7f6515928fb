// SPDX-License-Identifier: MIT
// Examples for the 2D library adapters (DRIVER.PATH.*): what each library reports for paths
// whose coverage is known without a rasterizer (pixel-aligned squares, a half pixel), and the
// scenes each refuses.

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

FloatContour polygon(const std::vector<FloatPoint>& pts) {
  FloatContour c;
  c.start = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    FloatPathSegment s;
    s.p[0] = pts[i];
    c.segments.push_back(s);
  }
  return c;
}

Scene path_scene(std::vector<FloatContour> contours, path::Coverage coverage,
                 path::FillRule rule = path::FillRule::kNonZero, std::int32_t side = 8) {
  Scene s;
  s.width = s.height = side;
  FloatPath p;
  p.fill_rule = rule;
  p.coverage = coverage;
  p.contours = std::move(contours);
  s.primitives.push_back(make_path(std::move(p)));
  return s;
}

std::unique_ptr<Driver> open(const std::string& name) {
  std::string error;
  auto d = open_driver(name, &error);
  EXPECT_NE(d, nullptr) << error;
  return d;
}

std::vector<Fragment> draw_ok(Driver& d, const Scene& s) {
  EXPECT_EQ(d.unsupported(s), "");
  DrawResult r = d.draw(s);
  if (const auto* e = std::get_if<DriverError>(&r)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return std::get<std::vector<Fragment>>(r);
}

const std::vector<FloatPoint> kSquare = {{2, 1}, {5, 1}, {5, 4}, {2, 4}};

// rule: DRIVER.PATH.LIBRARY, DRIVER.PATH.FREETYPE
TEST(PathLibraryFreeType, APixelAlignedSquareCoversItsPixelsAliasedAndAtFullAlpha) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  EXPECT_TRUE(d->info().paths.samples && d->info().paths.area);
  EXPECT_EQ(d->info().paths.grid, "26.6");
  for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
    const auto frags = draw_ok(*d, path_scene({polygon(kSquare)}, coverage));
    ASSERT_EQ(frags.size(), 9u) << to_string(coverage);
    for (const Fragment& f : frags) {
      EXPECT_GE(f.x, 2);
      EXPECT_LE(f.x, 4);
      EXPECT_GE(f.y, 1);
      EXPECT_LE(f.y, 3);
      EXPECT_EQ(f.mask, 1u);
      if (coverage == path::Coverage::kArea)
        EXPECT_EQ(f.area.text(), "1");
      else
        EXPECT_FALSE(f.area);
    }
  }
}

// rule: DRIVER.PATH.FREETYPE
TEST(PathLibraryFreeType, AHalfPixelTriangleGetsHalfAlphaAndEvenOddEmptiesATwiceDrawnSquare) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  const auto half =
      draw_ok(*d, path_scene({polygon({{1, 1}, {2, 1}, {2, 2}})}, path::Coverage::kArea));
  ASSERT_EQ(half.size(), 1u);
  EXPECT_EQ(half[0].x, 1);
  EXPECT_EQ(half[0].y, 1);
  // 1/2 px^2 as 8-bit alpha: FreeType stores 127 or 128.
  EXPECT_GE(half[0].area.alpha(), 127);
  EXPECT_LE(half[0].area.alpha(), 128);
  const auto twice = draw_ok(*d, path_scene({polygon(kSquare), polygon(kSquare)},
                                            path::Coverage::kArea, path::FillRule::kEvenOdd));
  EXPECT_TRUE(twice.empty());
  const auto nonzero =
      draw_ok(*d, path_scene({polygon(kSquare), polygon(kSquare)}, path::Coverage::kArea));
  EXPECT_EQ(nonzero.size(), 9u);
}

// rule: DRIVER.PATH.LIBRARY
TEST(PathLibraryFreeType, RefusesTrianglesMultisamplingAndPointsOffItsGrid) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  Scene tri;
  tri.width = tri.height = 4;
  tri.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  EXPECT_EQ(d->unsupported(tri), "primitives[0]: freetype draws paths only");
  Scene msaa = path_scene({polygon(kSquare)}, path::Coverage::kSamples);
  set_sample_pattern(msaa, standard_pattern(4));
  EXPECT_EQ(d->unsupported(msaa), "freetype draws one sample at the pixel centre");
  // 1/256 px is not on 26.6 (1/64 px).
  const Scene fine =
      path_scene({polygon({{1, 1}, {2.00390625f, 1}, {2, 2}})}, path::Coverage::kSamples);
  EXPECT_EQ(d->unsupported(fine),
            "primitives[0]: control point (513, 256) raw is not on freetype's 26.6 grid");
  EXPECT_EQ(d->info().triangles, false);
}

} // namespace
} // namespace rastrules::driver
