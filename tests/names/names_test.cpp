// SPDX-License-Identifier: MIT
// The words of every enumeration a scene names (rastrules/names.hpp) are the words of
// spec/scene.md, to_string() returns them, and the exact oracle, which keeps its own strings
// (it never includes the kernel), accepts exactly these words and no others.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

#include "rastrules/names.hpp"
#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"

namespace rastrules {
namespace {

std::string scene_md() {
  std::ifstream in(std::string(RASTRULES_SOURCE_DIR) + "/spec/scene.md");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every word of E once, spelled in spec/scene.md as a quoted string, and the table's round trip.
template <class E> void expect_words(const std::string& spec) {
  std::set<std::string_view> seen;
  for (const auto& [word, value] : Names<E>::table) {
    EXPECT_TRUE(seen.insert(word).second) << word << " twice";
    EXPECT_EQ(name_of(value), word);
    EXPECT_EQ(from_name<E>(word), value);
    EXPECT_NE(spec.find("\"" + std::string(word) + "\""), std::string::npos)
        << "spec/scene.md does not spell \"" << word << "\"";
  }
  EXPECT_FALSE(from_name<E>("no-such-word").has_value());
}

// rule: SCENE.FORMAT.V1, SCENE.LINE_MODE
TEST(Names, EveryWordIsTheWordOfSpecSceneMd) {
  const std::string spec = scene_md();
  ASSERT_FALSE(spec.empty());
  expect_words<PrimitiveType>(spec);
  expect_words<CullMode>(spec);
  expect_words<FrontFace>(spec);
  expect_words<FillConvention>(spec);
  expect_words<LineMode>(spec);
  // A custom sample pattern is a list of offsets in a file, not a word.
  EXPECT_NE(spec.find("\"standard\""), std::string::npos);
  EXPECT_NE(spec.find("\"center\""), std::string::npos);
  expect_words<CentroidRule>(spec);
  expect_words<ShadingRate>(spec);
  expect_words<pipe::Interpolation>(spec);
  expect_words<pipe::Location>(spec);
  expect_words<pipe::DepthFormat>(spec);
  expect_words<pipe::CompareFunc>(spec);
  expect_words<pipe::Provoking>(spec);
  // "none" is the default, never written in a file; the file's words are fine and coarse.
  EXPECT_NE(spec.find("\"fine\""), std::string::npos);
  EXPECT_NE(spec.find("\"coarse\""), std::string::npos);
}

// rule: SCENE.FORMAT.V1
TEST(Names, ToStringReturnsTheWord) {
  EXPECT_EQ(to_string(LineMode::kD3DDiamond), "d3d");
  for (const auto& [word, value] : Names<FillConvention>::table)
    EXPECT_EQ(to_string(value), word);
  for (const auto& [word, value] : Names<pipe::CompareFunc>::table)
    EXPECT_EQ(pipe::to_string(value), word);
  for (const auto& [word, value] : Names<PrimitiveType>::table)
    EXPECT_EQ(to_string(value), word);
}

// Whether calling f throws std::invalid_argument (the oracle's answer to a word it lacks).
template <class F> bool rejects(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument&) {
    return true;
  }
  return false;
}

// rule: SCENE.FORMAT.V1, SCENE.LINE_MODE, MSAA.CENTROID.D3D11, PIPE.DEPTH.TEST
TEST(Names, TheOracleAcceptsExactlyTheseWords) {
  const oracle::Raw2 a{0, 128}, b{1024, 128};
  // Triangles: cull, front face, fill (oracle::render with a one-triangle scene).
  const auto tri = [](oracle::State st) {
    oracle::Scene s;
    s.width = s.height = 4;
    s.state = std::move(st);
    s.triangles = {{{{0.5f, 0.5f}, {3.5f, 0.5f}, {0.5f, 3.5f}}}};
    (void)oracle::render(s);
  };
  for (const auto& [word, value] : Names<CullMode>::table)
    EXPECT_FALSE(rejects([&, w = word] { tri({std::string(w), "cw", "top-left"}); })) << word;
  for (const auto& [word, value] : Names<FrontFace>::table)
    EXPECT_FALSE(rejects([&, w = word] { tri({"back", std::string(w), "top-left"}); })) << word;
  for (const auto& [word, value] : Names<FillConvention>::table)
    EXPECT_FALSE(rejects([&, w = word] { (void)oracle::point_covers(a, b, std::string(w)); }))
        << word;
  EXPECT_TRUE(rejects([&] { tri({"sideways", "cw", "top-left"}); }));
  // Line modes: aliased ones by the line oracle, every one by the multisample oracle.
  for (const LineMode m : {LineMode::kD3DDiamond, LineMode::kVulkanBresenham})
    EXPECT_FALSE(rejects([&] {
      (void)oracle::aliased_line_covers({0, 128}, {1024, 128}, std::string(name_of(m)), 1, 0);
    })) << name_of(m);
  for (const LineMode m : {LineMode::kQuadWide, LineMode::kQuadNarrow})
    EXPECT_FALSE(rejects([&] { (void)oracle::quad_line_offset(a, b, std::string(name_of(m))); }))
        << name_of(m);
  EXPECT_TRUE(rejects([] {
    (void)oracle::aliased_line_covers({0, 128}, {1024, 128}, "d3d-diamond", 1, 0);
  }));
  for (const auto& [word, value] : Names<LineMode>::table) {
    oracle::msaa::Input in;
    in.width = in.height = 4;
    in.line_mode = std::string(word);
    in.pattern = oracle::msaa::standard_pattern(4);
    in.primitives = {oracle::msaa::Primitive{"line", {{128, 384}, {896, 384}}}};
    EXPECT_FALSE(rejects([&] { (void)oracle::msaa::render(in); })) << word;
  }
  // Multisampling: centroid rules, shading, derivatives.
  for (const auto& [word, value] : Names<CentroidRule>::table)
    EXPECT_FALSE(rejects([&, w = word] {
      (void)oracle::msaa::centroid(std::string(w), 1, 0xF, oracle::msaa::standard_pattern(4));
    })) << word;
  for (const auto& [word, value] : Names<ShadingRate>::table) {
    oracle::msaa::Input in;
    in.width = in.height = 2;
    in.shading = std::string(word);
    EXPECT_FALSE(rejects([&] { (void)oracle::msaa::render(in); })) << word;
  }
  for (const auto& [word, value] : Names<DerivativeMode>::table) {
    oracle::msaa::Input in;
    in.width = in.height = 2;
    in.derivatives = std::string(word);
    EXPECT_FALSE(rejects([&] { (void)oracle::msaa::render(in); })) << word;
  }
  // The pipeline: depth formats, compare functions, provoking vertices.
  for (const auto& [word, value] : Names<pipe::DepthFormat>::table)
    EXPECT_FALSE(rejects([&, w = word] {
      (void)oracle::pipe::store_exact(0.5, 0.0f, 1.0f, std::string(w));
    })) << word;
  for (const auto& [word, value] : Names<pipe::CompareFunc>::table)
    EXPECT_FALSE(rejects([&, w = word] {
      (void)oracle::pipe::depth_test(std::string(w), oracle::pipe::Stored{}, oracle::pipe::Stored{},
                                     "d24");
    })) << word;
  for (const auto& [word, value] : Names<pipe::Provoking>::table)
    EXPECT_FALSE(rejects([&, w = word] {
      (void)oracle::pipe::flat_value({1.0f, 2.0f}, std::string(w));
    })) << word;
  EXPECT_TRUE(rejects([] { (void)oracle::pipe::flat_value({1.0f}, "middle"); }));
}

} // namespace
} // namespace rastrules
