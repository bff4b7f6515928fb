// SPDX-License-Identifier: MIT
// Pipeline scenes in tools/io, called directly: every key of SCENE.PIPELINE read into
// rastrules::Scene, the defaults, plain scenes staying plain, the writer's round trip,
// and the fragment and depth-buffer output of SCENE.OUTPUT.PIPELINE on hand-made fragments.
// (The bad-input catalog, tests/bad_input/pipe_*.json, checks the errors.)

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"
#include "support.hpp"

namespace {

namespace pipe = rastrules::pipe;
namespace io = rastrules::io;
using rastrules::SceneError;

std::uint32_t bits(float f) {
  return std::bit_cast<std::uint32_t>(f);
}

rastrules::Scene pipe_ok(const std::string& text) {
  auto r = io::read_scene(text);
  if (auto* e = std::get_if<SceneError>(&r))
    ADD_FAILURE() << "unexpected error: " << e->what();
  if (auto* s = std::get_if<rastrules::Scene>(&r)) {
    if (!rastrules::has_pipeline_state(*s))
      ADD_FAILURE() << "read without pipeline state: " << text;
    return *s;
  }
  return rastrules::Scene{};
}

// The error a scene file gets on loading: the reader's (syntax and types), else the kernel's
// one validator's (pipe::validate), as rastrules load_scene reports them.
std::string error_of(const std::string& text) {
  auto r = io::read_scene(text);
  if (auto* e = std::get_if<SceneError>(&r))
    return e->what();
  if (auto e = rastrules::pipe::validate(std::get<rastrules::Scene>(r)))
    return e->what();
  return "(no error)";
}

// Checks every field of a depth state.
void expect_depth_state(const pipe::DepthState& got, const pipe::DepthState& want) {
  EXPECT_EQ(got.func, want.func);
  EXPECT_EQ(got.write, want.write);
  EXPECT_EQ(got.clear, want.clear);
  EXPECT_EQ(got.clip, want.clip);
  EXPECT_EQ(got.bias.bias, want.bias.bias);
  EXPECT_EQ(got.bias.slope_scaled, want.bias.slope_scaled);
  EXPECT_EQ(got.bias.clamp, want.bias.clamp);
}

constexpr const char* kTarget = R"("target": {"width": 8, "height": 4})";
constexpr const char* kPosTriangle =
    R"({"type": "triangle", "pos": [[-0.5, -0.5, 0.5], [0.5, -0.5, 0.25, 2], [0, 0.5, 0]]})";

// rule: SCENE.PIPELINE
TEST(PipelineSceneIo, ReadsEveryKey) {
  const rastrules::Scene s = pipe_ok(
      R"({"target": {"width": 16, "height": 8}, "cull": "back", "samples": 4, "shading": "sample",
          "viewport": {"x": 1.5, "y": -2, "width": 10, "height": 6, "min_depth": 0.25, "max_depth": 0.75},
          "transform": {"model": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16],
                        "view": [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1],
                        "projection": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0]},
          "depth": {"format": "d16", "func": "greater_equal", "write": false, "clear": 0.5,
                    "clip": false, "bias": -3, "slope_scaled_bias": 1.25, "bias_clamp": -0.125},
          "attributes": [{"name": "u", "interpolation": "linear", "location": "centroid"},
                         {"name": "id", "interpolation": "flat", "location": "sample"},
                         {"name": "s"}],
          "provoking_vertex": "last",
          "primitives": [
            {"type": "triangle", "pos": [[1, 2, 3], [4, 5, 6, 7], [8, 9, 10, 11]],
             "attr": [[0, 1, 2], [3, 4, 5], [6, 7, 8]]},
            {"type": "line", "v": [[1, 1], [5, 2]], "z": [0.5, 1], "w": [1, 4], "aa": true,
             "attr": [[1, 2, 3], [4, 5, 6]], "color": [1, 2, 3, 4]}]})");
  EXPECT_EQ(s.width, 16);
  EXPECT_EQ(s.height, 8);
  EXPECT_EQ(s.cull, rastrules::CullMode::kBack);
  EXPECT_EQ(s.msaa.pattern.count(), 4u);
  ASSERT_EQ(s.primitives.size(), 2u);
  ASSERT_TRUE(s.viewport.has_value());
  EXPECT_EQ(*s.viewport, (pipe::Viewport{1.5f, -2.0f, 10.0f, 6.0f, 0.25f, 0.75f}));
  ASSERT_TRUE(s.model && s.view && s.projection);
  for (std::size_t k = 0; k < 16; ++k)
    EXPECT_EQ((*s.model)[k], static_cast<float>(k + 1)) << k;
  EXPECT_EQ((*s.view)[0], 0.5f);
  EXPECT_EQ((*s.view)[15], 1.0f);
  EXPECT_EQ((*s.projection)[14], 1.0f);
  EXPECT_EQ((*s.projection)[15], 0.0f);
  ASSERT_TRUE(s.depth.has_value());
  EXPECT_EQ(s.conventions.depth, pipe::DepthFormat::kD16);
  expect_depth_state(*s.depth, {pipe::CompareFunc::kGreaterEqual, false, 0.5f, false,
                                pipe::DepthBias{-3, 1.25f, -0.125f}});
  ASSERT_EQ(s.attributes.size(), 3u);
  EXPECT_EQ(s.attributes[0].name, "u");
  EXPECT_EQ(s.attributes[0].interpolation, pipe::Interpolation::kLinear);
  EXPECT_EQ(s.attributes[0].location, pipe::Location::kCentroid);
  EXPECT_EQ(s.attributes[1].interpolation, pipe::Interpolation::kFlat);
  EXPECT_EQ(s.attributes[1].location, pipe::Location::kSample);
  EXPECT_EQ(s.attributes[2].interpolation, pipe::Interpolation::kPerspective);
  EXPECT_EQ(s.attributes[2].location, pipe::Location::kCenter);
  EXPECT_EQ(s.conventions.provoking, pipe::Provoking::kLast);
  ASSERT_EQ(s.primitives.size(), 2u);
  const rastrules::Primitive& t = s.primitives[0];
  EXPECT_EQ(t.type, rastrules::PrimitiveType::kTriangle);
  EXPECT_TRUE(t.v.empty()); // positions are in pos
  ASSERT_EQ(t.pos.size(), 3u);
  EXPECT_EQ(t.pos[0], (pipe::Vec4f{1, 2, 3, 1})); // w = 1 when omitted
  EXPECT_EQ(t.pos[1], (pipe::Vec4f{4, 5, 6, 7}));
  EXPECT_EQ(t.pos[2], (pipe::Vec4f{8, 9, 10, 11}));
  EXPECT_TRUE(t.z.empty());
  EXPECT_TRUE(t.w.empty());
  EXPECT_EQ(t.attr, (std::vector<std::vector<float>>{{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}));
  const rastrules::Primitive& l = s.primitives[1];
  EXPECT_EQ(l.type, rastrules::PrimitiveType::kLine);
  EXPECT_TRUE(l.aa);
  EXPECT_EQ(l.color, (rastrules::Rgba8{1, 2, 3, 4}));
  EXPECT_EQ(l.v, (std::vector<rastrules::FloatPoint>{{1, 1}, {5, 2}}));
  EXPECT_TRUE(l.pos.empty());
  EXPECT_EQ(l.z, (std::vector<float>{0.5f, 1.0f}));
  EXPECT_EQ(l.w, (std::vector<float>{1.0f, 4.0f}));
  EXPECT_EQ(l.attr.size(), 2u);
}

// rule: SCENE.PIPELINE
TEST(PipelineSceneIo, DefaultsOfEveryKey) {
  const rastrules::Scene s =
      pipe_ok(std::string("{") + kTarget +
              R"(, "viewport": {}, "depth": {}, "attributes": [{"name": "u"}],
                                        "transform": {},
                                        "primitives": [{"type": "point", "v": [[1, 1]], "attr": [[2]]}]})");
  ASSERT_TRUE(s.viewport.has_value());
  EXPECT_EQ(*s.viewport, (pipe::Viewport{0.0f, 0.0f, 8.0f, 4.0f, 0.0f, 1.0f}));
  EXPECT_FALSE(s.model || s.view || s.projection);
  ASSERT_TRUE(s.depth.has_value());
  // Every field at its default: d24, less, write, clear 1, clip, no bias.
  EXPECT_EQ(s.conventions.depth, pipe::DepthFormat::kD24);
  expect_depth_state(*s.depth,
                     {pipe::CompareFunc::kLess, true, 1.0f, true, pipe::DepthBias{0, 0.0f, 0.0f}});
  EXPECT_EQ(s.attributes[0].interpolation, pipe::Interpolation::kPerspective);
  EXPECT_EQ(s.attributes[0].location, pipe::Location::kCenter);
  EXPECT_EQ(s.conventions.provoking, pipe::Provoking::kFirst);
  EXPECT_TRUE(s.primitives[0].z.empty());
  EXPECT_TRUE(s.primitives[0].w.empty());

  // Without the keys: no viewport (run_pipeline's default), no depth, no attributes.
  const rastrules::Scene bare =
      pipe_ok(std::string("{") + kTarget + R"(, "primitives": [)" + kPosTriangle + "]}");
  EXPECT_FALSE(bare.viewport.has_value());
  EXPECT_FALSE(bare.depth.has_value());
  EXPECT_TRUE(bare.attributes.empty());
}

// rule: SCENE.PIPELINE
TEST(PipelineSceneIo, MissingViewportKeysTakeTheWholeTargetsValuesWhereverTheTargetComes) {
  const rastrules::Scene s = pipe_ok(
      R"({"viewport": {"y": 2, "max_depth": 0.5}, "primitives": [], "target": {"width": 32, "height": 16}})");
  ASSERT_TRUE(s.viewport.has_value());
  EXPECT_EQ(*s.viewport, (pipe::Viewport{0.0f, 2.0f, 32.0f, 16.0f, 0.0f, 0.5f}));
}

// rule: SCENE.PIPELINE, SCENE.FORMAT.V1
TEST(PipelineSceneIo, KeysThatAskForAStageGivePipelineStateAndOthersDoNot) {
  const std::string head = std::string("{") + kTarget + ", ";
  const std::string tri = R"({"type": "triangle", "v": [[1, 1], [6, 2], [2, 3]])";
  // Each key that asks for a stage, with the field first_pipeline_field() names.
  const std::vector<std::pair<std::string, std::string>> pipeline = {
      {head + R"("viewport": {}, "primitives": [])", "viewport"},
      {head + R"("transform": {"view": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]},
                 "primitives": [])",
       "transform.view"},
      {head + R"("depth": {}, "primitives": [])", "depth"},
      {head + R"("primitives": [)" + tri + R"(, "z": [0, 0, 0]}])", "primitives[0].z"},
      {head + R"("primitives": [)" + tri + R"(, "w": [1, 1, 1]}])", "primitives[0].w"},
      {head + R"("primitives": [)" + kPosTriangle + "]", "primitives[0].pos"},
      {head + R"("attributes": [{"name": "a"}], "primitives": [)" + tri +
           R"(, "attr": [[0], [0], [0]]}])",
       "attributes"},
      // Root keys come first, whatever the text's order.
      {head + R"("primitives": [)" + tri + R"(, "w": [1, 1, 1]}], "depth": {})", "depth"},
  };
  for (const auto& [text, field] : pipeline) {
    const auto r = io::read_scene(text + "}");
    ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(r)) << text;
    EXPECT_EQ(rastrules::first_pipeline_field(std::get<rastrules::Scene>(r)), field) << text;
  }
  // Keys that ask for nothing (an empty transform or attribute list, the default provoking
  // vertex, which is a convention, not a stage) read as the scene without them.
  const std::string plain = head + R"("samples": 4, "primitives": [)" + tri + "}]}";
  const auto without = io::read_scene(plain);
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(without));
  EXPECT_FALSE(rastrules::has_pipeline_state(std::get<rastrules::Scene>(without)));
  for (const std::string key :
       {R"("transform": {}, )", R"("attributes": [], )", R"("provoking_vertex": "first", )"}) {
    const auto with = io::read_scene(head + key + plain.substr(head.size()));
    ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(with)) << key;
    EXPECT_FALSE(rastrules::has_pipeline_state(std::get<rastrules::Scene>(with))) << key;
    EXPECT_TRUE(
        io::same_scene(std::get<rastrules::Scene>(with), std::get<rastrules::Scene>(without)))
        << key;
  }
}

// rule: SCENE.PIPELINE, SCENE.NUMBER.FLOAT32
TEST(PipelineSceneIo, NumbersAreReadAsFloat32LikeCoordinates) {
  // 16384 + 1/256 + 1/1024 + 1e-20 rounds straight to float32 as 16384 + 3/512 (through double:
  // 16384 + 2/512); integers round to float32 ties to even.
  const rastrules::Scene s = pipe_ok(
      R"({"target": {"width": 4, "height": 4}, "attributes": [{"name": "a"}],
          "viewport": {"width": 16384.00488281250000000001},
          "primitives": [{"type": "point", "pos": [[16777217, 0.1, -0.0]], "attr": [[1e-45]]}]})");
  EXPECT_EQ(bits(s.viewport->width), bits(16384.005859375f));
  EXPECT_EQ(bits(s.primitives[0].pos[0][0]), bits(16777216.0f));
  EXPECT_EQ(bits(s.primitives[0].pos[0][1]), bits(0.1f));
  EXPECT_EQ(bits(s.primitives[0].pos[0][2]), bits(-0.0f));
  EXPECT_EQ(bits(s.primitives[0].attr[0][0]), bits(std::numeric_limits<float>::denorm_min()));
}

// rule: SCENE.PIPELINE, SCENE.INPUT.ERRORS
TEST(PipelineSceneIo, ErrorsNameTheFieldAndComeInReadingOrder) {
  const std::string head = std::string("{") + kTarget + ", ";
  // The NaN in primitives[1] is found while reading (a type), before the missing attr of
  // primitives[0] (a rule of the scene, which the kernel's validator checks once it is read).
  EXPECT_EQ(
      error_of(
          head + R"("primitives": [)" + kPosTriangle +
          R"(, {"type": "point", "pos": [[0, 0, "NaN"]], "attr": [[1]]}], "attributes": [{"name": "a"}]})"),
      "primitives[1].pos[0][2]: is NaN");
  EXPECT_EQ(
      error_of(head + R"("primitives": [)" + kPosTriangle + R"(], "attributes": [{"name": "a"}]})"),
      "primitives[0].attr: is missing: the scene declares 1 attribute (PIPE.INPUT.ATTRIBUTES)");
  // Counts in every list.
  EXPECT_EQ(error_of(head +
                     R"("primitives": [{"type": "line_strip", "v": [[0, 0], [1, 1]], "z": [0]}]})"),
            "primitives[0].z: must have one number per vertex (2), got 1");
  EXPECT_EQ(error_of(head + R"("transform": {"view": []}, "primitives": []})"),
            "transform.view: must have exactly 16 numbers (a row-major 4x4 matrix), got 0");
  // The window-space coordinates keep their rules: NaN is the kernel's to reject.
  const auto nan_v = io::read_scene(
      head + R"("depth": {}, "primitives": [{"type": "point", "v": [["NaN", 1]]}]})");
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(nan_v));
  EXPECT_TRUE(std::isnan(std::get<rastrules::Scene>(nan_v).primitives[0].v[0][0]));
}

// rule: SCENE.PIPELINE
TEST(PipelineSceneIo, WriterRoundTripsAndSameSceneComparesEveryKey) {
  const rastrules::Scene s = pipe_ok(
      R"({"target": {"width": 16, "height": 8}, "samples": 4, "shading": "sample",
          "viewport": {"x": 1.5, "y": -2, "width": 10, "height": 6, "min_depth": 0.25, "max_depth": 0.75},
          "transform": {"view": [0.1, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1]},
          "depth": {"format": "d32f", "func": "not_equal", "write": false, "clear": 0.3,
                    "clip": false, "bias": 7, "slope_scaled_bias": 1e-3, "bias_clamp": 0.5},
          "attributes": [{"name": "u \"quoted\"\\", "interpolation": "linear", "location": "centroid"},
                         {"name": "id", "interpolation": "flat", "location": "sample"}],
          "provoking_vertex": "last",
          "primitives": [
            {"type": "triangle", "pos": [[1, 2, 3], [4, 5, 6, 7], [8, 9, 10, 11]],
             "attr": [[0, 1], [3, 4], [6, 7]]},
            {"type": "line_strip", "v": [[1, 1], [5, 2], [3, 3]], "z": [0.5, 1, 0], "w": [1, 4, 0.5],
             "attr": [[1, 2], [4, 5], [7, 8]], "color": [1, 2, 3, 4]}]})");
  const std::string text = io::write_scene(s);
  const auto back = io::read_scene(text);
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(back)) << text;
  EXPECT_TRUE(io::same_scene(std::get<rastrules::Scene>(back), s)) << text;
  EXPECT_EQ(io::write_scene(std::get<rastrules::Scene>(back)), text);

  // A scene without pipeline state writes no pipeline key and reads back as itself.
  rastrules::Scene minimal;
  minimal.width = 2;
  minimal.height = 2;
  const auto min_back = io::read_scene(io::write_scene(minimal));
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(min_back));
  EXPECT_TRUE(io::same_scene(std::get<rastrules::Scene>(min_back), minimal));
  EXPECT_EQ(io::write_scene(minimal).find("provoking_vertex"), std::string::npos);

  // Every change is seen.
  std::vector<rastrules::Scene> variants;
  auto variant = [&](auto change) {
    rastrules::Scene v = s;
    change(v);
    variants.push_back(v);
  };
  variant([](rastrules::Scene& v) { v.viewport.reset(); });
  variant([](rastrules::Scene& v) { v.viewport->max_depth = 1.0f; });
  variant([](rastrules::Scene& v) { v.view.reset(); });
  variant([](rastrules::Scene& v) { (*v.view)[3] = -0.0f; });
  variant([](rastrules::Scene& v) { v.model = pipe::Mat4f{}; });
  variant([](rastrules::Scene& v) { v.depth.reset(); });
  variant([](rastrules::Scene& v) { v.depth->func = pipe::CompareFunc::kEqual; });
  variant([](rastrules::Scene& v) { v.depth->bias.clamp = 0.25f; });
  variant([](rastrules::Scene& v) { v.attributes[1].location = pipe::Location::kCenter; });
  variant([](rastrules::Scene& v) { v.attributes[0].name = "u"; });
  variant([](rastrules::Scene& v) { v.conventions.provoking = pipe::Provoking::kFirst; });
  variant([](rastrules::Scene& v) { v.primitives[0].pos[2][3] = 12.0f; });
  variant([](rastrules::Scene& v) { v.primitives[1].z[0] = 0.25f; });
  variant([](rastrules::Scene& v) { v.primitives[1].w.clear(); });
  variant([](rastrules::Scene& v) { v.primitives[1].attr[2][1] = 9.0f; });
  variant([](rastrules::Scene& v) { v.msaa.quads = true; });
  for (std::size_t i = 0; i < variants.size(); ++i) {
    SCOPED_TRACE(io::write_scene(variants[i]));
    EXPECT_FALSE(io::same_scene(variants[i], s)) << i;
    const auto r = io::read_scene(io::write_scene(variants[i]));
    ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(r)) << i;
    EXPECT_TRUE(io::same_scene(std::get<rastrules::Scene>(r), variants[i])) << i;
  }
}

TEST(PipelineSceneIo, JsonStringEscapesQuotesBackslashesAndControls) {
  EXPECT_EQ(io::json_string("uv"), "\"uv\"");
  EXPECT_EQ(io::json_string("a\"b\\c\n\x01"), "\"a\\\"b\\\\c\\u000a\\u0001\"");
  EXPECT_EQ(io::json_string("\xc3\xa9"), "\"\xc3\xa9\"");
}

// A fragment and its data, as run_pipeline returns them in parallel arrays.
struct Frag {
  rastrules::Fragment f;
  pipe::FragmentData d;
};

Frag fragment(std::uint32_t prim, std::int32_t x, std::int32_t y, std::uint32_t mask) {
  Frag r;
  r.f = rastrules::Fragment(prim, x, y, mask);
  r.d.passed = mask;
  return r;
}

std::optional<std::string> to_json(const std::vector<Frag>& list,
                                   const io::PipeOutputFields& fields) {
  std::vector<rastrules::Fragment> fragments;
  std::vector<pipe::FragmentData> data;
  for (const Frag& x : list) {
    fragments.push_back(x.f);
    data.push_back(x.d);
  }
  return io::pipe_fragments_to_json(fragments, data, fields);
}

// rule: SCENE.OUTPUT.PIPELINE
TEST(PipelineFragmentOutput, FieldsInOrderFloatsRoundTripDepthAsStored) {
  io::PipeOutputFields fields;
  fields.attributes = {"u", "t\"q"};
  fields.depth = pipe::DepthFormat::kD24;
  Frag a = fragment(0, 3, 1, 5);
  a.d.part = 1;
  a.d.bary = pipe::Barycentrics{{120, 7, 129}, 256};
  a.d.attr = {0.1f, -3.0e-7f};
  a.d.depth = {pipe::DepthValue{8388608, 0.0f}, pipe::DepthValue{16777215, 0.0f}};
  a.d.passed = 4;
  Frag b = fragment(0, 0, 2, 1);
  b.d.part = 1;
  b.d.bary = pipe::Barycentrics{{0, 0, 1}, 1};
  b.d.attr = {1.0f, 16777216.0f};
  b.d.depth = {pipe::DepthValue{0, 0.0f}};
  // Killed by the depth test (PIPE.DEPTH.KILL): no bary, attr or depth, passed 0.
  Frag killed = fragment(1, 0, 0, 1);
  killed.d.passed = 0;
  const auto text = to_json({a, b, killed}, fields);
  ASSERT_TRUE(text.has_value());
  EXPECT_EQ(
      *text,
      "{\"fragments\": [\n"
      "  {\"prim\": 0, \"part\": 1, \"x\": 3, \"y\": 1, \"mask\": 5, \"bary\": [120, 7, 129, 256], "
      "\"attr\": {\"u\": 0.1, \"t\\\"q\": -3e-07}, \"depth\": [8388608, 16777215], \"passed\": "
      "4},\n"
      "  {\"prim\": 0, \"part\": 1, \"x\": 0, \"y\": 2, \"mask\": 1, \"bary\": [0, 0, 1, 1], "
      "\"attr\": {\"u\": 1, \"t\\\"q\": 16777216}, \"depth\": [0], \"passed\": 1},\n"
      "  {\"prim\": 1, \"x\": 0, \"y\": 0, \"mask\": 1, \"passed\": 0}\n"
      "]}\n");
  // The floats read back to the same float32.
  const auto doc = nlohmann::json::parse(*text);
  EXPECT_EQ(static_cast<float>(doc["fragments"][0]["attr"]["u"].get<double>()), 0.1f);
  EXPECT_EQ(static_cast<float>(doc["fragments"][0]["attr"]["t\"q"].get<double>()), -3.0e-7f);

  // d32f depths are floats; without depth or attributes only the plain fields (and bary, part
  // when given).
  io::PipeOutputFields f32;
  f32.depth = pipe::DepthFormat::kD32F;
  Frag c = fragment(2, 1, 1, 1);
  c.d.depth = {pipe::DepthValue{0, 0.3f}};
  EXPECT_EQ(to_json({c}, f32), "{\"fragments\": [\n  {\"prim\": 2, \"x\": 1, \"y\": 1, \"mask\": "
                               "1, \"depth\": [0.3], \"passed\": 1}\n]}\n");
  Frag d = fragment(0, 1, 1, 1);
  d.f.seg = 2;
  d.d.part = 3;
  EXPECT_EQ(to_json({d}, io::PipeOutputFields{}),
            "{\"fragments\": [\n  {\"prim\": 0, \"part\": 3, \"x\": 1, \"y\": 1, \"mask\": 1, "
            "\"seg\": 2}\n]}\n");
  // No data at all (a window-space scene without depth or attributes).
  EXPECT_EQ(
      io::pipe_fragments_to_json({d.f}, {}, io::PipeOutputFields{}),
      "{\"fragments\": [\n  {\"prim\": 0, \"x\": 1, \"y\": 1, \"mask\": 1, \"seg\": 2}\n]}\n");
  EXPECT_EQ(io::pipe_fragments_to_json({}, {}, io::PipeOutputFields{}), "{\"fragments\": []}\n");
  EXPECT_FALSE(io::pipe_fragments_to_json({d.f, d.f}, {d.d}, io::PipeOutputFields{}).has_value());
}

// rule: SCENE.OUTPUT.PIPELINE
TEST(PipelineFragmentOutput, OrderIsPrimPartYXAndFieldsMustMatch) {
  const io::PipeOutputFields none;
  const Frag p0 = fragment(0, 5, 5, 1);
  Frag p1a = fragment(1, 5, 5, 1);
  p1a.d.part = 0;
  Frag p1b = fragment(1, 0, 0, 1);
  p1b.d.part = 1; // a later part may start above and left of the earlier one
  const Frag unparted = fragment(1, 9, 9, 1);
  EXPECT_TRUE(to_json({p0, p1a, p1b}, none).has_value());
  EXPECT_FALSE(to_json({p1b, p1a}, none).has_value());
  EXPECT_FALSE(to_json({p1a, p1a}, none).has_value());
  EXPECT_FALSE(to_json({p1a, unparted}, none).has_value()); // a missing part comes first
  EXPECT_TRUE(to_json({unparted, p1a}, none).has_value());
  // One value per attribute, one depth per covered sample; a killed fragment has neither.
  io::PipeOutputFields attrs;
  attrs.attributes = {"u"};
  EXPECT_FALSE(to_json({p0}, attrs).has_value());
  EXPECT_FALSE(io::pipe_fragments_to_json({p0.f}, {}, attrs).has_value());
  io::PipeOutputFields depth;
  depth.depth = pipe::DepthFormat::kD16;
  Frag two = fragment(0, 1, 1, 3);
  two.d.depth = {pipe::DepthValue{1, 0.0f}};
  EXPECT_FALSE(to_json({two}, depth).has_value());
  two.d.depth.push_back(pipe::DepthValue{65535, 0.0f});
  EXPECT_TRUE(to_json({two}, depth).has_value());
  two.d.passed = 0;
  EXPECT_FALSE(to_json({two}, depth).has_value()); // killed, yet with depths

  // The streaming writer applies the same checks.
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  io::FragmentWriter writer(out, none);
  EXPECT_TRUE(writer.add(p1a.f, &p1a.d));
  EXPECT_FALSE(writer.add(p0.f, &p0.d));
  EXPECT_TRUE(writer.add(p1b.f, &p1b.d));
  EXPECT_TRUE(writer.finish());
  EXPECT_EQ(writer.count(), 2u);
  std::fclose(out);
}

// rule: SCENE.OUTPUT.PIPELINE
TEST(PipelineFragmentOutput, DepthBufferOneTargetRowPerLine) {
  const rastrules::test::TempDir dir;
  const auto path = dir / "depth.json";
  std::FILE* out = std::fopen(path.c_str(), "wb");
  ASSERT_NE(out, nullptr);
  const std::vector<pipe::DepthValue> buffer = {{0, 0.5f}, {0, 1.0f}, {0, 0.25f}, {0, 1.0f},
                                                {0, 0.0f}, {0, 1.0f}, {0, 1.0f},  {0, 1.0f}};
  EXPECT_TRUE(io::write_depth_buffer(out, 2, 2, 2, pipe::DepthFormat::kD32F, buffer));
  EXPECT_FALSE(io::write_depth_buffer(out, 3, 2, 2, pipe::DepthFormat::kD32F, buffer));
  std::fclose(out);
  const std::string text = rastrules::test::read_file(path);
  EXPECT_EQ(text.substr(0, text.find("\n]}\n") + 4),
            "{\"format\": \"d32f\", \"width\": 2, \"height\": 2, \"samples\": 2, \"depth\": [\n"
            "  0.5, 1, 0.25, 1,\n"
            "  0, 1, 1, 1\n"
            "]}\n");
  EXPECT_EQ(io::depth_text(pipe::DepthValue{65535, 0.0f}, pipe::DepthFormat::kD16), "65535");
  EXPECT_EQ(io::depth_text(pipe::DepthValue{0, 0.1f}, pipe::DepthFormat::kD32F), "0.1");
}

} // namespace
