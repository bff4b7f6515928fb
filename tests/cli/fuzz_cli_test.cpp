// SPDX-License-Identifier: MIT
// rastrules fuzz, check and probe: exit codes, outputs (reproducers, pictures, reports) and
// usage errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "support.hpp"

namespace rastrules::test {
namespace {

// One triangle whose bottom-right edge runs through the centre of pixel (0, 0): the top-left
// rule leaves it out, a bottom-right rule takes it.
const char* kTieScene = R"({"version": 1, "target": {"width": 1, "height": 1},
  "primitives": [{"type": "triangle", "v": [[0, 0], [1, 0], [0, 1]]}]})";

// rule: FUZZ.REPORT
TEST(CliFuzz, FindingsWriteReproducerPictureAndReportAndExitWith1) {
  TempDir dir;
  const auto out = dir / "out";
  const RunResult r = run_cli({"fuzz", "--driver", "imprecise:fill-bottom-right", "--cases", "40",
                               "--seed", "1", "--out", out.string()});
  ASSERT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("| cases"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("cases/s"), std::string::npos);
  EXPECT_EQ(r.err.find("["), std::string::npos)
      << "no progress bar when standard error is not a terminal";
  const auto report = nlohmann::json::parse(read_file(out / "report.json"));
  EXPECT_EQ(report["driver"], "imprecise:fill-bottom-right");
  EXPECT_EQ(report["profile"], "d3d11");
  EXPECT_EQ(report["cases"], 40);
  ASSERT_GT(report["mismatches"].get<int>(), 0);
  ASSERT_FALSE(report["findings"].empty());
  const auto& f = report["findings"][0];
  EXPECT_EQ(f["seed"], 1);
  EXPECT_EQ(f["primitives_after"], 1);
  EXPECT_FALSE(f["missing"].empty() && f["extra"].empty());
  // The picture: three panels of the shrunk target side by side (each magnified as much as
  // fits, at most 96 times), titled above with the x coordinates, y coordinates at the left,
  // the legend below: wider than the three panels and their gaps, taller than one panel.
  const auto png = read_png(f["picture"].get<std::string>());
  ASSERT_TRUE(png.has_value());
  const auto min = nlohmann::json::parse(read_file(f["shrunk_scene"].get<std::string>()));
  const int w = min["target"]["width"], h = min["target"]["height"];
  const int scale = std::min({(4096 - 27) / (3 * w), 4095 / h, 96});
  EXPECT_GT(png->width, 3 * (w * scale + 1) + 2 * 12);
  EXPECT_GT(png->height, h * scale + 1);
  // The campaign's page shows it (FUZZ.REPORT.HTML).
  const std::string page = read_file(out / "index.html");
  const std::string name = std::filesystem::path(f["picture"].get<std::string>()).filename();
  EXPECT_NE(page.find("<img src=\"" + name + "\""), std::string::npos);
  // The shrunk scene reproduces the finding with `check`, and the reference agrees with it.
  const std::string shrunk = f["shrunk_scene"].get<std::string>();
  const RunResult again = run_cli({"check", shrunk, "--driver", "imprecise:fill-bottom-right"});
  EXPECT_EQ(again.status, 1) << again.err;
  EXPECT_EQ(run_cli({"check", shrunk, "--driver", "reference"}).status, 0);
}

// rule: FUZZ.REPORT, FUZZ.COMPARE.LEGAL
TEST(CliFuzz, CheckReportsTheLegalConventionUnderVulkan) {
  TempDir dir;
  const auto scene = dir.write("tie.json", kTieScene);
  EXPECT_EQ(run_cli({"check", scene.string(), "--driver", "imprecise:fill-bottom-right"}).status,
            1);
  const RunResult legal =
      run_cli({"check", scene.string(), "--driver", "imprecise:fill-bottom-right", "--profile",
               "vulkan", "--mode", "legal"});
  EXPECT_EQ(legal.status, 0) << legal.err;
  EXPECT_NE(legal.out.find("bottom-right 1"), std::string::npos) << legal.out;
  EXPECT_EQ(run_cli({"check", scene.string(), "--driver", "imprecise:fill-bottom-right",
                     "--profile", "d3d11", "--mode", "legal"})
                .status,
            1);
}

// rule: FUZZ.REPORT
TEST(CliFuzz, ReferenceFindsNothingAndExternalRenderIsAConformingDriver) {
  EXPECT_EQ(
      run_cli({"fuzz", "--driver", "reference", "--cases", "50", "--profile", "vulkan"}).status, 0);
  const RunResult ext = run_cli(
      {"fuzz", "--driver", std::string("external:") + RASTRULES_CLI + " render - --fragments -",
       "--cases", "10"});
  EXPECT_EQ(ext.status, 0) << ext.err;
  EXPECT_NE(ext.out.find("no difference"), std::string::npos);
}

// rule: FUZZ.PROBE
TEST(CliFuzz, ProbeReportsThePlantedConventions) {
  const RunResult four = run_cli({"probe", "--driver", "imprecise:4-bit-subpixel"});
  ASSERT_EQ(four.status, 0) << four.err;
  EXPECT_NE(four.out.find("subpixel bits     4"), std::string::npos) << four.out;
  const RunResult br = run_cli({"probe", "--driver", "imprecise:fill-bottom-right"});
  EXPECT_NE(br.out.find("fill convention   bottom-right"), std::string::npos) << br.out;
}

// rule: FUZZ.REPORT
TEST(CliFuzz, BadUsageAndDriverFailuresExitWith2) {
  TempDir dir;
  const auto scene = dir.write("tie.json", kTieScene);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"fuzz"},
           {"fuzz", "--driver"},
           {"fuzz", "--driver", "nonesuch"},
           {"fuzz", "--driver", "reference", "--cases", "0"},
           {"fuzz", "--driver", "reference", "--seed", "x"},
           {"fuzz", "--driver", "reference", "--profile", "metal"},
           {"fuzz", "--driver", "reference", "--mode", "lenient"},
           {"fuzz", "--driver", "reference", "--frobnicate"},
           {"check", "--driver", "reference"},
           {"check", scene.string()},
           {"check", (dir / "missing.json").string(), "--driver", "reference"},
           {"check", scene.string(), "--driver", "reference", "--cases", "3"},
           {"check", scene.string(), "--driver", "external:/nonexistent/driver"},
           {"probe"},
           {"probe", "--driver", "nonesuch"},
       }) {
    const RunResult r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args[0] << " " << (args.size() > 1 ? args.back() : "");
    EXPECT_NE(r.err.find("rastrules: error: "), std::string::npos) << r.err;
  }
}

} // namespace
} // namespace rastrules::test

namespace rastrules::test {
namespace {

// rule: FUZZ.PATH.REPORT
TEST(CliFuzz2d, APlantedBugIsFoundWithReportAndPicturesAndExitWith1) {
  TempDir dir;
  const auto out = dir / "f2d";
  const RunResult r = run_cli({"fuzz2d", "--driver", "imprecise-path:float-accumulation", "--cases",
                               "20", "--max-findings", "1", "--out", out.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("class       conflation"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("finding     case "), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(out / "report.json"));
  const RunResult ref = run_cli({"fuzz2d", "--driver", "imprecise-path:flatten-quarter",
                                 "--families", "polygon,ties", "--cases", "10"});
  EXPECT_EQ(ref.status, 0) << ref.out << ref.err; // no curves drawn: no difference
}

// rule: FUZZ.PATH.PROBE
TEST(CliFuzz2d, ProbeOfAPathDriverReportsItsMethod) {
  const RunResult r = run_cli({"probe", "--driver", "imprecise-path:float-accumulation"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("conflation        a half pixel drawn twice, even-odd: alpha 255"),
            std::string::npos)
      << r.out;
  const RunResult j = run_cli({"probe", "--driver", "imprecise-path:float-accumulation", "--json"});
  EXPECT_NE(j.out.find("\"twice_evenodd\": 255"), std::string::npos) << j.out;
}

// rule: FUZZ.PATH.REPORT
TEST(CliFuzz2d, BadUsageExitsWith2) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"fuzz2d"},
           {"fuzz2d", "--driver", "nonesuch"},
           {"fuzz2d", "--driver", "reference", "--cases", "0"},
           {"fuzz2d", "--driver", "reference", "--alpha-tolerance", "256"},
           {"fuzz2d", "--driver", "reference", "--families", "spirals"},
           {"fuzz2d", "--driver", "reference", "--max-findings", "-1"},
           {"fuzz2d", "--driver", "imprecise"},
           {"fuzz2d", "--driver", "imprecise-path:nonesuch"},
       }) {
    const RunResult r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args.back();
    EXPECT_NE(r.err.find("rastrules: error: "), std::string::npos) << r.err;
  }
}

} // namespace
} // namespace rastrules::test
