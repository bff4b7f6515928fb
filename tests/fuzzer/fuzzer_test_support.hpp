// SPDX-License-Identifier: MIT
// Helpers shared by the fuzzer's tests.

#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "rastrules/driver/driver.hpp"

namespace rastrules::fuzzer::test {

// Opens a driver by name; a failure to open fails the test (and returns nullptr).
inline std::unique_ptr<driver::Driver> open(const std::string& name) {
  std::string err;
  auto d = driver::open_driver(name, &err);
  EXPECT_NE(d, nullptr) << err;
  return d;
}

} // namespace rastrules::fuzzer::test
