// SPDX-License-Identifier: MIT
// Properties: each profile's front face is its API's own orientation rule, restated here from
// the APIs' words rather than read from the profile: D3D11 calls clockwise triangles on screen
// front (FrontCounterClockwise FALSE); Vulkan computes the signed area in framebuffer
// coordinates (y down) and calls a positive one counter-clockwise, front under
// VK_FRONT_FACE_COUNTER_CLOCKWISE; OpenGL computes it in its y-up window (the same numbers),
// front when positive under GL_CCW. With back-face culling, a triangle is culled under the profile
// exactly when its API calls it back-facing. Implements (properties for): PROFILE.D3D11,
// PROFILE.VULKAN, PROFILE.OPENGL, TRI.CULL.MODE

#include <array>
#include <cstdint>
#include <variant>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/profile.hpp"
#include "rastrules/scene.hpp"

namespace {

using rastrules::FloatPoint;
using rastrules::ProfileName;

// Twice the signed area of the snapped triangle in the API's own words, in 1/65536 px^2;
// positive: counter-clockwise as the API sees it. Vulkan: a = -1/2 sum(x_i y_{i+1} -
// x_{i+1} y_i) in framebuffer coordinates (y down, as here). OpenGL: a = +1/2 sum(...) in its
// window coordinates, which are these numbers read in a y-up window (PROFILE.OPENGL: the same
// coordinates, so its windings are mirrored). D3D11 states no formula: clockwise on screen is
// Vulkan's a negative.
std::int64_t api_ccw_area(ProfileName api, const std::array<rastrules::Vec2, 3>& v) {
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    const std::int64_t xi = v[i].x.raw(), yi = v[i].y.raw(), xj = v[j].x.raw(), yj = v[j].y.raw();
    sum += xi * yj - xj * yi;
  }
  return api == ProfileName::kOpenGL ? sum : -sum;
}

// Whether the API calls the triangle front-facing under the profile's state: D3D11 clockwise on
// screen (that is, not counter-clockwise by Vulkan's y-down formula); Vulkan and OpenGL a
// positive counter-clockwise area.
bool api_front(ProfileName api, const std::array<rastrules::Vec2, 3>& v) {
  const std::int64_t a = api_ccw_area(api, v);
  if (api == ProfileName::kD3D11)
    return a < 0; // clockwise on screen
  return a > 0;
}

} // namespace

// rule: PROFILE.D3D11, PROFILE.VULKAN, PROFILE.OPENGL, TRI.CULL.MODE
RC_GTEST_PROP(Profile, BackFaceCullingRemovesWhatEachApiCallsBackFacing, ()) {
  const auto api =
      *rc::gen::element(ProfileName::kD3D11, ProfileName::kVulkan, ProfileName::kOpenGL);
  rastrules::Scene s;
  s.width = s.height = 64;
  std::array<FloatPoint, 3> v;
  for (auto& p : v) {
    p = FloatPoint{static_cast<float>(*rc::gen::inRange(-2048, 2048 * 64)) / 2048.0f,
                   static_cast<float>(*rc::gen::inRange(-2048, 2048 * 64)) / 2048.0f};
  }
  s.primitives.push_back(rastrules::make_triangle(v));
  rastrules::apply(rastrules::profile(api), s);
  s.cull = rastrules::CullMode::kBack;
  const auto prepared = rastrules::prepare(s);
  RC_ASSERT(std::holds_alternative<rastrules::PreparedScene>(prepared));
  const rastrules::TriangleSetup& t =
      std::get<rastrules::PreparedScene>(prepared).primitives[0].triangles[0].setup;
  const std::int64_t area = api_ccw_area(api, t.snapped);
  RC_CLASSIFY(area == 0, "degenerate");
  RC_CLASSIFY(area != 0 && api_front(api, t.snapped), "front");
  if (area == 0) {
    RC_ASSERT(t.status == rastrules::TriangleStatus::kDegenerate);
    return;
  }
  RC_ASSERT((t.status == rastrules::TriangleStatus::kCulledBack) == !api_front(api, t.snapped));
  RC_ASSERT((t.status == rastrules::TriangleStatus::kRasterized) == api_front(api, t.snapped));
}
