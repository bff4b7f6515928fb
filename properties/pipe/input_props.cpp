// SPDX-License-Identifier: MIT
// Properties of the pipeline's input and of what a scene asks for: one bad value (NaN, an
// infinity, a coordinate one float step beyond 2^64, a transform that overflows, a matrix entry
// that is not finite, a NaN or infinite attribute, a window-space vertex that does not snap)
// planted in an otherwise valid scene is rejected naming its primitive and vertex (or matrix),
// and 2^64 itself is accepted; a window-space scene without depth and attributes costs nothing
// more: no data, and exactly the fragments of the coverage kernel (rastrules::render) for
// triangles, points and lines alike; and every triangle, point and line of a clip-space scene
// covers what the coverage kernel draws for its clipped, projected window-space primitive.
// Implements (properties for): PIPE.INPUT.POSITION, PIPE.INPUT.ATTRIBUTES,
//   PIPE.TRANSFORM.FLOAT32, PIPE.EFFECTS.ON_DEMAND, PIPE.CLIP.LINE

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"
#include "pipe_scene.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace ps = rastrules::pipe_scene;
namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;
using rastrules::FloatPoint;
using rastrules::PrimitiveType;

constexpr float kTwo64 = 18446744073709551616.0f;

// A small valid scene of clip-space and window-space triangles with n attributes.
rastrules::Scene valid_scene(std::size_t nattr) {
  rastrules::Scene s;
  s.width = 8;
  s.height = 8;
  for (std::size_t k = 0; k < nattr; ++k)
    s.attributes.push_back(kp::AttributeDecl{"a" + std::to_string(k), {}, {}});
  const int n = *rc::gen::inRange(1, 4);
  for (int i = 0; i < n; ++i) {
    rastrules::Primitive p;
    if (*rc::gen::arbitrary<bool>()) {
      p.pos = {kp::Vec4f{-0.5f, -0.5f, 0.5f, 1.0f}, kp::Vec4f{0.5f, -0.5f, 0.5f, 1.0f},
               kp::Vec4f{0.0f, 0.5f, 0.5f, 1.0f}};
    } else {
      p.v = {FloatPoint{1.0f, 1.0f}, FloatPoint{6.0f, 1.0f}, FloatPoint{3.0f, 6.0f}};
    }
    for (int j = 0; j < 3 && nattr > 0; ++j)
      p.attr.push_back(std::vector<float>(nattr, 0.25f));
    s.primitives.push_back(p);
  }
  return s;
}

bool names(const rastrules::SceneError& e, const std::string& prefix, const std::string& part) {
  return e.field.rfind(prefix, 0) == 0 && e.field.find(part) != std::string::npos;
}

// rule: PIPE.INPUT.POSITION, PIPE.INPUT.ATTRIBUTES, PIPE.TRANSFORM.FLOAT32
RC_GTEST_PROP(PipeInput, OneBadValueIsRejectedByName, ()) {
  const std::size_t nattr = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  rastrules::Scene s = valid_scene(nattr);
  const std::size_t i =
      static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, s.primitives.size()));
  const std::size_t j = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  rastrules::Primitive& p = s.primitives[i];
  const std::string prim = "primitives[" + std::to_string(i) + "]";
  const float huge = std::nextafter(kTwo64, std::numeric_limits<float>::infinity());
  const float bad = *rc::gen::element(std::numeric_limits<float>::quiet_NaN(),
                                      std::numeric_limits<float>::infinity(),
                                      -std::numeric_limits<float>::infinity(), huge, -huge);
  const int where = *rc::gen::inRange(0, 5);
  std::string expect_prefix = prim, expect_part, planted;
  bool expect_error = true;
  if (where == 0 && !p.pos.empty()) {                            // a position
    const float v = *rc::gen::inRange(0, 4) == 0 ? kTwo64 : bad; // 2^64 itself is allowed
    p.pos[j][static_cast<std::size_t>(*rc::gen::inRange(0, 4))] = v;
    expect_error = v != kTwo64;
    expect_part = ".pos[" + std::to_string(j) + "]";
    planted = expect_error ? "position" : "position 2^64";
  } else if (where == 1 && nattr > 0) { // an attribute
    p.attr[j][static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, nattr))] =
        *rc::gen::element(std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity());
    expect_part = ".attr[" + std::to_string(j) + "]";
    planted = "attribute";
  } else if (where == 2 && !p.pos.empty()) { // a transform that overflows 2^64
    kp::Mat4f m{};
    for (std::size_t r = 0; r < 4; ++r)
      m[5 * r] = 1.0f;
    m[0] = std::ldexp(1.0f, 70);
    s.model = m;
    p.pos[j][0] = 1.0f;
    // Every primitive with positions overflows (x = +-0.5 or 1): the first one is named.
    for (std::size_t q = i + 1; q-- > 0;) {
      if (!s.primitives[q].pos.empty())
        expect_prefix = "primitives[" + std::to_string(q) + "]";
    }
    expect_part = ".pos[";
    planted = "transform overflow";
  } else if (where == 3) { // a matrix entry that is not finite
    kp::Mat4f m{};
    for (std::size_t r = 0; r < 4; ++r)
      m[5 * r] = 1.0f;
    m[static_cast<std::size_t>(*rc::gen::inRange(0, 16))] =
        bad == huge || bad == -huge ? std::numeric_limits<float>::quiet_NaN() : bad;
    s.projection = m;
    expect_prefix = "transform.projection";
    expect_part = "";
    planted = "matrix entry";
  } else if (p.pos.empty()) { // a window-space vertex that does not snap
    p.v[j][static_cast<std::size_t>(*rc::gen::inRange(0, 2))] =
        *rc::gen::element(std::numeric_limits<float>::quiet_NaN(), 40000.0f, -1e30f);
    expect_part = ".v[" + std::to_string(j) + "]";
    planted = "window vertex";
  } else {
    expect_error = false;
    planted = "nothing";
  }
  const auto r = kp::run_pipeline(s);
  const std::string scene = ps::show(s);
  if (!expect_error) {
    if (const auto* e = std::get_if<rastrules::SceneError>(&r))
      RC_FAIL("rejected a valid scene: " + e->what() + "\n" + scene);
    RC_TAG(planted);
    return;
  }
  const auto* e = std::get_if<rastrules::SceneError>(&r);
  if (!e)
    RC_FAIL("accepted a scene with a bad value (expected " + expect_prefix + expect_part + ")\n" +
            scene);
  if (!names(*e, expect_prefix, expect_part))
    RC_FAIL("the error names " + e->field + " (" + e->message + "), expected " + expect_prefix +
            "..." + expect_part + "\n" + scene);
  if (planted == "transform overflow" && e->message.find("transform") == std::string::npos)
    RC_FAIL("an overflowing transform is not said to be one: " + e->what());
  RC_TAG(planted);
}

// A window-space scene of triangles, points and lines, without depth and attributes.
rc::Gen<rastrules::Scene> coverage_only_scene() {
  return rc::gen::exec([] {
    rastrules::Scene s;
    s.width = *rc::gen::inRange(1, 20);
    s.height = *rc::gen::inRange(1, 20);
    set_raster_state(s, *rastrules::gen::raster_state());
    set_sample_pattern(s, rastrules::standard_pattern(*rc::gen::element(1u, 4u)));
    const int n = *rc::gen::inRange(1, 5);
    for (int i = 0; i < n; ++i) {
      rastrules::Primitive p;
      const rastrules::gen::GenTriangle t = *rastrules::gen::triangle_near(s.width, s.height);
      p.type = *rc::gen::element(PrimitiveType::kTriangle, PrimitiveType::kTriangle,
                                 PrimitiveType::kPoint, PrimitiveType::kLine);
      const std::size_t nv = rastrules::required_vertex_count(p.type);
      p.v.assign(t.v.begin(), t.v.begin() + static_cast<std::ptrdiff_t>(nv));
      s.primitives.push_back(p);
    }
    return s;
  });
}

// rule: PIPE.EFFECTS.ON_DEMAND
RC_GTEST_PROP(PipeInput, CoverageOnlyScenesAreTheCoverageKernel, ()) {
  const rastrules::Scene s = *coverage_only_scene();
  const auto r =
      kp::run_pipeline(s, *rc::gen::element(kp::PipeOptions{}, kp::PipeOptions::plain()));
  rastrules::Scene ws = rastrules::target_of(s);
  for (const rastrules::Primitive& p : s.primitives)
    ws.primitives.push_back(rastrules::coverage_of(p));
  const auto want = rastrules::render(ws);
  if (std::holds_alternative<rastrules::SceneError>(want)) {
    RC_ASSERT(std::holds_alternative<rastrules::SceneError>(
        r)); // both reject (a point out of range, ...)
    return;
  }
  if (const auto* e = std::get_if<rastrules::SceneError>(&r))
    RC_FAIL("rejected: " + e->what() + "\n" + ps::show(s));
  const kp::PipeResult& got = std::get<kp::PipeResult>(r);
  RC_ASSERT(got.effects.coverage_only());
  RC_ASSERT(got.data.empty());
  RC_ASSERT(got.depth_buffer.empty());
  if (got.fragments != std::get<std::vector<rastrules::Fragment>>(want))
    RC_FAIL("fragments differ from rastrules::render\n" + ps::show(s));
}

} // namespace
