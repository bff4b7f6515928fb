// SPDX-License-Identifier: MIT
// Multisampling through the scene file and the command line: the new keys read, written back
// and compared; the fragment fields of SCENE.OUTPUT.MSAA on hand-checked scenes; render
// --resolve and its limit; the picture's sample points; explain per sample.
//
// The hand-checked scene: a 2x2 target, 4x standard pattern (offsets (-2,-6), (6,-2), (-6,2),
// (2,6) in 1/16 px), and the triangle (0,0), (2,0), (0,2), whose hypotenuse is x + y = 2.
// Pixel (0,0): every sample has x + y <= 1.5: mask 0b1111. Pixel (1,0): samples (1.375,
// 0.125), (1.875, 0.375), (1.125, 0.625), (1.625, 0.875) sum to 1.5, 2.25, 1.75, 2.5: samples 0
// and 2, mask 5; pixel (0,1) likewise; pixel (1,1): every sum >= 2.5: nothing.

#include <array>
#include <filesystem>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace {

using rastrules::test::read_file;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

constexpr const char* kTriangle =
    R"("primitives": [{"type": "triangle", "v": [[0, 0], [2, 0], [0, 2]]}]})";

std::string scene(const std::string& keys) {
  return R"({"target": {"width": 2, "height": 2}, "samples": 4, )" + keys + kTriangle;
}

std::string render_fragments(const std::string& text) {
  const TempDir dir;
  const auto path = dir.write("scene.json", text);
  const auto r = run_cli({"render", path.string(), "--fragments", "-"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return r.out;
}

// rule: SCENE.MSAA, SCENE.FORMAT.V1
TEST(CliMsaaSceneIo, ReadsEveryKeyIntoTheScene) {
  const auto read = rastrules::io::read_scene(
      R"({"target": {"width": 8, "height": 8}, "sample_pattern": [[-8, 7], [7, -8], [0, 0]],
          "sample_mask": 5, "centroid": "d3d10", "shading": "sample", "quads": true,
          "multisample_enable": true, "derivatives": "coarse", "clear_color": [1, 2, 3, 4],
          "primitives": [{"type": "point", "v": [[1, 1]], "color": [10, 20, 30, 40]}]})");
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(read))
      << std::get<rastrules::SceneError>(read).what();
  const rastrules::Scene& s = std::get<rastrules::Scene>(read);
  EXPECT_EQ(s.msaa.pattern.kind, rastrules::PatternKind::kCustom);
  ASSERT_EQ(s.msaa.pattern.count(), 3u);
  EXPECT_EQ(s.msaa.pattern.positions[0], (rastrules::SampleOffset{-8, 7}));
  EXPECT_EQ(s.msaa.pattern.positions[1], (rastrules::SampleOffset{7, -8}));
  EXPECT_EQ(s.msaa.sample_mask, 5u);
  EXPECT_TRUE(s.msaa.has_centroid);
  EXPECT_EQ(s.conventions.centroid, rastrules::CentroidRule::kD3D10);
  EXPECT_EQ(s.msaa.shading, rastrules::ShadingRate::kSample);
  EXPECT_TRUE(s.msaa.quads);
  EXPECT_TRUE(s.conventions.multisample_enable);
  EXPECT_EQ(s.msaa.derivatives, rastrules::DerivativeMode::kCoarse);
  // Written back only when set, and read back the same.
  const std::string text = rastrules::io::write_scene(s);
  EXPECT_NE(text.find("\"multisample_enable\": true"), std::string::npos);
  const auto again = rastrules::io::read_scene(text);
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(again));
  EXPECT_TRUE(rastrules::io::same_scene(std::get<rastrules::Scene>(again), s));
  rastrules::Scene off = s;
  off.conventions.multisample_enable = false;
  EXPECT_FALSE(rastrules::io::same_scene(off, s));
  EXPECT_EQ(rastrules::io::write_scene(off).find("multisample_enable"), std::string::npos);
  EXPECT_EQ(s.clear_color, (rastrules::Rgba8{1, 2, 3, 4}));
  EXPECT_EQ(s.primitives[0].color, (rastrules::Rgba8{10, 20, 30, 40}));
}

// rule: SCENE.MSAA, MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER
TEST(CliMsaaSceneIo, SamplesAndPatternNameInEitherOrder) {
  const auto a = rastrules::io::read_scene(
      R"({"sample_pattern": "center", "samples": 8, "target": {"width": 1, "height": 1}, "primitives": []})");
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(a));
  EXPECT_EQ(std::get<rastrules::Scene>(a).msaa.pattern, rastrules::center_pattern(8));
  const auto b = rastrules::io::read_scene(
      R"({"samples": 16, "target": {"width": 1, "height": 1}, "primitives": []})");
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(b));
  EXPECT_EQ(std::get<rastrules::Scene>(b).msaa.pattern, rastrules::standard_pattern(16));
  // Without the keys: one sample at the centre, all samples in the mask, white primitives.
  const auto c = rastrules::io::read_scene(R"({"target": {"width": 1, "height": 1}, )" +
                                           std::string(kTriangle));
  ASSERT_TRUE(std::holds_alternative<rastrules::Scene>(c));
  const rastrules::Scene& sc = std::get<rastrules::Scene>(c);
  EXPECT_EQ(sc.msaa.pattern, rastrules::standard_pattern(1));
  EXPECT_EQ(sc.msaa.sample_mask, 0xFFFFFFFFu);
  EXPECT_FALSE(sc.msaa.has_centroid);
  EXPECT_EQ(sc.primitives[0].color, (rastrules::Rgba8{255, 255, 255, 255}));
  EXPECT_EQ(sc.clear_color, (rastrules::Rgba8{0, 0, 0, 0}));
}

// rule: SCENE.MSAA, SCENE.FORMAT.V1
TEST(CliMsaaSceneIo, WriterRoundTripsTheKeysAndSameSceneComparesThem) {
  rastrules::Scene s;
  s.width = 4;
  s.height = 4;
  s.primitives.push_back(rastrules::make_triangle({{{0, 0}, {4, 0}, {0, 4}}}));
  // Defaults write no multisampling key at all.
  const std::string plain = rastrules::io::write_scene(s);
  for (const char* key : {"samples", "sample_pattern", "sample_mask", "centroid", "shading",
                          "quads", "derivatives", "clear_color", "color"}) {
    EXPECT_EQ(plain.find(std::string("\"") + key + "\""), std::string::npos) << key << "\n"
                                                                             << plain;
  }
  auto round_trips = [](const rastrules::Scene& scene) {
    const auto back = rastrules::io::read_scene(rastrules::io::write_scene(scene));
    if (!std::holds_alternative<rastrules::Scene>(back))
      return false;
    return rastrules::io::same_scene(std::get<rastrules::Scene>(back), scene);
  };
  std::vector<rastrules::Scene> variants;
  auto variant = [&](auto change) {
    rastrules::Scene v = s;
    change(v);
    variants.push_back(v);
  };
  variant([](rastrules::Scene& v) { set_sample_pattern(v, rastrules::standard_pattern(4)); });
  variant([](rastrules::Scene& v) { set_sample_pattern(v, rastrules::center_pattern(2)); });
  variant([](rastrules::Scene& v) { set_sample_pattern(v, rastrules::center_pattern(1)); });
  variant([](rastrules::Scene& v) {
    set_sample_pattern(v, rastrules::custom_pattern({{-8, -8}, {7, 7}}));
  });
  variant([](rastrules::Scene& v) { set_sample_pattern(v, rastrules::custom_pattern({{0, 0}})); });
  variant([](rastrules::Scene& v) { v.msaa.sample_mask = 0; });
  variant([](rastrules::Scene& v) { v.msaa.has_centroid = true; });
  variant([](rastrules::Scene& v) {
    v.msaa.has_centroid = true;
    v.conventions.centroid = rastrules::CentroidRule::kD3D10;
  });
  variant([](rastrules::Scene& v) { v.msaa.shading = rastrules::ShadingRate::kSample; });
  variant([](rastrules::Scene& v) { v.msaa.quads = true; });
  variant([](rastrules::Scene& v) { v.msaa.derivatives = rastrules::DerivativeMode::kFine; });
  variant([](rastrules::Scene& v) { v.msaa.derivatives = rastrules::DerivativeMode::kCoarse; });
  variant([](rastrules::Scene& v) { v.clear_color = {0, 0, 0, 1}; });
  variant([](rastrules::Scene& v) { v.primitives[0].color = {255, 255, 255, 254}; });
  for (std::size_t i = 0; i < variants.size(); ++i) {
    SCOPED_TRACE(rastrules::io::write_scene(variants[i]));
    EXPECT_TRUE(round_trips(variants[i]));
    EXPECT_FALSE(rastrules::io::same_scene(variants[i], s));
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_FALSE(rastrules::io::same_scene(variants[i], variants[j])) << j;
  }
}

// rule: SCENE.OUTPUT.MSAA, MSAA.COVER.SAMPLE, MSAA.MASK.AND
TEST(CliMsaaFragments, FourSamplesGiveTheHandCheckedMasks) {
  EXPECT_EQ(render_fragments(scene("")), "{\"fragments\": [\n"
                                         "  {\"prim\": 0, \"x\": 0, \"y\": 0, \"mask\": 15},\n"
                                         "  {\"prim\": 0, \"x\": 1, \"y\": 0, \"mask\": 5},\n"
                                         "  {\"prim\": 0, \"x\": 0, \"y\": 1, \"mask\": 5}\n"
                                         "]}\n");
  // The mask removes samples; a pixel left with none produces no fragment.
  EXPECT_EQ(render_fragments(scene("\"sample_mask\": 10, ")),
            "{\"fragments\": [\n"
            "  {\"prim\": 0, \"x\": 0, \"y\": 0, \"mask\": 10}\n"
            "]}\n");
}

// Sample mask 0b1110. D3D11 applies the mask first: pixel (0,0), fully covered, has covered
// samples 1, 2, 3 in the mask, not all four -> the first, sample 1 at (6, -2)/16; pixels (1,0) and
// (0,1) -> the first covered sample in the mask, sample 2 at (-6, 2)/16; the helper (1,1), with
// nothing covered and a partial mask -> the mask's first sample, sample 1 at (6, -2)/16.
// rule: SCENE.OUTPUT.MSAA, MSAA.CENTROID.D3D11, MSAA.QUAD.HELPER
TEST(CliMsaaFragments, CentroidD3D11AndAHelperLane) {
  EXPECT_EQ(render_fragments(scene(R"("sample_mask": 14, "centroid": "d3d11", "quads": true, )")),
            "{\"fragments\": [\n"
            "  {\"prim\": 0, \"x\": 0, \"y\": 0, \"mask\": 14, \"centroid\": [0.875, 0.375]},\n"
            "  {\"prim\": 0, \"x\": 1, \"y\": 0, \"mask\": 4, \"centroid\": [1.125, 0.625]},\n"
            "  {\"prim\": 0, \"x\": 0, \"y\": 1, \"mask\": 4, \"centroid\": [0.125, 1.625]},\n"
            "  {\"prim\": 0, \"x\": 1, \"y\": 1, \"mask\": 0, \"helper\": true, \"centroid\": "
            "[1.875, 1.375]}\n"
            "]}\n");
}

// D3D10: the mask applies first, so pixel (0,0) is no longer "covered": its covered samples in
// the mask (1, 2, 3) all lie at squared distance 40 from the centre; the lowest index, sample 1
// at (6, -2)/16, wins.
// rule: SCENE.OUTPUT.MSAA, MSAA.CENTROID.D3D10
TEST(CliMsaaFragments, CentroidD3D10AppliesTheMaskFirst) {
  const std::string out = render_fragments(scene(R"("sample_mask": 14, "centroid": "d3d10", )"));
  EXPECT_NE(
      out.find("{\"prim\": 0, \"x\": 0, \"y\": 0, \"mask\": 14, \"centroid\": [0.875, 0.375]}"),
      std::string::npos)
      << out;
}

// Sample shading: one fragment per covered sample, mask 1 << k; quads per sample index; the
// derivatives of a fixed sample position are one pixel across and down.
// rule: SCENE.OUTPUT.MSAA, MSAA.SHADING.SAMPLE, MSAA.QUAD.HELPER, MSAA.DERIV.COARSE
TEST(CliMsaaFragments, SampleShadingHelpersAndDerivatives) {
  const std::string out =
      render_fragments(scene(R"("shading": "sample", "derivatives": "coarse", )"));
  const auto doc = nlohmann::json::parse(out);
  const auto& list = doc.at("fragments");
  ASSERT_EQ(list.size(), 16u) << out; // 4 samples x 4 lanes of the one quad
  int covered = 0, helpers = 0;
  for (const auto& f : list) {
    const auto k = f.at("sample").get<unsigned>();
    EXPECT_EQ(f.at("ddx"), nlohmann::json::parse("[1.0, 0.0]"));
    EXPECT_EQ(f.at("ddy"), nlohmann::json::parse("[0.0, 1.0]"));
    if (f.contains("helper")) {
      EXPECT_EQ(f.at("helper"), true);
      EXPECT_EQ(f.at("mask"), 0);
      ++helpers;
    } else {
      EXPECT_EQ(f.at("mask").get<unsigned>(), 1u << k);
      ++covered;
    }
  }
  EXPECT_EQ(covered, 8); // 4 + 2 + 2
  EXPECT_EQ(helpers, 8);
  EXPECT_EQ(
      list[5].dump(),
      R"({"ddx":[1.0,0.0],"ddy":[0.0,1.0],"helper":true,"mask":0,"prim":0,"sample":1,"x":1,"y":0})");
}

// rule: MSAA.RESOLVE.AVERAGE, SCENE.OUTPUT.MSAA
TEST(CliMsaaResolve, AveragesTheSamplesRoundingHalfToEven) {
  const TempDir dir;
  const auto path =
      dir.write("scene.json",
                R"({"target": {"width": 2, "height": 2}, "samples": 4, "clear_color": [0, 0, 0, 0],
        "primitives": [{"type": "triangle", "v": [[0, 0], [2, 0], [0, 2]], "color": [255, 1, 3, 255]}]})");
  const auto r = run_cli({"render", path.string(), "--resolve", (dir / "r.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto png = rastrules::test::read_png_rgba(dir / "r.png");
  ASSERT_TRUE(png.has_value());
  ASSERT_EQ(png->width, 2u);
  ASSERT_EQ(png->height, 2u);
  using P = std::array<std::uint8_t, 4>;
  EXPECT_EQ(png->rgba_at(0, 0), (P{255, 1, 3, 255}));
  // 2 of 4 samples: 127.5 -> 128 (even), 0.5 -> 0 (even), 1.5 -> 2 (even).
  EXPECT_EQ(png->rgba_at(1, 0), (P{128, 0, 2, 128}));
  EXPECT_EQ(png->rgba_at(0, 1), (P{128, 0, 2, 128}));
  EXPECT_EQ(png->rgba_at(1, 1), (P{0, 0, 0, 0}));
}

// rule: MSAA.LIMITS, SCENE.INPUT.ERRORS
TEST(CliMsaaResolve, ATooLargeSampleBufferIsBadInputNamingTheLimit) {
  const TempDir dir;
  const auto path = dir.write(
      "scene.json",
      R"({"target": {"width": 16384, "height": 16384}, "samples": 16, "primitives": []})");
  const auto r = run_cli({"render", path.string(), "--resolve", (dir / "r.png").string(),
                          "--fragments", (dir / "f.json").string()});
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("--resolve: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(limit MSAA.LIMITS)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "r.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "f.json"));
  // One sample fits: 2^28 > 2^26 still does not; a 4096 x 4096 target at 4 samples does.
  const auto small =
      dir.write("small.json",
                R"({"target": {"width": 4096, "height": 4096}, "samples": 4, "primitives": []})");
  EXPECT_EQ(run_cli({"render", small.string(), "--resolve", (dir / "s.png").string()}).status, 0);
  const auto big =
      dir.write("big.json", R"({"target": {"width": 8192, "height": 8193}, "primitives": []})");
  EXPECT_EQ(run_cli({"render", big.string(), "--resolve", (dir / "b.png").string()}).status, 2);
}

// rule: SCENE.INPUT.ERRORS
TEST(CliMsaaResolve, OnlyOneOutputMayBeStandardOutput) {
  const TempDir dir;
  const auto path = dir.write("scene.json", scene(""));
  const auto r = run_cli({"render", path.string(), "--resolve", "-", "--fragments", "-"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("only one of --fragments, --png and --resolve can be standard output"),
            std::string::npos)
      << r.err;
  const auto s = run_cli({"render", path.string(), "--resolve"});
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.err.find("--resolve needs a file name"), std::string::npos) << s.err;
}

// The picture at 32 image pixels per pixel: pixel (i, j) spans [32 i, 32 i + 32); sample k is
// drawn at (32 i + 16 + 2 o.x, 32 j + 16 + 2 o.y): covered samples filled in the primitive's
// edge colour, uncovered ones hollow; the helper lane (1,1) outlined dashed in purple.
// rule: SCENE.OUTPUT.MSAA
TEST(CliMsaaPicture, ShowsSamplesCoveredSamplesAndHelperLanes) {
  const TempDir dir;
  const auto path = dir.write("scene.json", scene(R"("quads": true, )"));
  const auto r =
      run_cli({"render", path.string(), "--png", (dir / "p.png").string(), "--scale", "32"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto png = rastrules::test::read_png(dir / "p.png");
  ASSERT_TRUE(png.has_value());
  ASSERT_EQ(png->width, 65u);
  const rastrules::io::Rgb edge = rastrules::io::edge_colour(0);
  const rastrules::io::Rgb fill = rastrules::io::cover_colour(0);
  using C = std::array<std::uint8_t, 3>;
  const C edge_c{edge.r, edge.g, edge.b}, fill_c{fill.r, fill.g, fill.b};
  // Pixel (1,0): sample 0 at (-2,-6) covered -> filled; sample 1 at (6,-2) not -> hollow.
  EXPECT_EQ(png->at(32 + 16 - 4, 16 - 12), edge_c);
  EXPECT_EQ(png->at(32 + 16 + 12, 16 - 4), fill_c);
  // Pixel (1,1) is a helper lane: its dashed outline starts at (32 + 3, 32 + 3).
  EXPECT_EQ(png->at(35, 35), (C{150, 0, 150}));
  // ... and none of its samples is filled.
  EXPECT_EQ(png->at(32 + 16 - 4, 32 + 16 - 12), (C{255, 255, 255}));
}

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, TRI.FILL.TOP_LEFT
TEST(CliMsaaExplain, ListsEverySampleWithItsEdgesTiesMaskAndCentroid) {
  // The hypotenuse x + y = 1.75 is a right edge and runs through sample 2 of pixel (1,0),
  // (1.125, 0.625): a tie, outside under top-left. Sample 0, (1.375, 0.125), is inside;
  // samples 1 and 3 (sums 2.25 and 2.5) are outside.
  const TempDir dir;
  const auto path = dir.write(
      "scene.json", R"({"target": {"width": 2, "height": 2}, "samples": 4, "centroid": "d3d11",
        "sample_mask": 7, "primitives": [{"type": "triangle", "v": [[0, 0], [1.75, 0], [0, 1.75]]}]})");
  const auto r = run_cli({"explain", path.string(), "--pixel", "1,0"});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* line :
       {"multisampling: 4 samples, standard pattern, sample mask 0b0111 (samples 0, 1, 2), "
        "centroid d3d11",
        "  sample 0 at (-2, -6)/16 -> (1.375, 0.125) px = raw (352, 32)  [MSAA.SAMPLE.POSITION]\n",
        "  sample 2 at (-6, 2)/16 -> (1.125, 0.625) px = raw (288, 160)  [MSAA.SAMPLE.POSITION]\n"
        "    edge 0 v0->v1 (top): E = 71680 raw = 1.09375 px^2 -> inside: TRI.EDGE.FUNCTION: E > 0 "
        "-> inside\n"
        "    edge 1 v1->v2 (right): E = 0 raw = 0 px^2 -> outside: TRI.FILL.TOP_LEFT: E == 0 on a "
        "right edge "
        "(neither top nor left) -> outside\n",
        "  coverage 0b0001 (sample 0)  [MSAA.COVER.SAMPLE]\n",
        "  sample mask 0b0111 (samples 0, 1, 2) -> fragment mask 0b0001 (sample 0)  "
        "[MSAA.MASK.AND]\n",
        "  centroid (d3d11): first covered sample in index order -> (-2, -6)/16 = (1.375, 0.125) "
        "px  "
        "[MSAA.CENTROID.D3D11]\n",
        "  verdict: fragment, mask 1\n", "pixel (1, 0): covered by primitive 0\n"}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  }
  // The fragment list agrees with the explanation.
  const auto f = run_cli({"render", path.string(), "--fragments", "-"});
  EXPECT_NE(
      f.out.find("{\"prim\": 0, \"x\": 1, \"y\": 0, \"mask\": 1, \"centroid\": [1.375, 0.125]}"),
      std::string::npos)
      << f.out;

  const auto j = run_cli({"explain", path.string(), "--pixel", "1,0", "--json"});
  ASSERT_EQ(j.status, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc.at("samples"), 4);
  EXPECT_EQ(doc.at("sample_mask"), 7);
  const auto& m = doc.at("primitives").at(0).at("msaa");
  ASSERT_EQ(m.at("samples").size(), 4u);
  const auto& s2 = m.at("samples").at(2);
  EXPECT_EQ(s2.at("offset"), nlohmann::json::parse("[-6, 2]"));
  EXPECT_EQ(s2.at("covered"), false);
  bool tie = false;
  for (const auto& e : s2.at("triangles").at(0).at("edges"))
    tie = tie || (e.at("e_raw") == 0 && e.at("inside") == false);
  EXPECT_TRUE(tie) << s2.dump();
  EXPECT_EQ(m.at("samples").at(0).at("covered"), true);
  const auto& seg = m.at("segments").at(0);
  EXPECT_EQ(seg.at("coverage"), 1);
  EXPECT_EQ(seg.at("mask"), 1);
  EXPECT_EQ(seg.at("centroid").at("offset"), nlohmann::json::parse("[-2, -6]"));
  EXPECT_EQ(doc.at("covered_by"), nlohmann::json::parse("[0]"));
}

// A pixel whose covered samples the mask removes: no fragment, and explain says why.
// rule: MSAA.MASK.AND
TEST(CliMsaaExplain, APixelTheMaskEmptiesHasNoFragment) {
  const TempDir dir;
  const auto path = dir.write("scene.json", scene(R"("sample_mask": 2, )"));
  const auto r = run_cli({"explain", path.string(), "--pixel", "1,0"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  coverage 0b0101 (samples 0, 2)  [MSAA.COVER.SAMPLE]\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("-> fragment mask 0b0000 (no sample)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  verdict: no fragment\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pixel (1, 0): covered by no primitive\n"), std::string::npos) << r.out;
}

// Points are tested per sample (their two triangles); lines on a multisampled target are
// 1.4 px quadrilaterals tested per sample; Vulkan Bresenham lines cover whole pixels.
// rule: MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE
TEST(CliMsaaExplain, PointsAndLinesPerSample) {
  const TempDir dir;
  const auto point = dir.write("p.json", R"({"target": {"width": 4, "height": 4}, "samples": 4,
        "primitives": [{"type": "point", "v": [[2.0, 2.0]]}, {"type": "line", "v": [[0, 1.5], [4, 1.5]]}]})");
  const auto r = run_cli({"explain", point.string(), "--pixel", "1,1"});
  ASSERT_EQ(r.status, 0) << r.err;
  // The point's square [1.5, 2.5)^2 holds only sample 3 (1.625, 1.875) of the pixel: sample 0
  // (1.375, 1.125) and 2 (1.125, 1.625) lie left of it, sample 1 (1.875, 1.375) above it.
  EXPECT_NE(r.out.find("  coverage 0b1000 (sample 3)  [MSAA.COVER.SAMPLE]\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("    triangle 1:\n"), std::string::npos) << r.out;
  // The line y = 1.5 drawn 1.4 px wide covers every sample of row 1.
  EXPECT_NE(r.out.find("  coverage 0b1111 (samples 0, 1, 2, 3)  [MSAA.COVER.SAMPLE]\n"),
            std::string::npos)
      << r.out;
  const auto vk = dir.write(
      "v.json",
      R"({"target": {"width": 4, "height": 4}, "samples": 4, "line_mode": "vulkan-bresenham",
        "primitives": [{"type": "line", "v": [[0, 1.5], [4, 1.5]]}]})");
  const auto v = run_cli({"explain", vk.string(), "--pixel", "1,1"});
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_NE(v.out.find("line covers every sample of each pixel it produces  [MSAA.LINE.MODE]"),
            std::string::npos)
      << v.out;
}

// The fragment writer's exact decimals for centroids and derivatives.
// rule: SCENE.OUTPUT.MSAA
TEST(CliMsaaFragments, SixteenthsAreWrittenExactly) {
  rastrules::Fragment f{0, 3, 1, 4};
  f.centroid = rastrules::Centroid{{-8, 7}, rastrules::CentroidBranch::kFirstCovered};
  f.derivatives = rastrules::EvalDerivatives{17, -1, -16, 0};
  f.sample = 2;
  f.helper = true;
  EXPECT_EQ(rastrules::io::fragments_to_json({f}),
            "{\"fragments\": [\n  {\"prim\": 0, \"x\": 3, \"y\": 1, \"mask\": 4, \"sample\": 2, "
            "\"helper\": true, "
            "\"centroid\": [3.0, 1.9375], \"ddx\": [1.0625, -0.0625], \"ddy\": [-1.0, 0.0]}\n]}\n");
}

} // namespace
