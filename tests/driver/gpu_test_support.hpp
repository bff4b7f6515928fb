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
#include <set>
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

// --- Values of pipeline scenes (DRIVER.VALUES), shared by the GPU adapters' tests ------------

// Draws s with d's draw_values, expecting it supported and drawn.
inline Drawing values_ok(Driver& d, const Scene& s) {
  EXPECT_EQ(d.unsupported(s), "");
  ValuesResult r = d.draw_values(s);
  if (const auto* e = std::get_if<DriverError>(&r)) {
    ADD_FAILURE() << d.info().name << ": " << e->message;
    return {};
  }
  return std::get<Drawing>(std::move(r));
}

// A pipeline scene: an 8 x 6 target, one attribute per interpolation, D24, no vertex or edge
// through a pixel centre (the adapters' tie rules differ from the reference's).
inline Scene values_scene() {
  Scene s = scene(8, 6);
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  s.attributes = {{"p", pipe::Interpolation::kPerspective, pipe::Location::kCenter},
                  {"l", pipe::Interpolation::kLinear, pipe::Location::kCenter},
                  {"f", pipe::Interpolation::kFlat, pipe::Location::kCenter}};
  s.depth = pipe::DepthState{};
  s.depth->func = pipe::CompareFunc::kAlways;
  s.conventions.depth = pipe::DepthFormat::kD24;
  return s;
}

// The driver reports values, refuses what it cannot report with a named reason, and gives the
// reference's one-line error for invalid input.
inline void expect_values_support(Driver& d) {
  EXPECT_TRUE(d.info().values);
  Scene s = values_scene();
  Primitive t = make_triangle({{{0.3F, 0.7F}, {7.2F, 1.3F}, {2.1F, 5.7F}}});
  t.attr = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  s.primitives.push_back(t);
  EXPECT_EQ(d.unsupported(s), "");
  s.depth->bias = {3, 0.5F, 0.01F}; // every bias term (PIPE.DEPTH.BIAS)
  EXPECT_EQ(d.unsupported(s), "");
  s.depth->bias = {};
  s.primitives[0].w = {1.0F, 2.0F, 1.0F};
  EXPECT_NE(d.unsupported(s).find("w other than 1"), std::string::npos);
  s.primitives[0].w = {};
  s.primitives[0].z = {0.5F, 1.5F, 0.0F};
  EXPECT_NE(d.unsupported(s).find("depth range"), std::string::npos);
  s.primitives[0].z = {};
  s.primitives[0].attr.pop_back();
  const ValuesResult r = d.draw_values(s);
  ASSERT_TRUE(std::holds_alternative<DriverError>(r));
  EXPECT_NE(std::get<DriverError>(r).message.find("invalid scene"), std::string::npos);
}

// A window-space triangle whose values are exact at every pixel centre (dyadic vertex values,
// gradients of 1/2 and 1/4 per pixel): the driver gives the exact values and the exactly
// rounded D24 depth, the same fragments and values as the reference, under both provoking
// vertices.
inline void expect_exact_values(Driver& d) {
  Scene s = values_scene();
  Primitive t = make_triangle({{{0.0F, 0.0F}, {8.0F, 0.0F}, {0.0F, 16.0F}}});
  t.z = {0.25F, 0.75F, 0.25F};
  t.attr = {{0.0F, 0.0F, 1.0F}, {4.0F, 4.0F, 2.0F}, {0.0F, 0.0F, 3.0F}};
  s.primitives.push_back(t);
  for (const pipe::Provoking pv : {pipe::Provoking::kFirst, pipe::Provoking::kLast}) {
    s.conventions.provoking = pv;
    const Drawing got = values_ok(d, s);
    auto ref = open_driver("reference", nullptr);
    const Drawing want = std::get<Drawing>(ref->draw_values(s));
    ASSERT_EQ(got.fragments.size(), want.fragments.size()) << describe(got.fragments);
    ASSERT_EQ(got.values.size(), got.fragments.size());
    for (std::size_t i = 0; i < got.fragments.size(); ++i) {
      EXPECT_EQ(got.fragments[i], want.fragments[i]);
      EXPECT_EQ(got.values[i].attr, want.values[i].attr) << "fragment " << i;
      EXPECT_EQ(got.values[i].depth, want.values[i].depth) << "fragment " << i;
      EXPECT_EQ(got.values[i].attr[2], pv == pipe::Provoking::kFirst ? 1.0F : 3.0F);
    }
  }
}

// The exact scene of expect_exact_values on the standard 4x pattern under sample-rate shading:
// one fragment per covered sample (MSAA.SHADING.SAMPLE), attributes at the sample or the centre,
// each exact (sample positions are multiples of 1/16), the reference's values and keys. With
// centre_at_sample the driver's centre attributes are expected at the sample instead (legal
// under Vulkan and OpenGL, FUZZ.VALUES.LEGAL; FINDING.OPENGL.SAMPLE_SHADING_CENTER).
inline void expect_exact_sample_values(Driver& d, bool centre_at_sample) {
  for (const pipe::Location where : {pipe::Location::kSample, pipe::Location::kCenter}) {
    Scene s = values_scene();
    set_sample_pattern(s, standard_pattern(4));
    s.msaa.shading = ShadingRate::kSample;
    for (std::size_t k = 0; k < 2; ++k)
      s.attributes[k].location = where;
    Primitive t = make_triangle({{{0.0F, 0.0F}, {8.0F, 0.0F}, {0.0F, 16.0F}}});
    t.attr = {{0.0F, 0.0F, 1.0F}, {4.0F, 4.0F, 2.0F}, {0.0F, 0.0F, 3.0F}};
    s.primitives.push_back(t);
    const Drawing got = values_ok(d, s);
    Scene expected = s;
    if (centre_at_sample) {
      for (std::size_t k = 0; k < 2; ++k)
        expected.attributes[k].location = pipe::Location::kSample;
    }
    auto ref = open_driver("reference", nullptr);
    const Drawing want = std::get<Drawing>(ref->draw_values(expected));
    ASSERT_EQ(got.fragments.size(), want.fragments.size()) << describe(got.fragments);
    for (std::size_t i = 0; i < got.fragments.size(); ++i) {
      EXPECT_EQ(got.fragments[i], want.fragments[i]);
      EXPECT_EQ(got.values[i].attr, want.values[i].attr)
          << "fragment " << i << " sample " << got.fragments[i].sample.value_or(99);
    }
  }
}

// The exact scene of expect_exact_values on the standard 4x pattern: in D16 and D32F every
// covered sample's stored depth equals the reference's (read through a float, exact for these
// two); in D24 fragments carry attributes and no depth.
inline void expect_multisampled_depth(Driver& d) {
  for (const pipe::DepthFormat f :
       {pipe::DepthFormat::kD16, pipe::DepthFormat::kD32F, pipe::DepthFormat::kD24}) {
    const bool reports_ms_depth = f != pipe::DepthFormat::kD24;
    Scene s = values_scene();
    set_sample_pattern(s, standard_pattern(4));
    s.conventions.depth = f;
    Primitive t = make_triangle({{{0.0F, 0.0F}, {8.0F, 0.0F}, {0.0F, 16.0F}}});
    t.z = {0.25F, 0.75F, 0.25F};
    t.attr = {{0.0F, 0.0F, 1.0F}, {4.0F, 4.0F, 2.0F}, {0.0F, 0.0F, 3.0F}};
    s.primitives.push_back(t);
    const Drawing got = values_ok(d, s);
    auto ref = open_driver("reference", nullptr);
    const Drawing want = std::get<Drawing>(ref->draw_values(s));
    ASSERT_EQ(got.fragments, want.fragments) << describe(got.fragments);
    for (std::size_t i = 0; i < got.fragments.size(); ++i) {
      if (reports_ms_depth)
        EXPECT_EQ(got.values[i].depth, want.values[i].depth) << "fragment " << i;
      else
        EXPECT_TRUE(got.values[i].depth.empty()) << "fragment " << i;
    }
  }
}

// A constant depth bias moves a window-space triangle of constant depth by between one and two
// steps of the format per unit of bias, in the bias's direction: r may be up to twice D3D's
// under Vulkan and OpenGL (FUZZ.VALUES.LEGAL). Lines are not biased (triangles only).
inline void expect_biased_depth(Driver& d) {
  for (const pipe::DepthFormat f : {pipe::DepthFormat::kD16, pipe::DepthFormat::kD24}) {
    for (const std::int32_t bias : {-40, 40}) {
      Scene s = values_scene();
      s.conventions.depth = f;
      Primitive t = make_triangle({{{0.0F, 0.0F}, {8.0F, 0.0F}, {0.0F, 16.0F}}});
      t.z = {0.5F, 0.5F, 0.5F};
      t.attr = {{0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
      s.primitives.push_back(t);
      Primitive l;
      l.type = PrimitiveType::kLine;
      l.v = {{{0.25F, 5.25F}, {7.75F, 5.25F}}};
      l.z = {0.5F, 0.5F};
      l.attr = {{0, 0, 1}, {0, 0, 2}};
      s.primitives.push_back(l);
      const Drawing plain = values_ok(d, s);
      s.depth->bias.bias = bias;
      const Drawing biased = values_ok(d, s);
      ASSERT_EQ(plain.fragments, biased.fragments);
      for (std::size_t i = 0; i < plain.fragments.size(); ++i) {
        ASSERT_EQ(plain.values[i].depth.size(), 1U);
        ASSERT_EQ(biased.values[i].depth.size(), 1U);
        const auto moved = static_cast<std::int64_t>(biased.values[i].depth[0].unorm) -
                           static_cast<std::int64_t>(plain.values[i].depth[0].unorm);
        if (plain.fragments[i].prim == 1) {
          EXPECT_EQ(moved, 0) << "a line is not biased";
          continue;
        }
        EXPECT_GE(moved * bias, std::int64_t{bias} * bias) << "fragment " << i;
        EXPECT_LE(moved * bias, 2 * std::int64_t{bias} * bias + std::abs(bias)) << "fragment " << i;
      }
    }
  }
}

// Each segment of a line strip is its own primitive: gl_PrimitiveID names the segment, flat
// attributes take the segment's provoking vertex (PIPE.INTERP.FLAT), and a clipped strip's
// segments are parts without seg (PIPE.CLIP.LINE), as in the reference.
inline void expect_strip_values(Driver& d) {
  for (const bool clipped : {false, true}) {
    for (const pipe::Provoking pv : {pipe::Provoking::kFirst, pipe::Provoking::kLast}) {
      Scene s = values_scene();
      s.width = 16;
      s.height = 16;
      s.conventions.provoking = pv;
      Primitive p;
      p.type = PrimitiveType::kLineStrip;
      p.v.clear();
      p.pos = {{-0.8F, -0.8F, 0.25F, 1.0F},
               {0.8F, -0.7F, 0.5F, 1.0F},
               {0.7F, 0.8F, clipped ? -0.5F : 0.75F, 1.0F}};
      p.attr = {{0, 0, 10}, {1, 1, 20}, {2, 2, 30}};
      s.primitives.push_back(p);
      const Drawing got = values_ok(d, s);
      ASSERT_FALSE(got.fragments.empty());
      std::set<std::uint32_t> segments;
      for (std::size_t i = 0; i < got.fragments.size(); ++i) {
        const std::uint32_t k = clipped ? got.values[i].part.value() : got.fragments[i].seg.value();
        EXPECT_EQ(got.fragments[i].seg.has_value(), !clipped);
        segments.insert(k);
        const float provoking = pv == pipe::Provoking::kFirst ? 10.0F * static_cast<float>(k + 1)
                                                              : 10.0F * static_cast<float>(k + 2);
        EXPECT_EQ(got.values[i].attr[2], provoking) << "segment " << k;
      }
      EXPECT_EQ(segments, (std::set<std::uint32_t>{0, 1})) << "clipped " << clipped;
    }
  }
}

} // namespace rastrules::driver::gpu_test
