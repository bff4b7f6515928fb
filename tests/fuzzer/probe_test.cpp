// SPDX-License-Identifier: MIT
// The probe reports each driver's conventions: the planted ones of the imprecise drivers and
// the reference's own.

#include <gtest/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {
namespace {

ProbeReport probe_named(const std::string& name) {
  std::string err;
  auto d = driver::open_driver(name, &err);
  EXPECT_NE(d, nullptr) << err;
  if (!d)
    return {};
  ProbeReport r = probe(*d);
  EXPECT_EQ(r.error, "") << name;
  return r;
}

// rule: FUZZ.PROBE
TEST(Probe, ReferenceIsTopLeftWithEightBitsRoundHalfToEven) {
  const ProbeReport r = probe_named("reference");
  EXPECT_EQ(r.fill, "top-left");
  EXPECT_EQ(r.subpixel_bits, 8);
  EXPECT_EQ(r.threshold_4096, 9); // half a 1/256 step is 8/4096: a tie, kept at the even 0.5
  EXPECT_NE(r.rounding.find("half to even"), std::string::npos) << r.rounding;
  // Every line mode matches itself; the 4x scan finds the kernel's standard pattern.
  EXPECT_EQ(r.line_mode.find("differs"), std::string::npos) << r.line_mode;
  EXPECT_NE(r.line_mode.find("vulkan-bresenham matches"), std::string::npos) << r.line_mode;
  EXPECT_EQ(r.samples_4x, standard_pattern(4).positions);
  EXPECT_NE(r.point_rule.find("POINT.SHAPE.SQUARE"), std::string::npos) << r.point_rule;
}

// rule: FUZZ.PROBE
TEST(Probe, FindsThePlantedConventions) {
  const ProbeReport four = probe_named("imprecise:4-bit-subpixel");
  EXPECT_EQ(four.fill, "top-left");
  EXPECT_EQ(four.subpixel_bits, 4);
  EXPECT_NE(four.rounding.find("half to even"), std::string::npos) << four.rounding;
  const ProbeReport br = probe_named("imprecise:fill-bottom-right");
  EXPECT_EQ(br.fill, "bottom-right");
  EXPECT_EQ(br.subpixel_bits, 8);
  const ProbeReport fe = probe_named("imprecise:float-edges");
  EXPECT_TRUE(fe.top && fe.bottom && fe.left && fe.right);
  EXPECT_NE(fe.fill.find("no consistent fill convention"), std::string::npos) << fe.fill;
  EXPECT_EQ(fe.subpixel_bits, 8);
  EXPECT_NE(fe.point_rule.find("not probed"), std::string::npos);
  EXPECT_NE(fe.line_mode.find("not probed"), std::string::npos);
}

// llvmpipe's OpenGL under glClipControl(GL_UPPER_LEFT) (DRIVER.OPENGL.ORIGIN): bottom-left ties in
// the y-down frame (FINDING.OPENGL.FILL_BOTTOM_LEFT), 8 bits rounded half to even, points as
// POINT.SHAPE.SQUARE under that rule, the standard 4x positions, Bresenham-like lines that
// differ (FINDING.OPENGL.LINES). Skips when the build or the machine has no llvmpipe EGL.
// rule: FUZZ.PROBE, DRIVER.OPENGL.ORIGIN
TEST(Probe, OpenGLIsBottomLeftUnderAnUpperLeftOrigin) {
  std::string err;
  auto d = driver::open_driver("opengl", &err);
  if (!d)
    GTEST_SKIP() << "no opengl driver: " << err;
  const ProbeReport r = probe(*d);
  ASSERT_EQ(r.error, "");
  EXPECT_EQ(r.fill, "bottom-left");
  EXPECT_EQ(r.subpixel_bits, 8);
  EXPECT_NE(r.rounding.find("half to even"), std::string::npos) << r.rounding;
  EXPECT_NE(r.point_rule.find("as POINT.SHAPE.SQUARE"), std::string::npos) << r.point_rule;
  EXPECT_NE(r.line_mode.find("vulkan-bresenham differs"), std::string::npos) << r.line_mode;
  EXPECT_EQ(r.samples_4x, standard_pattern(4).positions);
}

} // namespace
} // namespace rastrules::fuzzer
