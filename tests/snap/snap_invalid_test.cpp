// SPDX-License-Identifier: MIT
// Bad input at the kernel API: rastrules::prepare rejects the whole scene, naming the field.

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <variant>

#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

Scene three_triangles() {
  return scene_px(
      16, 8, RasterState{},
      {{{{0, 0}, {4, 0}, {0, 4}}}, {{{4, 0}, {8, 0}, {4, 4}}}, {{{8, 0}, {12, 0}, {8, 4}}}});
}

// Returns the error of prepare(), or a SceneError with field "<none>" when it succeeded.
SceneError error_of(const Scene& s) {
  const auto r = prepare(s);
  if (const auto* e = std::get_if<SceneError>(&r))
    return *e;
  return SceneError{"<none>", "prepare succeeded"};
}

// rule: SNAP.VERTEX.INVALID
TEST(SnapVertexInvalid, NaNVertexIsRejectedWithTheExactFieldPath) {
  Scene s = three_triangles();
  s.primitives[1].v[2][0] = std::numeric_limits<float>::quiet_NaN();
  const SceneError e = error_of(s);
  EXPECT_EQ(e.field, "primitives[1].v[2][0]");
  EXPECT_EQ(e.message, "is NaN");
  EXPECT_EQ(e.what(), "primitives[1].v[2][0]: is NaN");
  // render() rejects the scene as a whole: no fragment of primitive 0 either.
  EXPECT_TRUE(std::holds_alternative<SceneError>(render(s)));
}

// rule: SNAP.VERTEX.INVALID
TEST(SnapVertexInvalid, InfiniteAndOutOfRangeCoordinatesAreRejected) {
  Scene s = three_triangles();
  s.primitives[0].v[1][1] = -std::numeric_limits<float>::infinity();
  EXPECT_EQ(error_of(s).field, "primitives[0].v[1][1]");
  EXPECT_EQ(error_of(s).message, "is infinite");

  s = three_triangles();
  s.primitives[2].v[0][1] = 32767.998046875f; // rounds to 2^23: out of range
  EXPECT_EQ(error_of(s).field, "primitives[2].v[0][1]");
  EXPECT_NE(error_of(s).message.find("outside the supported range"), std::string::npos)
      << error_of(s).message;

  s = three_triangles();
  s.primitives[2].v[0][1] = 32767.99609375f; // the largest value in range
  EXPECT_EQ(error_of(s).field, "<none>");
}

// rule: SNAP.VERTEX.INVALID
TEST(SnapVertexInvalid, TheFirstBadFieldInFieldOrderIsReported) {
  Scene s = three_triangles();
  s.primitives[2].v[0][0] = std::numeric_limits<float>::quiet_NaN();
  s.primitives[1].v[1][1] = std::numeric_limits<float>::infinity();
  s.primitives[1].v[2][0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(error_of(s).what(), "primitives[1].v[1][1]: is infinite");
}

// The scene reader's checks are tested in tests/cli; this checks that the kernel entry point
// enforces the target limits on its own.
// rule: SCENE.TARGET.LIMITS
TEST(KernelPrepare, RejectsTargetsOutsideOneTo16384) {
  Scene s = three_triangles();
  s.width = 0;
  EXPECT_EQ(error_of(s).field, "target.width");
  s.width = 16385;
  EXPECT_EQ(error_of(s).field, "target.width");
  s.width = -1;
  EXPECT_EQ(error_of(s).field, "target.width");
  s.width = 16384;
  s.height = 0;
  EXPECT_EQ(error_of(s).field, "target.height");
  s.height = 16385;
  EXPECT_EQ(error_of(s).field, "target.height");
  s.height = 1;
  EXPECT_EQ(error_of(s).field, "<none>");
  // The target is checked before the vertices.
  s.width = 0;
  s.primitives[0].v[0][0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(error_of(s).field, "target.width");
}

// rule: SCENE.OUTPUT.FRAGMENTS
TEST(KernelPrepare, AnEmptySceneIsValidAndDrawsNothing) {
  Scene s;
  s.width = 1;
  s.height = 1;
  const auto r = render(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r));
  EXPECT_TRUE(std::get<std::vector<Fragment>>(r).empty());
}

} // namespace
} // namespace rastrules::test
