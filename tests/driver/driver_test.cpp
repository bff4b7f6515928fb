// SPDX-License-Identifier: MIT
// Examples for DRIVER.INTERFACE and DRIVER.REFERENCE: the registry, and the reference driver
// reports exactly the kernel's observable fragments.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

// rule: DRIVER.INTERFACE
TEST(DriverRegistry, UnknownNameFailsWithTheKnownNames) {
  std::string error;
  EXPECT_EQ(open_driver("no-such-driver", &error), nullptr);
  EXPECT_NE(error.find("unknown driver 'no-such-driver'"), std::string::npos) << error;
  EXPECT_NE(error.find("reference"), std::string::npos) << error;
  const auto names = driver_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "reference"), names.end());
}

// rule: DRIVER.INTERFACE
TEST(DriverRegistry, ReferenceTakesNoArgument) {
  std::string error;
  EXPECT_EQ(open_driver("reference:x", &error), nullptr);
  EXPECT_FALSE(error.empty());
}

// rule: DRIVER.REFERENCE
TEST(ReferenceDriver, MatchesTheKernelWithoutUnobservableFields) {
  std::string error;
  auto d = open_driver("reference", &error);
  ASSERT_NE(d, nullptr) << error;
  EXPECT_EQ(d->info().subpixel_bits, 8);
  Scene s;
  s.width = 8;
  s.height = 8;
  set_sample_pattern(s, standard_pattern(4));
  s.msaa.has_centroid = true;
  s.msaa.derivatives = DerivativeMode::kFine;
  s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {6.0F, 1.0F}, {2.0F, 7.0F}}}));
  ASSERT_TRUE(d->unsupported(s).empty());
  const DrawResult r = d->draw(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r));
  const auto& got = std::get<std::vector<Fragment>>(r);
  const auto kernel = std::get<std::vector<Fragment>>(render(s));
  // The kernel lists helper lanes and centroids here; the driver keeps only covered fragments.
  ASSERT_TRUE(
      std::any_of(kernel.begin(), kernel.end(), [](const Fragment& f) { return f.helper; }));
  std::vector<Fragment> expected;
  for (Fragment f : kernel) {
    if (f.helper)
      continue;
    f.centroid.reset();
    f.derivatives.reset();
    expected.push_back(f);
  }
  EXPECT_EQ(got, expected);
  for (const Fragment& f : got)
    EXPECT_NE(f.mask, 0U);
}

// rule: DRIVER.REFERENCE
TEST(ReferenceDriver, InvalidSceneIsAnErrorNamingTheField) {
  auto d = open_driver("reference", nullptr);
  ASSERT_NE(d, nullptr);
  Scene s;
  s.width = 4;
  s.height = 4;
  s.primitives.push_back(make_triangle(
      {{{0.0F, 0.0F}, {std::numeric_limits<float>::quiet_NaN(), 1.0F}, {2.0F, 2.0F}}}));
  const DrawResult r = d->draw(s);
  ASSERT_TRUE(std::holds_alternative<DriverError>(r));
  EXPECT_NE(std::get<DriverError>(r).message.find("primitives[0].v[1][0]"), std::string::npos)
      << std::get<DriverError>(r).message;
}

} // namespace
} // namespace rastrules::driver
