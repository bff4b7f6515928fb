// SPDX-License-Identifier: MIT
// Examples for the sample patterns: the standard tables checked against two independent
// sources (the legends of the D3D pictures img/MSAAPatterns_2_4.png and _8_16.png, transcribed
// verbatim, and Vulkan's standard-sample-locations table in [0,1), spec-anchors.md section 8),
// the sample grid, exact sample positions, centre and custom patterns.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// Parses a D3D picture legend such as "{ (4,4),(-4,-4) }" into offsets.
std::vector<SampleOffset> parse_legend(std::string_view s) {
  std::vector<SampleOffset> out;
  std::size_t i = 0;
  auto number = [&]() {
    std::size_t j = i;
    while (j < s.size() && (s[j] == '-' || (s[j] >= '0' && s[j] <= '9')))
      ++j;
    const int v = std::stoi(std::string(s.substr(i, j - i)));
    i = j;
    return v;
  };
  while ((i = s.find('(', i)) != std::string_view::npos) {
    ++i;
    const int x = number();
    i = s.find(',', i) + 1;
    while (s[i] == ' ')
      ++i;
    const int y = number();
    out.push_back(SampleOffset{static_cast<std::int8_t>(x), static_cast<std::int8_t>(y)});
  }
  return out;
}

// Converts a Vulkan location (decimal in [0, 1), from the fragment's top-left corner) to an
// offset in 1/16 px from the centre: v * 16 - 8, which must be an integer.
int vulkan_to_offset(std::string_view dec) {
  // Exact decimal arithmetic: dec = n / 10^k.
  std::int64_t n = 0, den = 1;
  bool frac = false;
  for (const char c : dec) {
    if (c == '.') {
      frac = true;
      continue;
    }
    n = n * 10 + (c - '0');
    if (frac)
      den *= 10;
  }
  EXPECT_EQ((n * 16) % den, 0) << dec << " is not a multiple of 1/16";
  return static_cast<int>(n * 16 / den) - 8;
}

std::vector<SampleOffset> parse_vulkan(std::string_view s) {
  std::vector<SampleOffset> out;
  std::size_t i = 0;
  while ((i = s.find('(', i)) != std::string_view::npos) {
    const std::size_t comma = s.find(',', i), close = s.find(')', i);
    const int x = vulkan_to_offset(s.substr(i + 1, comma - i - 1));
    const int y = vulkan_to_offset(s.substr(comma + 1, close - comma - 1));
    out.push_back(SampleOffset{static_cast<std::int8_t>(x), static_cast<std::int8_t>(y)});
    i = close;
  }
  return out;
}

struct Source {
  std::uint32_t n;
  std::string_view d3d_legend; // verbatim from the D3D picture
  std::string_view vulkan;     // verbatim from Vulkan's table
};

// The legends as printed next to each D3D pattern picture; the Vulkan rows as in primsrast.adoc.
const Source kSources[] = {
    {1, "{ (0,0) }", "(0.5,0.5)"},
    {2, "{ (4,4),(-4,-4) }", "(0.75,0.75), (0.25,0.25)"},
    {4, "{ (-2,-6),(6,-2),(-6,2),(2,6) }",
     "(0.375,0.125), (0.875,0.375), (0.125,0.625), (0.625,0.875)"},
    {8, "{ (1,-3), (-1,3), (5,1), (-3,-5), (-5,5), (-7,-1), (3,7), (7,-7) }",
     "(0.5625,0.3125), (0.4375,0.6875), (0.8125,0.5625), (0.3125,0.1875), (0.1875,0.8125), "
     "(0.0625,0.4375), (0.6875,0.9375), (0.9375,0.0625)"},
    {16,
     "{ (1,1), (-1,-3), (-3,2), (4,-1), (-5,-2), (2,5), (5,3), (3,-5), (-2,6), (0,-7), (-4,-6), "
     "(-6,4), (-8,0), (7,-4), (6,7), (-7,-8) }",
     "(0.5625,0.5625), (0.4375,0.3125), (0.3125,0.625), (0.75,0.4375), (0.1875,0.375), "
     "(0.625,0.8125), (0.8125,0.6875), (0.6875,0.1875), (0.375,0.875), (0.5,0.0625), "
     "(0.25,0.125), (0.125,0.75), (0.0,0.5), (0.9375,0.25), (0.875,0.9375), (0.0625,0.0)"},
};

// rule: MSAA.PATTERN.STANDARD
TEST(PatternStandard, EqualsTheD3DPictureLegends) {
  for (const Source& src : kSources) {
    const SamplePattern p = standard_pattern(src.n);
    EXPECT_EQ(p.kind, PatternKind::kStandard);
    EXPECT_EQ(p.count(), src.n);
    EXPECT_EQ(p.positions, parse_legend(src.d3d_legend)) << src.n << " samples";
  }
}

// rule: MSAA.PATTERN.STANDARD
TEST(PatternStandard, EqualsVulkansTableIndexForIndex) {
  for (const Source& src : kSources) {
    EXPECT_EQ(standard_pattern(src.n).positions, parse_vulkan(src.vulkan)) << src.n << " samples";
  }
}

// rule: MSAA.PATTERN.STANDARD
TEST(PatternStandard, DotsReadOffThePicturesGrids) {
  // Read from the grids of the pictures (not the legends), in reading order top to bottom:
  // the set of positions must match, whatever the index order.
  auto sorted = [](std::vector<SampleOffset> v) {
    std::sort(v.begin(), v.end(),
              [](SampleOffset a, SampleOffset b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    return v;
  };
  EXPECT_EQ(sorted(standard_pattern(4).positions),
            (std::vector<SampleOffset>{{-2, -6}, {6, -2}, {-6, 2}, {2, 6}}));
  EXPECT_EQ(sorted(standard_pattern(8).positions),
            (std::vector<SampleOffset>{
                {7, -7}, {-3, -5}, {1, -3}, {-7, -1}, {5, 1}, {-1, 3}, {-5, 5}, {3, 7}}));
  // The 16-sample picture puts samples on both reachable edges: (-8, 0) and (-7, -8).
  const auto p16 = standard_pattern(16).positions;
  EXPECT_NE(std::find(p16.begin(), p16.end(), SampleOffset{-8, 0}), p16.end());
  EXPECT_NE(std::find(p16.begin(), p16.end(), SampleOffset{-7, -8}), p16.end());
}

// rule: MSAA.PATTERN.STANDARD
TEST(PatternStandard, OnlyPowersOfTwoUpTo16HaveOne) {
  for (std::uint32_t n = 0; n <= 33; ++n) {
    EXPECT_EQ(is_standard_count(n), n == 1 || n == 2 || n == 4 || n == 8 || n == 16) << n;
  }
}

// rule: MSAA.PATTERN.GRID
TEST(PatternGrid, LeftAndTopEdgesReachableRightAndBottomNot) {
  EXPECT_TRUE(on_sample_grid(-8, -8));
  EXPECT_TRUE(on_sample_grid(7, 7));
  EXPECT_FALSE(on_sample_grid(8, 0));
  EXPECT_FALSE(on_sample_grid(0, 8));
  EXPECT_FALSE(on_sample_grid(-9, 0));
  EXPECT_FALSE(on_sample_grid(0, -9));
  for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
    for (const SampleOffset o : standard_pattern(n).positions) {
      EXPECT_TRUE(on_sample_grid(o.x, o.y)) << n;
    }
  }
  // Sample (-8, -8) of pixel (3, 2) is the pixel's top-left corner; (7, 7) is 1/16 px short of
  // the bottom-right corner.
  EXPECT_EQ(sample_position(3, 2, SampleOffset{-8, -8}), sample_px(3.0, 2.0));
  EXPECT_EQ(sample_position(3, 2, SampleOffset{7, 7}), sample_px(3.9375, 2.9375));
}

// rule: MSAA.SAMPLE.POSITION
TEST(SamplePosition, IsTheCentrePlusSixteenRawUnitsPerStep) {
  EXPECT_EQ(kSampleGridUnit, 16);
  const Vec2 s = sample_position(5, 7, SampleOffset{-3, 6});
  EXPECT_EQ(s.x.raw(), 256 * 5 + 128 - 48);
  EXPECT_EQ(s.y.raw(), 256 * 7 + 128 + 96);
  // The farthest sample of the largest target stays inside the vertex range.
  const Vec2 far = sample_position(kMaxTargetSide - 1, kMaxTargetSide - 1, SampleOffset{7, 7});
  EXPECT_LE(far.x.raw(), kMaxVertexRaw);
  EXPECT_EQ(sample_position(0, 0, SampleOffset{-8, -8}), sample_px(0.0, 0.0));
}

// rule: MSAA.PATTERN.CENTER
TEST(PatternCenter, EverySampleAtTheCentre) {
  for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
    const SamplePattern p = center_pattern(n);
    EXPECT_EQ(p.kind, PatternKind::kCenter);
    EXPECT_EQ(p.count(), n);
    for (const SampleOffset o : p.positions)
      EXPECT_EQ(o, (SampleOffset{0, 0}));
  }
  // A pixel's samples are all covered exactly when its centre is.
  const TriangleSetup t = triangle_px({0.5, 0.5}, {3, 0.5}, {0.5, 3}); // centre (0,0) on edges
  EXPECT_EQ(sample_coverage(t, 0, 0, center_pattern(8)), 0xFFu);
  EXPECT_EQ(sample_coverage(t, 2, 1, center_pattern(8)), 0u); // (2.5, 1.5): x + y = 4 > 3.5
  EXPECT_EQ(sample_coverage(t, 1, 1, center_pattern(8)), 0xFFu);
}

// rule: MSAA.PATTERN.CUSTOM
TEST(PatternCustom, PositionsInIndexOrderMayRepeat) {
  const SamplePattern p = custom_pattern({{7, 7}, {-8, -8}, {7, 7}});
  EXPECT_EQ(p.kind, PatternKind::kCustom);
  EXPECT_EQ(p.count(), 3u);
  EXPECT_EQ(p.positions[0], (SampleOffset{7, 7}));
  EXPECT_EQ(p.positions[1], (SampleOffset{-8, -8}));
  // Repeated positions are covered together; the same pattern applies to every pixel.
  const TriangleSetup t = triangle_px({0, 0}, {8, 0}, {0, 8});
  EXPECT_EQ(sample_coverage(t, 0, 0, p), 0b111u);
  EXPECT_EQ(sample_coverage(t, 3, 3, p), 0b111u);
  EXPECT_EQ(sample_coverage(t, 3, 4, p), 0b010u); // (3.9375, 4.9375): x + y > 8
}

// rule: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CUSTOM
TEST(PatternNames, ToString) {
  EXPECT_EQ(to_string(PatternKind::kStandard), "standard");
  EXPECT_EQ(to_string(PatternKind::kCenter), "center");
  EXPECT_EQ(to_string(PatternKind::kCustom), "custom");
  EXPECT_EQ(to_string(ShadingRate::kPixel), "pixel");
  EXPECT_EQ(to_string(ShadingRate::kSample), "sample");
  EXPECT_EQ(to_string(DerivativeMode::kNone), "none");
  EXPECT_EQ(to_string(DerivativeMode::kFine), "fine");
  EXPECT_EQ(to_string(DerivativeMode::kCoarse), "coarse");
  EXPECT_EQ(to_string(CentroidRule::kD3D11), "d3d11");
  EXPECT_EQ(to_string(CentroidRule::kD3D10), "d3d10");
  EXPECT_EQ(to_string(static_cast<PatternKind>(9)), "unknown");
}

} // namespace
} // namespace rastrules::test
