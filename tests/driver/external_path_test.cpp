// SPDX-License-Identifier: MIT
// Paths through the external-process protocol (DRIVER.EXTERNAL.PATHS): the "paths" capability
// read strictly, "alpha" read and checked, the refusals a 2D library adapter gives; then the two
// Node drivers, Skia (canvaskit-wasm) and tiny-skia (@resvg/resvg-js), on shapes whose coverage
// is known without a rasterizer. The Node drivers' tests skip, with the reason, when a driver
// cannot be opened (no node, or no `npm ci` run in tools/driver/node).

#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/external.hpp"
#include "rastrules/scene.hpp"

// A namespace of its own: the test sources may be compiled as one unity file.
namespace rastrules::driver::external_paths {
namespace {

class TempDir {
public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("rastrules-paths-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Writes an executable script (its first line given, or /bin/sh) and returns its path.
  std::string script(const std::string& name, const std::string& body,
                     const std::string& interpreter = "#!/bin/sh") const {
    const auto p = path_ / name;
    std::ofstream(p) << interpreter << "\n" << body << "\n";
    ::chmod(p.c_str(), 0755);
    return p.string();
  }

private:
  std::filesystem::path path_;
};

FloatContour polygon(const std::vector<FloatPoint>& pts) {
  FloatContour c;
  c.start = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    FloatPathSegment s;
    s.p[0] = pts[i];
    c.segments.push_back(s);
  }
  return c;
}

Primitive path_prim(std::vector<FloatContour> contours, path::Coverage coverage,
                    path::FillRule rule = path::FillRule::kNonZero) {
  FloatPath p;
  p.fill_rule = rule;
  p.coverage = coverage;
  p.contours = std::move(contours);
  return make_path(std::move(p));
}

Scene path_scene(std::vector<FloatContour> contours, path::Coverage coverage,
                 path::FillRule rule = path::FillRule::kNonZero, std::int32_t side = 8) {
  Scene s;
  s.width = s.height = side;
  s.primitives.push_back(path_prim(std::move(contours), coverage, rule));
  return s;
}

const std::vector<FloatPoint> kSquare = {{2, 1}, {5, 1}, {5, 4}, {2, 4}};
const std::vector<FloatPoint> kHalfPixel = {{1, 1}, {2, 1}, {2, 2}};

// A driver that answers the capabilities query with `reply` and draws by writing `fragments`.
std::string fake_driver(const TempDir& dir, const std::string& name, const std::string& reply,
                        const std::string& fragments = R"({"fragments": []})") {
  return dir.script(name, "if [ \"$RASTRULES_QUERY\" = capabilities ]; then echo '" + reply +
                              "'; exit 0; fi\ncat > /dev/null; echo '" + fragments + "'");
}

const std::string kPathsReply =
    R"({"capabilities": {"primitives": ["path"], "sample_counts": [1], "paths": )"
    R"({"samples": true, "area": true, "fill_rules": ["nonzero"], "curves": ["quadratic"], )"
    R"("grid": "26.6", "aliased_method": "centres", "antialiased_method": "cells"}}})";

std::string parse_error(std::string_view text, const Scene& scene) {
  const auto r = parse_external_fragments(text, scene);
  return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string();
}

// rule: DRIVER.EXTERNAL.PATHS, DRIVER.EXTERNAL.CAPABILITIES
TEST(ExternalPaths, ThePathsCapabilityIsReadStrictly) {
  const auto ok = parse_capabilities(kPathsReply);
  ASSERT_TRUE(std::holds_alternative<Capabilities>(ok)) << std::get<std::string>(ok);
  const Capabilities& c = std::get<Capabilities>(ok);
  ASSERT_TRUE(c.paths.has_value());
  EXPECT_TRUE(c.paths->samples && c.paths->area && c.paths->nonzero && c.paths->quadratics);
  EXPECT_FALSE(c.paths->evenodd || c.paths->cubics);
  EXPECT_EQ(c.paths->grid, "26.6");
  EXPECT_EQ(c.paths->grid_raw, 4);
  EXPECT_EQ(c.paths->aliased_method, "centres");
  EXPECT_EQ(c.paths->antialiased_method, "cells");
  // Absent keys allow everything; "curves" may be empty (straight paths only); grids.
  const auto all = parse_capabilities(R"({"capabilities": {"paths": {"curves": []}}})");
  ASSERT_TRUE(std::holds_alternative<Capabilities>(all)) << std::get<std::string>(all);
  const PathSupport& a = *std::get<Capabilities>(all).paths;
  EXPECT_TRUE(a.samples && a.area && a.nonzero && a.evenodd);
  EXPECT_FALSE(a.quadratics || a.cubics);
  EXPECT_EQ(a.grid, "float");
  EXPECT_EQ(a.grid_raw, 1);
  for (const auto& [grid, raw] : {std::pair{"24.8", 1}, std::pair{"28.4", 16},
                                  std::pair{"16.16", 1}, std::pair{"32.0", 256}}) {
    const auto g = parse_capabilities(std::string(R"({"capabilities": {"paths": {"grid": ")") +
                                      grid + "\"}}}");
    ASSERT_TRUE(std::holds_alternative<Capabilities>(g)) << grid;
    EXPECT_EQ(std::get<Capabilities>(g).paths->grid_raw, raw) << grid;
  }
  const std::pair<const char*, const char*> bad[] = {
      {R"({"capabilities": {"paths": true}})", "capabilities: paths: expected an object"},
      {R"({"capabilities": {"paths": {"colour": 1}}})",
       "capabilities: paths: unknown key \"colour\""},
      {R"({"capabilities": {"paths": {"samples": 1}}})",
       "capabilities: paths.samples: expected true or false"},
      {R"({"capabilities": {"paths": {"fill_rules": ["winding"]}}})",
       "capabilities: paths.fill_rules: unknown name \"winding\" (known: nonzero, evenodd)"},
      {R"({"capabilities": {"paths": {"fill_rules": []}}})",
       "capabilities: paths.fill_rules: expected a non-empty array of names"},
      {R"({"capabilities": {"paths": {"curves": ["conic"]}}})",
       "capabilities: paths.curves: unknown name \"conic\" (known: quadratic, cubic)"},
      {R"({"capabilities": {"paths": {"curves": "cubic"}}})",
       "capabilities: paths.curves: expected an array"},
      {R"({"capabilities": {"paths": {"grid": "26,6"}}})",
       "capabilities: paths.grid: expected \"float\" or a fixed-point format \"I.F\""},
      {R"({"capabilities": {"paths": {"grid": "0.8"}}})", "capabilities: paths.grid: expected"},
      {R"({"capabilities": {"paths": {"grid": 8}}})", "capabilities: paths.grid: expected"},
      {R"({"capabilities": {"paths": {"aliased_method": ""}}})",
       "capabilities: paths.aliased_method: expected a text of 1 to 200 characters"},
      {R"({"capabilities": {"paths": {"samples": false, "area": false}}})",
       "capabilities: paths: neither \"samples\" nor \"area\" is drawn"},
      {R"({"capabilities": {"primitives": ["triangle"], "paths": {}}})",
       "capabilities: paths: given, but \"path\" is not in primitives"},
  };
  for (const auto& [text, want] : bad) {
    const auto r = parse_capabilities(text);
    ASSERT_TRUE(std::holds_alternative<std::string>(r)) << text;
    EXPECT_EQ(std::get<std::string>(r).rfind(want, 0), 0u)
        << text << " -> " << std::get<std::string>(r);
  }
  // Without a "paths" object, no path scene is declared.
  const auto none = parse_capabilities(R"({"capabilities": {"primitives": ["path"]}})");
  ASSERT_TRUE(std::holds_alternative<Capabilities>(none));
  EXPECT_EQ(undeclared(std::get<Capabilities>(none),
                       path_scene({polygon(kSquare)}, path::Coverage::kSamples)),
            "paths not declared by the driver (its capabilities have no \"paths\" object)");
}

// rule: DRIVER.EXTERNAL.PATHS
TEST(ExternalPaths, AlphaIsReadForAreaPathsAndRefusedElsewhere) {
  Scene s = path_scene({polygon(kSquare)}, path::Coverage::kArea);
  s.primitives.push_back(path_prim({polygon(kSquare)}, path::Coverage::kSamples));
  s.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  // Any key order: "alpha" before "prim" is checked when the fragment ends.
  const auto r = parse_external_fragments(
      R"({"fragments": [{"alpha": 128, "prim": 0, "x": 1, "y": 1}, {"prim": 0, "x": 2, "y": 1,)"
      R"( "alpha": 255}, {"prim": 1, "x": 3, "y": 1}, {"prim": 2, "x": 0, "y": 0}]})",
      s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r)) << std::get<std::string>(r);
  const auto& f = std::get<std::vector<Fragment>>(r);
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0].area.text(), "128/255");
  EXPECT_EQ(f[0].area.alpha(), 128);
  EXPECT_EQ(f[0].area.bound_text(), "");
  EXPECT_EQ(f[1].area.text(), "1");
  EXPECT_FALSE(f[2].area);
  EXPECT_FALSE(f[3].area);
  const std::pair<const char*, const char*> bad[] = {
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1}]})",
       "fragments[0].alpha: missing (primitive 0 is a path with coverage \"area\")"},
      {R"({"fragments": [{"prim": 1, "x": 1, "y": 1, "alpha": 255}]})",
       "fragments[0].alpha: primitive 1 is not a path with coverage \"area\""},
      {R"({"fragments": [{"prim": 2, "x": 1, "y": 1, "alpha": 9}]})",
       "fragments[0].alpha: primitive 2 is not a path with coverage \"area\""},
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "alpha": 0}]})",
       "fragments[0].alpha: must be an integer in [1, 255] (8-bit alpha; 0 is no fragment)"},
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "alpha": 256}]})",
       "fragments[0].alpha: must be an integer in [1, 255]"},
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "alpha": 0.5}]})",
       "fragments[0].alpha: must be an integer in [1, 255]"},
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "alpha": [1]}]})",
       "fragments[0].alpha: must be an integer in [1, 255]"},
      {R"({"fragments": [{"prim": 0, "x": 1, "y": 1, "alpha": 1, "alpha": 2}]})",
       "the key \"alpha\" is given twice in one object"},
  };
  for (const auto& [text, want] : bad)
    EXPECT_EQ(parse_error(text, s).rfind(want, 0), 0u) << text << " -> " << parse_error(text, s);
}

// rule: DRIVER.EXTERNAL.PATHS
TEST(ExternalPaths, ADriverThatDeclaresPathsGetsPathScenesWithTheAdaptersRefusals) {
  TempDir dir;
  std::string err;
  auto d = open_driver(
      "external:" + fake_driver(dir, "paths.sh", kPathsReply,
                                R"({"fragments": [{"prim": 0, "x": 2, "y": 1, "alpha": 255}]})"),
      &err);
  ASSERT_NE(d, nullptr) << err;
  const PathSupport& ps = d->info().paths;
  EXPECT_TRUE(ps.any());
  EXPECT_EQ(ps.grid, "26.6");
  EXPECT_FALSE(d->info().triangles);
  const Scene square = path_scene({polygon(kSquare)}, path::Coverage::kArea);
  EXPECT_EQ(d->unsupported(square), "");
  DrawResult r = d->draw(square);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r)) << std::get<DriverError>(r).message;
  ASSERT_EQ(std::get<std::vector<Fragment>>(r).size(), 1u);
  EXPECT_EQ(std::get<std::vector<Fragment>>(r)[0].area.text(), "1");
  // The refusals of a 2D library adapter (DRIVER.PATH.LIBRARY), named after the driver.
  Scene msaa = square;
  set_sample_pattern(msaa, standard_pattern(4));
  EXPECT_EQ(d->unsupported(msaa), "4 samples not declared by the driver");
  EXPECT_EQ(d->unsupported(
                path_scene({polygon(kSquare)}, path::Coverage::kArea, path::FillRule::kEvenOdd)),
            "primitives[0]: external has no fill rule evenodd");
  FloatContour cubic = polygon(kSquare);
  cubic.segments[1].kind = path::SegmentKind::kCubic;
  cubic.segments[1].p = {FloatPoint{6, 2}, FloatPoint{6, 3}, FloatPoint{5, 4}};
  EXPECT_EQ(d->unsupported(path_scene({cubic}, path::Coverage::kSamples)),
            "primitives[0]: external draws no cubic curves");
  EXPECT_EQ(d->unsupported(path_scene({polygon({{1, 1}, {2.00390625f, 1}, {2, 2}})},
                                      path::Coverage::kSamples)),
            "primitives[0]: control point (513, 256) raw is not on external's 26.6 grid");
  auto aliased_only =
      open_driver("external:" + fake_driver(dir, "aliased.sh",
                                            R"({"capabilities": {"paths": {"area": false}}})"),
                  &err);
  ASSERT_NE(aliased_only, nullptr) << err;
  EXPECT_EQ(aliased_only->unsupported(square),
            "primitives[0]: external draws no antialiased paths (coverage \"area\")");
  // It declares every sample count, but a path is drawn with one sample at the pixel centre.
  EXPECT_EQ(aliased_only->unsupported(msaa), "external draws one sample at the pixel centre");
  // A driver that declares no capabilities, or none for paths, gets no path scene.
  auto plain = open_driver("external:" + dir.script("plain.sh", "cat > /dev/null; exit 3"), &err);
  ASSERT_NE(plain, nullptr) << err;
  EXPECT_EQ(plain->unsupported(square),
            "paths not declared by the driver (it answered no capabilities query)");
  EXPECT_FALSE(plain->info().paths.any());
  auto no_paths = open_driver(
      "external:" + fake_driver(dir, "nopaths.sh", R"({"capabilities": {"primitives": ["path"]}})"),
      &err);
  ASSERT_NE(no_paths, nullptr) << err;
  EXPECT_EQ(no_paths->unsupported(square),
            "paths not declared by the driver (its capabilities have no \"paths\" object)");
  // A driver's bad alpha is malformed output naming the fragment.
  auto bad =
      open_driver("external:" + fake_driver(dir, "bad.sh", kPathsReply,
                                            R"({"fragments": [{"prim": 0, "x": 2, "y": 1}]})"),
                  &err);
  ASSERT_NE(bad, nullptr) << err;
  const DrawResult b = bad->draw(square);
  ASSERT_TRUE(std::holds_alternative<DriverError>(b));
  EXPECT_NE(std::get<DriverError>(b).message.find(
                "malformed output: fragments[0].alpha: missing (primitive 0 is a path with "
                "coverage \"area\")"),
            std::string::npos)
      << std::get<DriverError>(b).message;
}

// Opens a Node driver, or says why it cannot be opened (the test then skips).
std::unique_ptr<Driver> open_node(const std::string& name, std::string* why) {
  auto d = open_driver(name, why);
  EXPECT_TRUE(d != nullptr || !why->empty());
  return d;
}

// The scene writer's coordinates snapped by the Node drivers' scene.mjs equal the kernel's
// (SNAP.VERTEX.ROUND): ties of x * 256 both ways, negative ties, and random float32 values. A
// Node program run as an external driver writes the raw values it computed to a file.
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA, SNAP.VERTEX.ROUND
TEST(NodePathDrivers, TheNodeDriversSnapLikeTheKernel) {
  std::string why;
  if (open_node("tiny-skia", &why) == nullptr)
    GTEST_SKIP() << "tiny-skia cannot be opened: " << why;
  TempDir dir;
  const std::string out = dir.file("raw.txt");
  const std::string program = dir.script(
      "snap.mjs",
      "import { readScene } from '" + node_drivers_dir() +
          "/scene.mjs';\n"
          "import { writeFileSync } from 'node:fs';\n"
          "if (process.env.RASTRULES_QUERY === 'capabilities') {\n"
          "  console.log(JSON.stringify({capabilities: {primitives: ['path'], paths: {}}}));\n"
          "} else {\n"
          "  let text = '';\n"
          "  for await (const chunk of process.stdin) text += chunk;\n"
          "  const raw = readScene(text).paths.flatMap((p) => p.contours.flat())\n"
          "      .flatMap((c) => c.pts.flat());\n"
          "  writeFileSync('" +
          out +
          "', raw.join(' '));\n"
          "  console.log('{\"fragments\": []}');\n"
          "}",
      "");
  std::string err;
  auto d = open_driver("external:node " + program, &err);
  ASSERT_NE(d, nullptr) << err;
  std::vector<FloatPoint> pts;
  for (int k = -9; k <= 9; k += 2) // k / 512: exactly half-way between two raw values
    pts.push_back({static_cast<float>(k) / 512.0f, static_cast<float>(k + 1024) / 512.0f});
  pts.push_back({-32768.0f, 32767.99609375f});
  pts.push_back({8192.001953125f, -8192.005859375f}); // ties where float32 steps by 1/1024 px
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> coord(-300.0f, 300.0f);
  for (int i = 0; i < 400; ++i)
    pts.push_back({coord(rng), coord(rng)});
  Scene s = path_scene({polygon(pts)}, path::Coverage::kSamples);
  ASSERT_EQ(d->unsupported(s), "");
  const DrawResult r = d->draw(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r)) << std::get<DriverError>(r).message;
  const auto prepared = prepare(s);
  ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared));
  const path::Path& kernel = *std::get<PreparedScene>(prepared).primitives[0].path;
  std::vector<std::int64_t> want = {kernel.contours[0].start.x, kernel.contours[0].start.y};
  for (const path::Segment& seg : kernel.contours[0].segments) {
    want.push_back(seg.p[0].x);
    want.push_back(seg.p[0].y);
  }
  std::ifstream in(out);
  std::vector<std::int64_t> got;
  for (std::int64_t v = 0; in >> v;)
    got.push_back(v);
  EXPECT_EQ(got, want);
  EXPECT_EQ(want[0], -4); // -9/512 px = -4.5 raw: to the even -4
  EXPECT_EQ(want[2], -4); // -7/512 px = -3.5 raw: to the even -4
}

class NodePathDriver : public ::testing::TestWithParam<const char*> {
protected:
  void SetUp() override {
    std::string why;
    driver_ = open_node(GetParam(), &why);
    if (driver_ == nullptr)
      GTEST_SKIP() << GetParam() << " cannot be opened: " << why;
  }

  std::vector<Fragment> draw_ok(const Scene& s) {
    EXPECT_EQ(driver_->unsupported(s), "");
    DrawResult r = driver_->draw(s);
    if (const auto* e = std::get_if<DriverError>(&r)) {
      ADD_FAILURE() << e->message;
      return {};
    }
    return std::get<std::vector<Fragment>>(r);
  }

  std::unique_ptr<Driver> driver_;
};

// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST_P(NodePathDriver, DeclaresPathsOnly) {
  const DriverInfo& info = driver_->info();
  EXPECT_EQ(info.name, GetParam());
  EXPECT_EQ(info.capabilities, "declared");
  EXPECT_TRUE(info.paths.samples && info.paths.area && info.paths.nonzero && info.paths.evenodd &&
              info.paths.quadratics && info.paths.cubics);
  EXPECT_EQ(info.paths.grid, "float");
  EXPECT_FALSE(info.paths.aliased_method.empty() || info.paths.antialiased_method.empty());
  EXPECT_FALSE(info.triangles || info.points || info.lines_d3d);
  EXPECT_EQ(info.sample_counts, std::vector<std::uint32_t>{1});
  Scene tri;
  tri.width = tri.height = 4;
  tri.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  EXPECT_EQ(driver_->unsupported(tri), "primitive type 'triangle' not declared by the driver");
}

// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST_P(NodePathDriver, APixelAlignedSquareCoversItsPixelsAliasedAndAtFullAlpha) {
  for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
    const auto frags = draw_ok(path_scene({polygon(kSquare)}, coverage));
    ASSERT_EQ(frags.size(), 9u) << to_string(coverage);
    for (const Fragment& f : frags) {
      EXPECT_TRUE(f.x >= 2 && f.x <= 4 && f.y >= 1 && f.y <= 3) << f.x << ", " << f.y;
      EXPECT_EQ(f.mask, 1u);
      if (coverage == path::Coverage::kArea)
        EXPECT_EQ(f.area.text(), "1");
      else
        EXPECT_FALSE(f.area);
    }
  }
}

// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST_P(NodePathDriver, AHalfPixelTriangleGetsPartialAlphaAndEvenOddEmptiesATwiceDrawnSquare) {
  const auto half = draw_ok(path_scene({polygon(kHalfPixel)}, path::Coverage::kArea));
  ASSERT_EQ(half.size(), 1u);
  EXPECT_EQ(half[0].x, 1);
  EXPECT_EQ(half[0].y, 1);
  // 1/2 px^2: Skia's analytic coverage stores 128 (127.5 rounded); tiny-skia supersamples 4 x 4
  // and counts the 6 sub-samples strictly inside the diagonal: 6/16 of 255, 96.
  const int want = std::string(GetParam()) == "skia" ? 128 : 96;
  EXPECT_EQ(half[0].area.alpha(), want) << half[0].area.text();
  const auto twice = draw_ok(path_scene({polygon(kSquare), polygon(kSquare)}, path::Coverage::kArea,
                                        path::FillRule::kEvenOdd));
  EXPECT_TRUE(twice.empty());
  const auto twice_aliased = draw_ok(path_scene(
      {polygon(kSquare), polygon(kSquare)}, path::Coverage::kSamples, path::FillRule::kEvenOdd));
  EXPECT_TRUE(twice_aliased.empty());
  const auto nonzero = draw_ok(path_scene({polygon(kSquare), polygon(kSquare)},
                                          path::Coverage::kArea, path::FillRule::kNonZero));
  EXPECT_EQ(nonzero.size(), 9u);
}

// Curves reach the library: a quadratic and a cubic bulge covers pixels beyond its chord.
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST_P(NodePathDriver, CurvesAndSeveralPathsAreDrawnEachAlone) {
  FloatContour quad = polygon({{1, 1}, {7, 1}});
  FloatPathSegment q;
  q.kind = path::SegmentKind::kQuadratic;
  q.p = {FloatPoint{4, 9}, FloatPoint{1, 1}};
  quad.segments.push_back(q);
  Scene s = path_scene({quad}, path::Coverage::kSamples);
  s.primitives.push_back(path_prim({polygon(kSquare)}, path::Coverage::kArea));
  const auto frags = draw_ok(s);
  std::size_t first = 0;
  bool below_chord = false;
  for (const Fragment& f : frags) {
    first += f.prim == 0 ? 1 : 0;
    below_chord = below_chord || (f.prim == 0 && f.y >= 3);
  }
  EXPECT_TRUE(below_chord);
  EXPECT_GT(first, 6u);
  EXPECT_EQ(frags.size() - first, 9u); // the square, drawn alone on its own raster
}

INSTANTIATE_TEST_SUITE_P(Libraries, NodePathDriver, ::testing::Values("skia", "tiny-skia"),
                         [](const auto& p) {
                           return std::string(p.param) == "skia" ? "Skia" : "TinySkia";
                         });

// Opening reports what to run when the Node drivers' directory has no program or packages.
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST(NodePathDrivers, AMissingInstallIsOneLineSayingWhatToRun) {
  TempDir dir;
  struct Restore {
    ~Restore() { ::unsetenv(kNodeDriversVariable); }
  } restore;
  ::setenv(kNodeDriversVariable, dir.file("").c_str(), 1);
  std::string err;
  EXPECT_EQ(open_driver("skia", &err), nullptr);
  EXPECT_NE(err.find("skia: "), std::string::npos) << err;
  EXPECT_EQ(err.find('\n'), std::string::npos) << err;
  std::ofstream(dir.file("tiny-skia.mjs")) << "\n";
  EXPECT_EQ(open_driver("tiny-skia", &err), nullptr);
  if (err.find("node is not installed") == std::string::npos) { // node is there: the package is not
    EXPECT_NE(err.find("the npm package @resvg/resvg-js is not installed in"), std::string::npos)
        << err;
  }
  EXPECT_NE(err.find("run scripts/deps (or: npm ci --prefix "), std::string::npos) << err;
  EXPECT_EQ(open_driver("skia:x", &err), nullptr);
  EXPECT_NE(err.find("unknown driver"), std::string::npos) << err;
}

// One scene through each Node driver costs a process start and the library's load: measured and
// printed (campaigns run one process per scene), bounded loosely so a hang is caught.
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
TEST_P(NodePathDriver, OneSceneCostsAProcessStartAndTheLibrarysLoad) {
  const Scene s = path_scene({polygon(kSquare)}, path::Coverage::kArea);
  constexpr int kRuns = 5;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kRuns; ++i)
    EXPECT_EQ(draw_ok(s).size(), 9u);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
      kRuns;
  std::cout << "[ timing   ] " << GetParam() << ": " << ms << " ms a scene (process + load)\n";
  EXPECT_LT(ms, 10000.0);
}

} // namespace
} // namespace rastrules::driver::external_paths
