// SPDX-License-Identifier: MIT
// The C API (rastrules/rastrules.h) against the C++ library it wraps: bad JSON, bad scenes and
// limits give their code and the library's one-line message; NULL arguments give
// RR_ERROR_NULL_ARGUMENT; fragments equal render() and run_pipeline() field for field; the
// explanation equals io::explain_*_pixel; handles are released (ASan's leak check in the
// sanitizer stage of scripts/test).

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "rastrules/io/explain.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/profile.hpp"
#include "rastrules/rastrules.h"
#include "rastrules/scene.hpp"

namespace rastrules {
namespace {

const std::string kSource = RASTRULES_SOURCE_DIR;

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scene handle released at the end of the scope.
struct SceneHandle {
  rr_scene* p = nullptr;
  ~SceneHandle() { rr_scene_free(p); }
};
struct RenderHandle {
  rr_render* p = nullptr;
  ~RenderHandle() { rr_render_free(p); }
};

rr_status from_json(const std::string& text, SceneHandle& h) {
  return rr_scene_from_json(text.data(), text.size(), &h.p);
}

// The reader's error for a text (what the C API must pass on).
std::string reader_error(const std::string& text) {
  const auto r = io::read_scene(text);
  EXPECT_TRUE(std::holds_alternative<SceneError>(r));
  return std::holds_alternative<SceneError>(r) ? std::get<SceneError>(r).what() : "";
}

const char* kTriangle = R"({"target": {"width": 16, "height": 8}, "primitives": [
  {"type": "triangle", "v": [[1, 1], [9.5, 2], [2, 7.25]]}]})";

TEST(CApi, VersionIsTheProjectVersion) {
  EXPECT_STREQ(RASTRULES_VERSION_STRING, RASTRULES_PROJECT_VERSION);
  EXPECT_STREQ(rr_version(), RASTRULES_VERSION_STRING);
  EXPECT_EQ(std::to_string(RASTRULES_VERSION_MAJOR) + "." +
                std::to_string(RASTRULES_VERSION_MINOR) + "." +
                std::to_string(RASTRULES_VERSION_PATCH),
            RASTRULES_VERSION_STRING);
}

// rule: SCENE.INPUT.ERRORS
TEST(CApi, MalformedJsonIsBadSceneWithTheParserPosition) {
  SceneHandle h;
  const std::string text = "{\"target\":";
  EXPECT_EQ(from_json(text, h), RR_ERROR_BAD_SCENE);
  EXPECT_EQ(h.p, nullptr);
  EXPECT_EQ(std::string(rr_last_error()),
            "(json): " + std::get<SceneError>(io::read_scene(text)).message);
  EXPECT_EQ(std::string(rr_last_error()).rfind("(json): parse error at line 1, column ", 0), 0u)
      << rr_last_error();
}

// rule: SCENE.INPUT.ERRORS
TEST(CApi, BadFieldIsBadSceneWithTheReadersMessage) {
  const std::string text = R"({"target": {"width": 4, "height": 4}, "primitives": [
    {"type": "triangle", "v": [[0, 0], [1, "x"], [2, 2]]}]})";
  SceneHandle h;
  EXPECT_EQ(from_json(text, h), RR_ERROR_BAD_SCENE);
  EXPECT_EQ(h.p, nullptr);
  EXPECT_EQ(std::string(rr_last_error()), reader_error(text));
  EXPECT_EQ(std::string(rr_last_error()).rfind("primitives[0].v[1][1]: must be a number", 0), 0u);
}

// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID
TEST(CApi, KernelChecksAreMadeWhenTheSceneIsRead) {
  for (const std::string& text :
       {std::string(R"({"target": {"width": 0, "height": 4}, "primitives": []})"),
        std::string(R"({"target": {"width": 4, "height": 4}, "primitives": [
              {"type": "triangle", "v": [[0, 0], ["NaN", 1], [2, 2]]}]})")}) {
    const Scene scene = std::get<Scene>(io::read_scene(text));
    const auto prepared = prepare(scene);
    ASSERT_TRUE(std::holds_alternative<SceneError>(prepared));
    SceneHandle h;
    EXPECT_EQ(from_json(text, h), RR_ERROR_BAD_SCENE);
    EXPECT_EQ(h.p, nullptr);
    EXPECT_EQ(std::string(rr_last_error()), std::get<SceneError>(prepared).what());
  }
}

// rule: SCENE.PIPELINE, PIPE.INPUT.ATTRIBUTES
TEST(CApi, PipelineValidationIsMadeWhenTheSceneIsRead) {
  const std::string text = R"({"target": {"width": 4, "height": 4},
    "attributes": [{"name": "u"}],
    "primitives": [{"type": "triangle", "v": [[0, 0], [3, 0], [0, 3]], "attr": [[1], [2]]}]})";
  const auto read = io::read_scene(text);
  std::string expected;
  if (const auto* e = std::get_if<SceneError>(&read)) {
    expected = e->what();
  } else {
    const auto err = pipe::validate(std::get<Scene>(read));
    ASSERT_TRUE(err.has_value());
    expected = err->what();
  }
  SceneHandle h;
  EXPECT_EQ(from_json(text, h), RR_ERROR_BAD_SCENE);
  EXPECT_EQ(std::string(rr_last_error()), expected);
}

// rule: SCENE.INPUT.ERRORS
TEST(CApi, FilesAreNamedInTheirErrors) {
  SceneHandle h;
  EXPECT_EQ(rr_scene_from_file("/nonexistent/scene.json", &h.p), RR_ERROR_FILE);
  EXPECT_EQ(h.p, nullptr);
  EXPECT_NE(std::string(rr_last_error()).find("/nonexistent/scene.json"), std::string::npos);
  const std::string path = ::testing::TempDir() + "capi_bad.json";
  std::ofstream(path) << "{\"target\": ";
  EXPECT_EQ(rr_scene_from_file(path.c_str(), &h.p), RR_ERROR_BAD_SCENE);
  EXPECT_EQ(std::string(rr_last_error()).rfind(path + ": parse error at line 1", 0), 0u)
      << rr_last_error();
  EXPECT_EQ(rr_scene_from_file((kSource + "/examples/scenes/triangle_and_line.json").c_str(), &h.p),
            RR_OK);
  EXPECT_NE(h.p, nullptr);
  EXPECT_STREQ(rr_last_error(), "");
}

// rule: SCENE.INPUT.LIMITS
TEST(CApi, SceneTextLargerThanTheLimitIsRefused) {
  const std::string text(io::kMaxSceneBytes + 1, ' ');
  SceneHandle h;
  EXPECT_EQ(from_json(text, h), RR_ERROR_BAD_SCENE);
  EXPECT_NE(std::string(rr_last_error()).find("limit SCENE.INPUT.LIMITS"), std::string::npos);
}

// rule: SCENE.INPUT.LIMITS
TEST(CApi, RenderLimitsAreLimitErrors) {
  SceneHandle h;
  ASSERT_EQ(from_json(kTriangle, h), RR_OK);
  RenderHandle r;
  rr_render_options few{3, 0};
  EXPECT_EQ(rr_render_scene(h.p, &few, &r.p), RR_ERROR_LIMIT);
  EXPECT_EQ(r.p, nullptr);
  EXPECT_EQ(std::string(rr_last_error()),
            "render: more than 3 fragments (limit SCENE.INPUT.LIMITS); raise it with "
            "rr_render_options.max_fragments");
  rr_render_options little{0, 10};
  EXPECT_EQ(rr_render_scene(h.p, &little, &r.p), RR_ERROR_LIMIT);
  EXPECT_EQ(std::string(rr_last_error()), "render: primitives[0] " + work_limit_problem(10) +
                                              "; raise it with rr_render_options.max_work");
  // A pipeline scene: run_pipeline's limit.
  SceneHandle pipeline;
  ASSERT_EQ(
      rr_scene_from_file((kSource + "/spec/cases/lines_and_points.json").c_str(), &pipeline.p),
      RR_OK);
  EXPECT_EQ(rr_render_scene(pipeline.p, &few, &r.p), RR_ERROR_LIMIT);
  EXPECT_NE(std::string(rr_last_error()).find("SCENE.INPUT.LIMITS"), std::string::npos)
      << rr_last_error();
  EXPECT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  EXPECT_STREQ(rr_last_error(), "");
}

TEST(CApi, NullArgumentsAreErrorsNeverCrashes) {
  SceneHandle h;
  ASSERT_EQ(from_json(kTriangle, h), RR_OK);
  RenderHandle r;
  ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  rr_scene* s = nullptr;
  rr_render* rp = nullptr;
  rr_fragment f;
  rr_scene_info info;
  size_t n = 0;
  char* text = nullptr;
  const std::vector<rr_status> got = {
      rr_scene_from_json(nullptr, 3, &s),      rr_scene_from_json("{}", 2, nullptr),
      rr_scene_from_file(nullptr, &s),         rr_scene_from_file("x.json", nullptr),
      rr_scene_set_profile(nullptr, "vulkan"), rr_scene_set_profile(h.p, nullptr),
      rr_scene_get_info(nullptr, &info),       rr_scene_get_info(h.p, nullptr),
      rr_render_scene(nullptr, nullptr, &rp),  rr_render_scene(h.p, nullptr, nullptr),
      rr_render_fragment_count(nullptr, &n),   rr_render_fragment_count(r.p, nullptr),
      rr_render_fragment(nullptr, 0, &f),      rr_render_fragment(r.p, 0, nullptr),
      rr_explain(nullptr, 0, 0, 0, &text),     rr_explain(h.p, 0, 0, 0, nullptr),
  };
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i], RR_ERROR_NULL_ARGUMENT) << "call " << i;
  }
  EXPECT_EQ(s, nullptr);
  EXPECT_EQ(rp, nullptr);
  EXPECT_EQ(text, nullptr);
  EXPECT_EQ(std::string(rr_last_error()), "rr_explain: out is NULL");
  rr_scene_free(nullptr);
  rr_render_free(nullptr);
  rr_string_free(nullptr);
  EXPECT_STREQ(rr_status_name(RR_ERROR_NULL_ARGUMENT), "RR_ERROR_NULL_ARGUMENT");
  EXPECT_STREQ(rr_status_name(RR_ERROR_INTERNAL), "RR_ERROR_INTERNAL");
}

TEST(CApi, IndexAndPixelOutsideAreOutOfRange) {
  SceneHandle h;
  ASSERT_EQ(from_json(kTriangle, h), RR_OK);
  RenderHandle r;
  ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  size_t n = 0;
  ASSERT_EQ(rr_render_fragment_count(r.p, &n), RR_OK);
  rr_fragment f;
  EXPECT_EQ(rr_render_fragment(r.p, n, &f), RR_ERROR_OUT_OF_RANGE);
  char* text = nullptr;
  EXPECT_EQ(rr_explain(h.p, 16, 0, 0, &text), RR_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(rr_explain(h.p, -1, 0, 0, &text), RR_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(std::string(rr_last_error()), "rr_explain: (-1, 0) is outside the 16x8 target");
  EXPECT_EQ(text, nullptr);
}

// Every fragment of the C API against the C++ library's (and run_pipeline's data).
void expect_same_fragments(const rr_render* r, const std::vector<Fragment>& want,
                           const std::vector<pipe::FragmentData>& data, bool depth) {
  size_t n = 0;
  ASSERT_EQ(rr_render_fragment_count(r, &n), RR_OK);
  ASSERT_EQ(n, want.size());
  for (std::size_t i = 0; i < n; ++i) {
    rr_fragment f;
    ASSERT_EQ(rr_render_fragment(r, i, &f), RR_OK);
    const Fragment& w = want[i];
    EXPECT_EQ(f.prim, w.prim);
    EXPECT_EQ(f.x, w.x);
    EXPECT_EQ(f.y, w.y);
    EXPECT_EQ(f.mask, w.mask);
    EXPECT_EQ((f.flags & RR_FRAGMENT_SEG) != 0, w.seg.has_value());
    EXPECT_EQ(f.seg, w.seg.value_or(0));
    EXPECT_EQ(f.sample, w.sample.value_or(0));
    EXPECT_EQ((f.flags & RR_FRAGMENT_HELPER) != 0, w.helper);
    EXPECT_EQ(f.coverage_q16, w.coverage_q16.value_or(0));
    EXPECT_EQ((f.flags & RR_FRAGMENT_CENTROID) != 0, w.centroid.has_value());
    if (w.centroid) {
      EXPECT_EQ(f.centroid_x, w.centroid->offset.x);
      EXPECT_EQ(f.centroid_y, w.centroid->offset.y);
    }
    EXPECT_EQ((f.flags & RR_FRAGMENT_AREA) != 0, static_cast<bool>(w.area));
    if (w.area) {
      EXPECT_EQ(f.area, w.area.approx());
      EXPECT_EQ(f.alpha, w.area.alpha());
      EXPECT_EQ(std::string(f.area_text), w.area.text());
    }
    if (data.empty()) {
      EXPECT_EQ(f.passed, w.mask);
      EXPECT_EQ(f.attr_count, 0u);
      EXPECT_EQ(f.depth_count, 0u);
      continue;
    }
    const pipe::FragmentData& d = data[i];
    EXPECT_EQ(f.part, d.part.value_or(0));
    EXPECT_EQ(f.passed, d.passed);
    ASSERT_EQ(f.attr_count, d.attr.size());
    for (std::size_t k = 0; k < d.attr.size(); ++k)
      EXPECT_EQ(f.attr[k], d.attr[k]);
    EXPECT_EQ((f.flags & RR_FRAGMENT_DEPTH) != 0, depth);
    ASSERT_EQ(f.depth_count, d.depth.size());
    if (d.bary) {
      EXPECT_EQ(f.bary[0], d.bary->e[0]);
      EXPECT_EQ(f.bary_area, d.bary->area);
    }
  }
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA, SCENE.OUTPUT.AREA
TEST(CApi, FragmentsEqualTheLibrarysRender) {
  for (const char* name :
       {"/examples/scenes/triangle_and_line.json", "/tests/capi/scenes/msaa_strip_aa.json",
        "/tests/capi/scenes/path_area.json"}) {
    SCOPED_TRACE(name);
    const std::string text = file_text(kSource + name);
    const Scene scene = std::get<Scene>(io::read_scene(text));
    const auto want = render(scene);
    ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(want));
    ASSERT_FALSE(std::get<std::vector<Fragment>>(want).empty());
    SceneHandle h;
    ASSERT_EQ(from_json(text, h), RR_OK);
    RenderHandle r;
    ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
    expect_same_fragments(r.p, std::get<std::vector<Fragment>>(want), {}, false);
  }
}

// rule: SCENE.OUTPUT.PIPELINE
TEST(CApi, PipelineFragmentsCarryDepthAndAttributes) {
  const std::string text = file_text(kSource + "/spec/cases/lines_and_points.json");
  const Scene scene = std::get<Scene>(io::read_scene(text));
  const auto want = pipe::run_pipeline(scene);
  ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(want));
  const pipe::PipeResult& w = std::get<pipe::PipeResult>(want);
  ASSERT_FALSE(w.data.empty());
  SceneHandle h;
  ASSERT_EQ(from_json(text, h), RR_OK);
  rr_scene_info info;
  ASSERT_EQ(rr_scene_get_info(h.p, &info), RR_OK);
  EXPECT_NE(info.pipeline, 0);
  EXPECT_EQ(info.attributes, scene.attributes.size());
  RenderHandle r;
  ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  // The render keeps its own copy: freeing the scene first leaves every pointer valid.
  rr_scene_free(h.p);
  h.p = nullptr;
  expect_same_fragments(r.p, w.fragments, w.data, scene.depth.has_value());
  rr_fragment f;
  ASSERT_EQ(rr_render_fragment(r.p, 0, &f), RR_OK);
  if (scene.depth && !w.data[0].depth.empty()) {
    const pipe::DepthValue d = w.data[0].depth[0];
    EXPECT_EQ(f.depth[0], scene.conventions.depth == pipe::DepthFormat::kD32F
                              ? static_cast<double>(d.f)
                              : static_cast<double>(d.unorm));
  }
}

// rule: PROFILE.CONVENTIONS, PROFILE.VULKAN
TEST(CApi, ProfileGivesTheProfilesConventions) {
  const std::string text = R"({"target": {"width": 12, "height": 8}, "cull": "back",
    "primitives": [{"type": "triangle", "v": [[1, 1], [2, 7], [10, 2]]},
                   {"type": "line", "v": [[0.5, 0.5], [11, 7]]}]})";
  Scene scene = std::get<Scene>(io::read_scene(text));
  apply(profile(ProfileName::kVulkan), scene);
  const auto want = render(scene);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(want));
  SceneHandle h;
  ASSERT_EQ(from_json(text, h), RR_OK);
  EXPECT_EQ(rr_scene_set_profile(h.p, "metal"), RR_ERROR_UNKNOWN_NAME);
  EXPECT_EQ(std::string(rr_last_error()),
            "rr_scene_set_profile: unknown profile \"metal\" (d3d11, vulkan, opengl)");
  ASSERT_EQ(rr_scene_set_profile(h.p, "vulkan"), RR_OK);
  RenderHandle r;
  ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  expect_same_fragments(r.p, std::get<std::vector<Fragment>>(want), {}, false);
}

// rule: SCENE.PRIM.LINE, SCENE.LINE_MODE
TEST(CApi, ProfileThatMakesTheSceneInvalidLeavesItUnchanged) {
  const std::string text = R"({"target": {"width": 8, "height": 8},
    "primitives": [{"type": "line", "v": [[0.5, 0.5], [7, 5]], "aa": true}]})";
  SceneHandle h;
  ASSERT_EQ(from_json(text, h), RR_OK);
  EXPECT_EQ(rr_scene_set_profile(h.p, "vulkan"), RR_ERROR_BAD_SCENE);
  EXPECT_NE(std::string(rr_last_error()).find("primitives[0]"), std::string::npos)
      << rr_last_error();
  RenderHandle r;
  ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
  const auto want = render(std::get<Scene>(io::read_scene(text)));
  expect_same_fragments(r.p, std::get<std::vector<Fragment>>(want), {}, false);
}

// rule: TRI.EDGE.FUNCTION, SCENE.OUTPUT.PIPELINE
TEST(CApi, ExplainIsTheLibrarysExplanation) {
  const std::string text = file_text(kSource + "/examples/scenes/triangle_and_line.json");
  const Scene scene = std::get<Scene>(io::read_scene(text));
  const PreparedScene prepared = std::get<PreparedScene>(prepare(scene));
  SceneHandle h;
  ASSERT_EQ(from_json(text, h), RR_OK);
  for (const int as_json : {0, 1}) {
    char* out = nullptr;
    ASSERT_EQ(rr_explain(h.p, 1, 1, as_json, &out), RR_OK);
    ASSERT_NE(out, nullptr);
    EXPECT_EQ(std::string(out), io::explain_window_pixel(scene, prepared, 1, 1, as_json != 0));
    if (as_json == 0) {
      EXPECT_NE(std::string(out).find("TRI.EDGE.FUNCTION: E > 0 -> inside"), std::string::npos);
      EXPECT_NE(std::string(out).find("pixel (1, 1): covered by primitive 0"), std::string::npos);
    }
    rr_string_free(out);
  }
  const std::string piped = file_text(kSource + "/spec/cases/lines_and_points.json");
  const Scene pscene = std::get<Scene>(io::read_scene(piped));
  const auto result = pipe::run_pipeline(pscene);
  ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(result));
  const Fragment& first = std::get<pipe::PipeResult>(result).fragments.at(0);
  SceneHandle p;
  ASSERT_EQ(from_json(piped, p), RR_OK);
  char* out = nullptr;
  ASSERT_EQ(rr_explain(p.p, first.x, first.y, 0, &out), RR_OK);
  const auto want = io::explain_pipeline_pixel(pscene, std::get<pipe::PipeResult>(result), first.x,
                                               first.y, false);
  EXPECT_EQ(std::string(out), std::get<std::string>(want));
  rr_string_free(out);
}

TEST(CApi, LastErrorIsPerThread) {
  SceneHandle h;
  EXPECT_EQ(from_json("[", h), RR_ERROR_BAD_SCENE);
  const std::string mine = rr_last_error();
  std::string theirs;
  std::thread([&] {
    theirs = rr_last_error();
    SceneHandle other;
    EXPECT_EQ(from_json(kTriangle, other), RR_OK);
  }).join();
  EXPECT_EQ(theirs, "");
  EXPECT_EQ(std::string(rr_last_error()), mine);
}

// Many handles made and released: under ASan (scripts/test's sanitizer stage) a leak fails.
TEST(CApi, HandlesAreReleased) {
  for (int i = 0; i < 50; ++i) {
    SceneHandle h;
    ASSERT_EQ(from_json(kTriangle, h), RR_OK);
    RenderHandle r;
    ASSERT_EQ(rr_render_scene(h.p, nullptr, &r.p), RR_OK);
    char* out = nullptr;
    ASSERT_EQ(rr_explain(h.p, 2, 2, i % 2, &out), RR_OK);
    rr_string_free(out);
    SceneHandle bad;
    EXPECT_EQ(from_json("{\"target\": 1}", bad), RR_ERROR_BAD_SCENE);
  }
}

} // namespace
} // namespace rastrules
