// SPDX-License-Identifier: MIT
// Test support shared by the GPU adapter examples (lavapipe_test.cpp, opengl_test.cpp): both
// draw small scenes with one long-lived driver and compare the fragments with the reference
// driver's (DRIVER.LAVAPIPE.*, DRIVER.OPENGL.*). Scene builders, a readable fragment dump, and
// drawing that fails the test on an unsupported scene or a driver error.

#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver::gpu_test {

// One driver per name for the whole program: creating a device or context is the slow part,
// and reusing it across draws is what the adapters are built for. Returns nullptr and sets
// *why when the driver cannot be opened.
inline Driver* shared_driver(const std::string& name, std::string* why) {
  static std::map<std::string, std::pair<std::unique_ptr<Driver>, std::string>> opened;
  auto it = opened.find(name);
  if (it == opened.end()) {
    std::string error;
    std::unique_ptr<Driver> d = open_driver(name, &error);
    it = opened.emplace(name, std::make_pair(std::move(d), std::move(error))).first;
  }
  *why = it->second.second;
  return it->second.first.get();
}

// Declares Driver* var, the shared driver `name`, or skips the test saying `missing` and why.
#define RASTRULES_DRIVER_OR_SKIP(var, name, missing)                                               \
  std::string var##_why;                                                                           \
  Driver* var = ::rastrules::driver::gpu_test::shared_driver(name, &var##_why);                    \
  if (var == nullptr)                                                                              \
  GTEST_SKIP() << missing << ": " << var##_why

// The fragments as " {prim x,y mMASK[ sSEG]}..." for readable failures and comparisons.
inline std::string describe(const std::vector<Fragment>& fs) {
  std::ostringstream os;
  for (const Fragment& f : fs) {
    os << " {" << f.prim << " " << f.x << "," << f.y << " m" << f.mask;
    if (f.seg)
      os << " s" << *f.seg;
    os << "}";
  }
  return os.str();
}

// Draws s with d, expecting it supported and drawn without error.
inline std::vector<Fragment> draw_ok(Driver& d, const Scene& s) {
  EXPECT_EQ(d.unsupported(s), "");
  DrawResult r = d.draw(s);
  if (const auto* e = std::get_if<DriverError>(&r)) {
    ADD_FAILURE() << d.info().name << ": " << e->message;
    return {};
  }
  return std::get<std::vector<Fragment>>(r);
}

// The reference driver's fragments for s.
inline std::vector<Fragment> reference(const Scene& s) {
  auto d = open_driver("reference", nullptr);
  return draw_ok(*d, s);
}

// Draws s with d and expects want, which must not be empty.
inline void expect_draws(Driver& d, const Scene& s, const std::vector<Fragment>& want) {
  const auto got = draw_ok(d, s);
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(got, want) << d.info().name << ":" << describe(got) << "\nexpected:" << describe(want);
}

// A w x h target with the standard pattern of `samples` samples.
inline Scene scene(std::int32_t w, std::int32_t h, std::uint32_t samples = 1) {
  Scene s;
  s.width = w;
  s.height = h;
  set_sample_pattern(s, standard_pattern(samples));
  return s;
}

// A w x h target with `samples` samples, line mode `mode`, holding `prims`.
inline Scene line_scene(std::int32_t w, std::int32_t h, std::uint32_t samples, LineMode mode,
                        std::vector<Primitive> prims) {
  Scene s = scene(w, h, samples);
  s.conventions.line_mode = mode;
  s.primitives = std::move(prims);
  return s;
}

inline Primitive prim(PrimitiveType t, std::vector<FloatPoint> v) {
  Primitive p;
  p.type = t;
  p.v = std::move(v);
  return p;
}

inline Primitive line(FloatPoint a, FloatPoint b) {
  return prim(PrimitiveType::kLine, {a, b});
}

// A fragment list written (x, y, mask) for one primitive without seg.
inline std::vector<Fragment> frags(std::uint32_t prim_index,
                                   std::initializer_list<std::array<std::int32_t, 3>> list) {
  std::vector<Fragment> out;
  for (const auto& f : list) {
    out.emplace_back(prim_index, f[0], f[1], static_cast<std::uint32_t>(f[2]));
  }
  return out;
}

} // namespace rastrules::driver::gpu_test
