// SPDX-License-Identifier: MIT
// rastrules render --fragments OUT.bin (SCENE.OUTPUT.BINARY) and --count (SCENE.OUTPUT.COUNT):
// the binary runs hold exactly the JSON list's fragments and the reader refuses every damage;
// the counts equal the fragment list's, from the batch counter and from the traversal alike.

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "rastrules/io/fragment_binary.hpp"
#include "rastrules/io/scene_json.hpp"
#include "support.hpp"

namespace {

namespace io = rastrules::io;
using rastrules::Fragment;
using rastrules::test::read_file;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

std::vector<std::uint8_t> bytes_of(const std::string& s) {
  return {s.begin(), s.end()};
}

// (prim, x, y, mask, seg or -1) of every fragment of a JSON list, helper lanes left out.
using Row = std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::uint32_t, std::int64_t>;
std::vector<Row> rows_of_json(const std::string& text, bool with_helpers = false) {
  std::vector<Row> out;
  const nlohmann::json list = nlohmann::json::parse(text);
  for (const auto& f : list.at("fragments")) {
    if (!with_helpers && f.value("helper", false))
      continue;
    out.emplace_back(f.at("prim").get<std::uint32_t>(), f.at("x").get<std::int32_t>(),
                     f.at("y").get<std::int32_t>(), f.at("mask").get<std::uint32_t>(),
                     f.contains("seg") ? f.at("seg").get<std::int64_t>() : -1);
  }
  return out;
}

std::vector<Row> rows_of(const std::vector<Fragment>& fragments) {
  std::vector<Row> out;
  for (const Fragment& f : fragments)
    out.emplace_back(f.prim, f.x, f.y, f.mask, f.seg ? std::int64_t{*f.seg} : -1);
  return out;
}

rastrules::io::FragmentBinary read_binary(const std::string& bytes) {
  auto r = rastrules::io::read_fragment_binary(bytes_of(bytes));
  if (const auto* err = std::get_if<std::string>(&r))
    ADD_FAILURE() << *err;
  return std::get<rastrules::io::FragmentBinary>(std::move(r));
}

// Scenes of every kind the binary format holds: triangles, points, lines, a strip (seg),
// multisampled with a sample mask, paths (samples), and a scene whose rows cross the edge.
const std::map<std::string, std::string> kScenes = {
    {"triangles", R"({"target": {"width": 16, "height": 12}, "primitives": [
      {"type": "triangle", "v": [[0.5, 0.5], [15.5, 2], [3, 11.5]]},
      {"type": "triangle", "v": [[15, 11], [4, 11.5], [15.5, 1]]},
      {"type": "triangle", "v": [[-4, -3], [30, 5], [2, 40]]}]})"},
    {"points_lines", R"({"target": {"width": 12, "height": 8}, "line_mode": "vulkan-bresenham",
      "primitives": [{"type": "point", "v": [[6.5, 4.5]]},
      {"type": "line", "v": [[0.5, 0.5], [11.5, 7]]},
      {"type": "line_strip", "v": [[1, 1], [10, 3], [2, 7], [11, 6]]}]})"},
    {"msaa", R"({"target": {"width": 8, "height": 6}, "samples": 4, "sample_mask": 13,
      "primitives": [{"type": "triangle", "v": [[0.25, 0.5], [7.5, 1], [1, 5.75]]},
      {"type": "line", "v": [[0, 5], [8, 0]]}]})"},
    {"msaa16", R"({"target": {"width": 5, "height": 5}, "samples": 16,
      "primitives": [{"type": "triangle", "v": [[0.1, 0.3], [4.9, 0.2], [2, 4.8]]}]})"},
    {"paths", R"({"target": {"width": 10, "height": 10}, "primitives": [
      {"type": "path", "d": "M 1 1 L 9 1 L 1 9 Z M 2 2 L 6 2 L 2 6 Z", "fill_rule": "evenodd"},
      {"type": "path", "d": "M 1 9 Q 5 0 9 9 Z"}]})"},
};

// rule: SCENE.OUTPUT.BINARY
TEST(BinaryFragments, HoldExactlyTheJsonListForEveryKindOfScene) {
  for (const auto& [name, scene] : kScenes) {
    SCOPED_TRACE(name);
    TempDir dir;
    const auto in = dir.write("s.json", scene);
    ASSERT_EQ(run_cli({"render", in.string(), "--fragments", (dir / "f.json").string()}).status, 0);
    const auto r = run_cli({"render", in.string(), "--fragments", (dir / "f.bin").string()});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bin = read_file(dir / "f.bin");
    const auto read = read_binary(bin);
    const auto want = rows_of_json(read_file(dir / "f.json"));
    ASSERT_FALSE(want.empty());
    EXPECT_EQ(rows_of(read.fragments), want);
    EXPECT_EQ(read.header.width, static_cast<std::uint32_t>(
                                     nlohmann::json::parse(scene)["target"]["width"].get<int>()));
    // Any name with --fragments-format binary, standard output included, and any thread count:
    // the same bytes.
    EXPECT_EQ(
        run_cli({"render", in.string(), "--fragments", "-", "--fragments-format", "binary"}).out,
        bin);
    ASSERT_EQ(run_cli({"render", in.string(), "--threads", "3", "--fragments",
                       (dir / "g.dat").string(), "--fragments-format", "binary"})
                  .status,
              0);
    EXPECT_EQ(read_file(dir / "g.dat"), bin);
    EXPECT_EQ(read.header.version, 2u);
    // Version 1 (20 bytes a run) holds the same list.
    const auto v1 = run_cli({"render", in.string(), "--fragments", "-", "--fragments-format",
                             "binary-v1", "--threads", "2"});
    ASSERT_EQ(v1.status, 0) << v1.err;
    const auto read1 = read_binary(v1.out);
    EXPECT_EQ(read1.header.version, 1u);
    EXPECT_EQ(read1.fragments, read.fragments);
    EXPECT_EQ(read1.runs, read.runs);
    EXPECT_LT(bin.size(), v1.out.size());
  }
}

// rule: SCENE.OUTPUT.BINARY
TEST(BinaryFragments, ATriangleIsOneRunARowAndSingleSampleScenesStoreNoMasks) {
  TempDir dir;
  const auto in = dir.write("s.json", R"({"target": {"width": 64, "height": 64}, "primitives": [
    {"type": "triangle", "v": [[0, 0], [64, 0], [0, 64]]}]})");
  ASSERT_EQ(run_cli({"render", in.string(), "--fragments", (dir / "f.bin").string()}).status, 0);
  const std::string bin = read_file(dir / "f.bin");
  const auto read = read_binary(bin);
  // Pixel (x, y) is covered when x + y <= 62 (the diagonal is a right edge: excluded): rows 0
  // to 62, 63 - y pixels each.
  EXPECT_EQ(read.runs, 63u);
  EXPECT_EQ(read.header.mask_bytes, 0u);
  EXPECT_EQ(read.fragments.size(), 63u * 64u / 2u);
  // Version 2: a word a run (the first primitive is 0, the step from the start).
  EXPECT_EQ(bin.size(), 32u + 63u * 8u + 24u);
  const auto v1 =
      run_cli({"render", in.string(), "--fragments", "-", "--fragments-format", "binary-v1"});
  EXPECT_EQ(v1.out.size(), 32u + 63u * 20u + 24u);
  EXPECT_EQ(read_binary(v1.out).fragments, read.fragments);
}

// rule: SCENE.OUTPUT.BINARY
// Version 2's steps and control words: a step of 2^21 - 1 is a word, one more a control word,
// segments control words, and primitives up to 2^32 - 2; the reader gives the list back.
TEST(BinaryFragments, VersionTwoReachesEveryPrimitiveAndSegment) {
  namespace io = rastrules::io;
  const std::uint32_t big = io::kFragmentBinaryMaxStep;
  std::vector<Fragment> list = {
      Fragment(0, 1, 0, 1),
      Fragment(0, 2, 0, 1),
      Fragment(big, 3, 1, 1),             // a step of 2^21 - 1: in the word
      Fragment(2 * big + 1, 0, 0, 1),     // 2^21: a control word
      Fragment(2 * big + 1, 4, 5, 1, 0u), // a segment: a control word
      Fragment(2 * big + 1, 4, 6, 1, 0u), // the same segment: none
      Fragment(2 * big + 1, 4, 6, 1, 7u), // another
      Fragment(2 * big + 2, 0, 0, 1, 3u), // a new primitive with a segment: two
      Fragment(2 * big + 3, 0, 0, 1),     // a step: the segment ends
      Fragment(0xFFFFFFFEu, 7, 7, 1),     // the largest primitive
  };
  io::FragmentBinaryHeader h;
  h.width = h.height = 8;
  ASSERT_EQ(h.version, 2u);
  for (const std::uint32_t version : {1u, 2u}) {
    SCOPED_TRACE(version);
    h.version = version;
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    {
      io::FragmentBinaryWriter w(f, h);
      for (const Fragment& fr : list)
        ASSERT_EQ(w.add(fr), io::FragmentBinaryWriter::Added::kOk);
      ASSERT_TRUE(w.finish());
      EXPECT_EQ(w.runs(), 9u);
    }
    std::string bytes(static_cast<std::size_t>(std::ftell(f)), '\0');
    std::rewind(f);
    ASSERT_EQ(std::fread(bytes.data(), 1, bytes.size(), f), bytes.size());
    std::fclose(f);
    // 9 runs; version 2: control words for 2^21, the first and second segments, the new
    // primitive with a segment (prim and seg), and the step to 0xFFFFFFFE (over 2^21).
    EXPECT_EQ(bytes.size(), version == 1 ? 32u + 9u * 20u + 24u : 32u + (9u + 6u) * 8u + 24u);
    const auto back = read_binary(bytes);
    EXPECT_EQ(back.fragments, list);
    EXPECT_EQ(back.runs, 9u);
  }
}

// rule: SCENE.OUTPUT.BINARY
TEST(BinaryFragments, FieldsTheFormatDoesNotHoldAreBadInputAndLeaveNoFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"target": {"width": 8, "height": 8}, "primitives": [
         {"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]]},
         {"type": "line", "v": [[0.5, 1], [7, 6]], "aa": true}]})",
       "primitives[1]'s fragments have a \"coverage\" field"},
      {R"({"target": {"width": 8, "height": 8}, "samples": 4, "centroid": "d3d11",
         "primitives": [{"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]]}]})",
       "primitives[0]'s fragments have a \"centroid\" field"},
      {R"({"target": {"width": 8, "height": 8}, "primitives": [
         {"type": "path", "d": "M 1 1 L 7 1 L 1 7 Z", "coverage": "area"}]})",
       "\"area\" field"},
      {R"({"target": {"width": 8, "height": 8}, "depth": {"format": "d24", "func": "less"},
         "primitives": [{"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]]}]})",
       "a pipeline scene's fragments are written as JSON"},
  };
  for (const auto& [scene, message] : cases) {
    TempDir dir;
    const auto in = dir.write("s.json", scene);
    const auto r = run_cli({"render", in.string(), "--fragments", (dir / "f.bin").string()});
    EXPECT_EQ(r.status, 2);
    ASSERT_EQ(r.err_lines().size(), 1u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "f.bin"));
  }
}

// rule: SCENE.OUTPUT.BINARY
// add_runs writes what add_run writes run by run, leaving out (and reporting) a run that does
// not come after the one before it, in both versions.
TEST(BinaryFragments, RunsAtOnceWriteWhatRunsOneByOneWrite) {
  namespace io = rastrules::io;
  struct Run {
    std::uint32_t tri;
    std::int32_t y, x, n;
  };
  // Primitive 5 + tri: two rows of one, a run joining the previous one, one out of order.
  const std::vector<Run> runs = {{0, 0, 1, 2}, {0, 1, 0, 3}, {0, 1, 3, 1},
                                 {1, 0, 0, 1}, {1, 0, 0, 4}, {3, 7, 2, 5}};
  io::FragmentBinaryHeader h;
  h.width = h.height = 8;
  const auto file_of = [&](bool at_once, std::uint32_t version) {
    h.version = version;
    std::FILE* f = std::tmpfile();
    EXPECT_NE(f, nullptr);
    {
      io::FragmentBinaryWriter w(f, h);
      if (at_once) {
        EXPECT_EQ(w.add_runs(runs.data(), runs.size(), 5),
                  io::FragmentBinaryWriter::Added::kOutOfOrder);
      } else {
        for (std::size_t i = 0; i < runs.size(); ++i) {
          const Run& r = runs[i];
          EXPECT_EQ(w.add_run(5 + r.tri, r.y, r.x, static_cast<std::uint32_t>(r.n)),
                    i == 4 ? io::FragmentBinaryWriter::Added::kOutOfOrder
                           : io::FragmentBinaryWriter::Added::kOk);
        }
      }
      EXPECT_TRUE(w.finish());
      EXPECT_EQ(w.count(), 2u + 3u + 1u + 1u + 5u);
      EXPECT_EQ(w.runs(), 4u); // (0, 1..2), (1, 0..3), (0, 0), (7, 2..6)
    }
    std::string bytes(static_cast<std::size_t>(std::ftell(f)), '\0');
    std::rewind(f);
    EXPECT_EQ(std::fread(bytes.data(), 1, bytes.size(), f), bytes.size());
    std::fclose(f);
    return bytes;
  };
  for (const std::uint32_t version : {1u, 2u}) {
    SCOPED_TRACE(version);
    const std::string at_once = file_of(true, version);
    EXPECT_EQ(at_once, file_of(false, version));
    EXPECT_EQ(read_binary(at_once).fragments.size(), 12u);
  }
}

// rule: SCENE.OUTPUT.BINARY
// Every cut and every damaged field is refused with a one-line error naming its byte, in both
// versions.
TEST(BinaryFragments, TheReaderRefusesEveryCutAndEveryDamagedField) {
  TempDir dir;
  const auto in = dir.write("s.json", kScenes.at("msaa"));
  const auto u32 = [](std::uint32_t v) {
    return std::string{static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF),
                       static_cast<char>((v >> 16) & 0xFF), static_cast<char>(v >> 24)};
  };
  const auto u64 = [&](std::uint64_t v) {
    return u32(static_cast<std::uint32_t>(v)) + u32(static_cast<std::uint32_t>(v >> 32));
  };
  for (const std::string version : {"binary-v1", "binary"}) {
    SCOPED_TRACE(version);
    const auto written =
        run_cli({"render", in.string(), "--fragments", "-", "--fragments-format", version});
    ASSERT_EQ(written.status, 0) << written.err;
    const std::string good = written.out;
    for (std::size_t cut = 0; cut < good.size(); ++cut) {
      const auto r = rastrules::io::read_fragment_binary(bytes_of(good.substr(0, cut)));
      ASSERT_TRUE(std::holds_alternative<std::string>(r)) << "cut at " << cut;
      EXPECT_EQ(std::get<std::string>(r).rfind("byte ", 0), 0u);
    }
    const auto damaged = [&](std::size_t at, const std::string& value) {
      std::string b = good;
      b.replace(at, value.size(), value);
      return b;
    };
    std::vector<std::pair<std::string, std::string>> cases = {
        {damaged(0, "\x88"), "byte 0: not a rastrules binary fragment list"},
        {damaged(8, u32(3)), "byte 8: version 3 is neither 1 nor 2"},
        {damaged(12, u32(0)), "byte 12: width 0 is outside [1, 16384]"},
        {damaged(16, u32(16385)), "byte 16: height 16385"},
        {damaged(20, u32(17)), "byte 20: samples 17"},
        {damaged(24, u32(1)), "byte 24: mask bytes 1"},
        {damaged(28, u32(1)), "byte 28: the reserved field is not 0"},
        {good + std::string(1, '\0'), "bytes after the end record"},
        {damaged(good.size() - 16, u32(12345)), "the end record counts 12345 fragments"},
        {damaged(good.size() - 8, u32(7)), "the end record counts 7 runs"},
    };
    if (version == "binary-v1") {
      // The second run, to break the order: the first run's bytes (20 + masks padded).
      const std::uint32_t n = static_cast<std::uint8_t>(good[32 + 16]);
      const std::size_t first_run_bytes = 20 + (n * 2 + 3) / 4 * 4;
      cases.insert(
          cases.end(),
          {
              {damaged(32 + 8, u32(6)), "byte 40: row 6 is outside the target's 6"},
              {damaged(32 + 12, u32(8)), "byte 44: column 8 is outside the target's 8"},
              {damaged(32 + 16, u32(0)), "byte 48: a run of 0 pixels"},
              {damaged(32 + 16, u32(100)), "does not fit a row of 8"},
              {damaged(32 + 20, std::string(2, '\0')), "byte 52: mask 0 is not a nonzero mask"},
              {damaged(32 + 20, std::string("\x10\0", 2)),
               "mask 16 is not a nonzero mask of 4 samples"},
              {damaged(32 + first_run_bytes + 8, u32(0)), "does not come after the previous one"},
              {damaged(good.size() - 20, u32(1)), "the end record's reserved field is not 0"},
          });
    } else {
      // The first run's word (primitive 0 needs no control word): n, x, y, the step.
      std::uint64_t w = 0;
      for (int b = 7; b >= 0; --b)
        w = (w << 8) | static_cast<std::uint8_t>(good[32 + static_cast<std::size_t>(b)]);
      const std::uint64_t n = w & 0x7FFF;
      ASSERT_GT(n, 0u);
      const auto with = [&](std::uint64_t nn, std::uint64_t x, std::uint64_t y,
                            std::uint64_t step) {
        return damaged(32, u64(nn | (x << 15) | (y << 29) | (step << 43)));
      };
      const std::uint64_t x0 = (w >> 15) & 0x3FFF, y0 = (w >> 29) & 0x3FFF;
      const std::size_t second = 32 + 8 + (n * 2 + 7) / 8 * 8;
      // A control word setting primitive 0xFFFFFFFF before the first run, whose step is then 1.
      std::string overflow = with(n, x0, y0, 1);
      overflow.insert(32, u64((std::uint64_t{0xFFFFFFFFu} << 32) | (1u << 15)));
      cases.insert(
          cases.end(),
          {
              {with(n, x0, 6, 0), "byte 32: row 6 is outside the target's 6"},
              {with(n, 8, y0, 0), "byte 32: column 8 is outside the target's 8"},
              {with(100, x0, y0, 0), "byte 32: a run of 100 pixels from column"},
              {damaged(32, u64(std::uint64_t{9} << 15)),
               "byte 32: a control word of unknown kind 9"},
              {damaged(40, std::string(2, '\0')), "byte 40: mask 0 is not a nonzero mask"},
              {damaged(40, std::string("\x10\0", 2)), "mask 16 is not a nonzero mask of 4 samples"},
              {damaged(second, u64(1 | (x0 << 15) | (y0 << 29))),
               "does not come after the previous one"},
              {overflow, "byte 40: a run whose primitive passes 4294967295"},
              {damaged(good.size() - 20, u32(1)), "the end record's value is not 0"},
          });
    }
    for (const auto& [data, message] : cases) {
      const auto r = rastrules::io::read_fragment_binary(bytes_of(data));
      ASSERT_TRUE(std::holds_alternative<std::string>(r)) << message;
      EXPECT_NE(std::get<std::string>(r).find(message), std::string::npos)
          << std::get<std::string>(r);
    }
    // The fragment limit bounds the result's memory.
    const auto limited = rastrules::io::read_fragment_binary(bytes_of(good), 3);
    ASSERT_TRUE(std::holds_alternative<std::string>(limited));
    EXPECT_NE(std::get<std::string>(limited).find("more than 3 fragments"), std::string::npos);
  }
}

// The counts a fragment list implies (SCENE.OUTPUT.COUNT), helper lanes left out.
nlohmann::json counts_of_list(const std::vector<Row>& rows, std::size_t primitives) {
  std::vector<std::uint64_t> per(primitives, 0);
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint64_t> hits;
  for (const auto& [prim, x, y, mask, seg] : rows) {
    ++per[prim];
    ++hits[{x, y}];
  }
  std::vector<std::uint64_t> pixels;
  for (const auto& [xy, n] : hits) {
    if (n > pixels.size())
      pixels.resize(n, 0);
    ++pixels[n - 1];
  }
  std::uint64_t total = 0;
  for (const auto n : per)
    total += n;
  return {
      {"primitives", primitives},
      {"fragments", total},
      {"per_primitive", per},
      {"overdraw", {{"pixels_touched", hits.size()}, {"max", pixels.size()}, {"pixels", pixels}}}};
}

// A random seed, printed; RASTRULES_SEED=N replays a run.
unsigned printed_seed(const char* test) {
  const char* given = std::getenv("RASTRULES_SEED");
  const unsigned seed = given != nullptr ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                         : std::random_device{}();
  std::printf("%s seed %u (RASTRULES_SEED=%u replays it)\n", test, seed, seed);
  return seed;
}

// A triangle primitive of three vertices from vertex(), each moved to its pixel's centre one
// time in four (ties).
template <class Vertex> nlohmann::json tie_heavy_triangle(std::mt19937& rng, Vertex&& vertex) {
  nlohmann::json v = nlohmann::json::array();
  for (int k = 0; k < 3; ++k) {
    auto [x, y] = vertex();
    if (rng() % 4 == 0) {
      x = std::floor(x) + 0.5f;
      y = std::floor(y) + 0.5f;
    }
    v.push_back({x, y});
  }
  return {{"type", "triangle"}, {"v", v}};
}

// rule: SCENE.OUTPUT.COUNT, FAST.BATCH.EQUALS.PLAIN
// Random triangle scenes (the batch counter's case): the counts equal the fragment list's, and
// the batch counter (default), the plain traversal and every instruction set give the same bytes.
TEST(FragmentCount, TheBatchCounterEqualsTheFragmentListOnRandomTriangles) {
  const unsigned seed = printed_seed("FragmentCount");
  std::mt19937 rng(seed);
  for (int round = 0; round < 6; ++round) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " round " + std::to_string(round));
    const int w = 1 + static_cast<int>(rng() % 90), h = 1 + static_cast<int>(rng() % 90);
    std::uniform_real_distribution<float> coord(-20.0f, 110.0f), small(-3.0f, 3.0f);
    nlohmann::json scene = {{"target", {{"width", w}, {"height", h}}},
                            {"primitives", nlohmann::json::array()}};
    // The window-space state (taken by the fast reader's form): culling, the winding that
    // faces front and every fill convention.
    if (round % 2 == 1)
      scene["cull"] = "back";
    static const char* const kFill[] = {"top-left", "top-right", "bottom-left", "bottom-right"};
    scene["fill"] = kFill[round % 4];
    if (round % 3 == 2)
      scene["front_face"] = "ccw";
    const int n = 1 + static_cast<int>(rng() % 300);
    for (int i = 0; i < n; ++i) {
      // Small triangles (decided in 32-bit lanes) and large ones (the tiles); ties on centres.
      const float cx = coord(rng), cy = coord(rng);
      scene["primitives"].push_back(tie_heavy_triangle(rng, [&]() -> std::array<float, 2> {
        return {cx + (i % 3 == 0 ? coord(rng) / 2 : small(rng)),
                cy + (i % 3 == 0 ? coord(rng) / 2 : small(rng))};
      }));
    }
    TempDir dir;
    const auto in = dir.write("s.json", scene.dump());
    const auto r = run_cli({"render", in.string(), "--count", (dir / "c.json").string()});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string batch = read_file(dir / "c.json");
    ASSERT_EQ(run_cli({"render", in.string(), "--fragments", (dir / "f.json").string()}).status, 0);
    EXPECT_EQ(nlohmann::json::parse(batch),
              counts_of_list(rows_of_json(read_file(dir / "f.json")), scene["primitives"].size()));
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--traversal", "plain"},
                                                  {"--isa", "scalar"},
                                                  {"--isa", "avx2"}}) {
      auto args = std::vector<std::string>{"render", in.string(), "--count", "-"};
      args.insert(args.end(), extra.begin(), extra.end());
      const auto other = run_cli(args);
      if (other.status == 2 && other.err.find("cannot run") != std::string::npos)
        continue; // an instruction set this processor lacks
      EXPECT_EQ(other.out, batch) << extra[0] << " " << extra[1];
    }
    // The JSON list: from the batch unit's runs (the fast reader's form, state included); the
    // same bytes as the plain traversal's (always prepared) and two threads'.
    const std::string list = read_file(dir / "f.json");
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{"--traversal", "plain"}, {"--threads", "2"}}) {
      auto args = std::vector<std::string>{"render", in.string(), "--fragments", "-"};
      args.insert(args.end(), extra.begin(), extra.end());
      EXPECT_TRUE(run_cli(args).out == list) << "JSON, " << extra[0] << " " << extra[1];
    }
    // The binary list likewise.
    const auto bin =
        run_cli({"render", in.string(), "--fragments", "-", "--fragments-format", "binary"});
    ASSERT_EQ(bin.status, 0) << bin.err;
    EXPECT_EQ(rows_of(read_binary(bin.out).fragments), rows_of_json(read_file(dir / "f.json")));
    for (const std::vector<std::string>& extra : {std::vector<std::string>{"--traversal", "plain"},
                                                  {"--isa", "scalar"},
                                                  {"--isa", "avx2"}}) {
      auto args = std::vector<std::string>{"render", in.string(),          "--fragments",
                                           "-",      "--fragments-format", "binary"};
      args.insert(args.end(), extra.begin(), extra.end());
      const auto other = run_cli(args);
      if (other.status == 2 && other.err.find("cannot run") != std::string::npos)
        continue; // an instruction set this processor lacks
      EXPECT_TRUE(other.out == bin.out) << "binary, " << extra[0] << " " << extra[1];
    }
  }
}

// The names in a folder, sorted (a temporary file left behind shows here).
std::vector<std::string> entries_of(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, FAST.THREADS.DETERMINISTIC
// With --threads, a scene of the fast reader's form is written in units (runs of small triangles,
// bands of rows of large ones, made into bytes on the threads: write_fast_list): random scenes
// of thousands of small triangles (several units) and large ones (several bands, some past the
// target's edges, ties on pixel centres) give the plain traversal's JSON and binary lists for
// every thread count.
TEST(FragmentLists, ThreadsWriteTheRunsInUnitsAndBandsAsOneThreadDoes) {
  const unsigned seed = printed_seed("FragmentLists");
  std::mt19937 rng(seed);
  for (int round = 0; round < 2; ++round) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " round " + std::to_string(round));
    const int w = 100 + static_cast<int>(rng() % 300), h = 100 + static_cast<int>(rng() % 300);
    std::uniform_real_distribution<float> at(-40.0f, 440.0f), small(-3.0f, 3.0f);
    nlohmann::json scene = {{"target", {{"width", w}, {"height", h}}},
                            {"primitives", nlohmann::json::array()}};
    const int n = 3000 + static_cast<int>(rng() % 3000);
    for (int i = 0; i < n; ++i) {
      const bool large = rng() % 500 == 0;
      const float cx = at(rng), cy = at(rng);
      scene["primitives"].push_back(tie_heavy_triangle(rng, [&]() -> std::array<float, 2> {
        return {large ? at(rng) : cx + small(rng), large ? at(rng) : cy + small(rng)};
      }));
    }
    TempDir dir;
    const auto in = dir.write("s.json", scene.dump());
    for (const char* format : {"json", "binary"}) {
      const auto plain = run_cli({"render", in.string(), "--fragments", "-", "--fragments-format",
                                  format, "--traversal", "plain"});
      ASSERT_EQ(plain.status, 0) << plain.err;
      for (const char* threads : {"1", "2", "3", "8"}) {
        const auto got = run_cli({"render", in.string(), "--fragments", "-", "--fragments-format",
                                  format, "--threads", threads});
        ASSERT_EQ(got.status, 0) << got.err;
        EXPECT_TRUE(got.out == plain.out) << format << ", " << threads << " threads";
      }
    }
  }
}

// rule: SCENE.OUTPUT.COUNT
// Every other kind of scene is counted from its fragments as they stream (pipeline scenes from
// run_pipeline's list): the same counts as the fragment list, helper lanes left out.
TEST(FragmentCount, EveryKindOfSceneCountsItsFragmentList) {
  std::map<std::string, std::string> scenes = kScenes;
  scenes["quads_with_helpers"] =
      R"({"target": {"width": 8, "height": 8}, "quads": true, "derivatives": "coarse",
    "primitives": [{"type": "triangle", "v": [[0.5, 0.5], [7, 1], [1, 6]]}]})";
  scenes["area_and_aa"] = R"({"target": {"width": 8, "height": 8}, "primitives": [
    {"type": "path", "d": "M 1 1 L 7 2 L 6.5 6 L 2 7 Z", "coverage": "area"},
    {"type": "line", "v": [[0.5, 1], [7, 6]], "aa": true}]})";
  scenes["pipeline"] = R"({"target": {"width": 8, "height": 8}, "samples": 4,
    "depth": {"format": "d24", "func": "less"}, "primitives": [
    {"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]], "z": [0.5, 0.25, 0.75]},
    {"type": "triangle", "v": [[8, 8], [0, 8], [8, 0]], "z": [0.1, 0.9, 0.3]},
    {"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]], "z": [0.6, 0.6, 0.6]}]})";
  for (const auto& [name, scene] : scenes) {
    SCOPED_TRACE(name);
    TempDir dir;
    const auto in = dir.write("s.json", scene);
    const auto r = run_cli({"render", in.string(), "--count", (dir / "c.json").string()});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("fragments -> "), std::string::npos) << r.out;
    ASSERT_EQ(run_cli({"render", in.string(), "--fragments", (dir / "f.json").string()}).status, 0);
    const auto parsed = nlohmann::json::parse(scene);
    EXPECT_EQ(nlohmann::json::parse(read_file(dir / "c.json")),
              counts_of_list(rows_of_json(read_file(dir / "f.json")), parsed["primitives"].size()));
  }
}

// rule: SCENE.OUTPUT.COUNT, SCENE.OUTPUT.BINARY, SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
// A scene of triangles alone is counted (--count) or listed (--fragments OUT.bin) from its
// coordinates without being prepared; wherever that path declines (a vertex that does not snap,
// a target out of range, a work bound or a fragment count over its limit) the scene is loaded
// as any other: the same errors, byte for byte, as the prepared path (--traversal plain always
// takes it), no file left, and the same output where the exact work is within the limit that
// the bound passed.
TEST(FragmentCount, TheCoordinatesPathDeclinesToThePreparedPathsAnswers) {
  const auto scene_with = [](const std::string& target, const std::string& v) {
    return R"({"target":)" + target +
           R"(,"primitives":[{"type":"triangle","v":[[0,0],[4,0],[0,4]]},)" +
           R"({"type":"triangle","v":)" + v + "}]}";
  };
  const std::string fine_target = R"({"width":8,"height":8})";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {scene_with(fine_target, "[[1e9,0],[1,0],[0,1]]"), "primitives[1]"},
      {scene_with(fine_target, "[[0,0],[1,-8388609],[0,1]]"), "primitives[1]"},
      {scene_with(R"({"width":0,"height":8})", "[[0,0],[1,0],[0,1]]"), "target"},
      {scene_with(R"({"width":8,"height":99999})", "[[0,0],[1,0],[0,1]]"), "target"},
  };
  for (const auto& [scene, where] : bad) {
    SCOPED_TRACE(scene);
    TempDir dir;
    const auto in = dir.write("s.json", scene);
    // The list into a regular file is written as it is found and stops where it declines (its
    // temporary removed); one thread and two (units); standard output is counted first.
    for (const std::vector<std::string>& output :
         {std::vector<std::string>{"--count", "-"},
          {"--fragments", (dir / "f.bin").string(), "--fragments-format", "binary"},
          {"--fragments", (dir / "f.bin").string()},
          {"--fragments", (dir / "f.bin").string(), "--threads", "2"},
          {"--fragments", "-", "--threads", "2"}}) {
      auto args = std::vector<std::string>{"render", in.string()};
      args.insert(args.end(), output.begin(), output.end());
      const auto fast = run_cli(args);
      args.insert(args.end(), {"--traversal", "plain"});
      const auto prepared = run_cli(args);
      EXPECT_EQ(fast.status, 2);
      EXPECT_NE(fast.err.find(where), std::string::npos) << fast.err;
      EXPECT_EQ(fast.err, prepared.err);
      EXPECT_EQ(fast.out, "");
      EXPECT_EQ(entries_of(dir.path()), std::vector<std::string>{"s.json"});
    }
  }
  {
    // Over the fragment limit: the prepared path's error, and no file (binary and JSON, one
    // thread and two, into a file where the list stops past the limit and into standard output
    // where it is counted first).
    TempDir dir;
    const auto in = dir.write("s.json", scene_with(fine_target, "[[0,0],[8,0],[0,8]]"));
    for (const std::string name : {"f.bin", "f.json", "-"}) {
      for (const std::string threads : {"1", "2"}) {
        auto args =
            std::vector<std::string>{"render",          in.string(),
                                     "--fragments",     name == "-" ? name : (dir / name).string(),
                                     "--max-fragments", "20",
                                     "--threads",       threads};
        const auto fast = run_cli(args);
        args.insert(args.end(), {"--traversal", "plain"});
        const auto prepared = run_cli(args);
        EXPECT_EQ(fast.status, 2);
        EXPECT_NE(fast.err.find("more than 20 fragments"), std::string::npos) << fast.err;
        EXPECT_EQ(fast.err, prepared.err);
        EXPECT_EQ(fast.out, "");
        EXPECT_EQ(entries_of(dir.path()), std::vector<std::string>{"s.json"});
      }
    }
  }
  // The first triangle's walk is 4 x 4 pixels, the second's 2 x 2 (one covered; the others'
  // centres lie on its excluded diagonal): work 20 in all, which the bound ((floor(span) + 3)^2
  // per triangle, 49 + 25) overestimates.
  TempDir dir;
  const auto in = dir.write("s.json", scene_with(fine_target, "[[5,5],[7,5],[5,7]]"));
  const auto all = run_cli({"render", in.string(), "--count", "-"});
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_EQ(all.out, "{\"primitives\": 2, \"fragments\": 7, \"per_primitive\": [6, 1], "
                     "\"overdraw\": {\"pixels_touched\": 7, \"max\": 1, \"pixels\": [7]}}\n");
  const auto at_limit = run_cli({"render", in.string(), "--count", "-", "--max-work", "20"});
  EXPECT_EQ(at_limit.status, 0) << at_limit.err;
  EXPECT_EQ(at_limit.out, all.out);
  const auto over = run_cli({"render", in.string(), "--count", "-", "--max-work", "19"});
  EXPECT_EQ(over.status, 2);
  EXPECT_NE(over.err.find("primitives[1] brings the work to more than 19"), std::string::npos)
      << over.err;
  const auto bin_all =
      run_cli({"render", in.string(), "--fragments", "-", "--fragments-format", "binary"});
  const auto bin_at_limit = run_cli({"render", in.string(), "--fragments", "-",
                                     "--fragments-format", "binary", "--max-work", "20"});
  EXPECT_EQ(bin_at_limit.status, 0) << bin_at_limit.err;
  EXPECT_TRUE(bin_at_limit.out == bin_all.out);
  EXPECT_EQ(rows_of(read_binary(bin_all.out).fragments).size(), 7u);
}

// rule: SCENE.OUTPUT.COUNT, SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY
// rule: SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS, FAST.THREADS.DETERMINISTIC
// A scene whose keys all come before its list is counted (--count) or listed (--fragments FILE,
// binary or JSON) as it is read, in chunks of io::kTriangleStreamChunk triangles (with two or
// more threads on a thread beside the reader): the same bytes as the plain traversal (always
// prepared) for every thread count, with a state key after the list (read the other way) too;
// a vertex that does not snap in the last chunk, a work limit or a fragment limit passed after
// the first chunk give the prepared path's error and leave no file.
TEST(FragmentCount, ScenesCountedAsTheyAreReadGiveTheWholeListsCounts) {
  const unsigned seed = printed_seed("FragmentCountStream");
  std::mt19937 rng(seed);
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::uniform_int_distribution<int> at(-10, 70), leg(0, 4), far(-2000, 2000);
  const std::size_t n = 2 * io::kTriangleStreamChunk + 123;
  std::vector<std::string> tris;
  for (std::size_t i = 0; i < n; ++i) {
    const int x = at(rng), y = at(rng);
    // Small triangles with shared, tie-heavy integer vertices; after the first chunk, every 11th
    // large (its walk nearly always the whole target: work 64 x 60).
    const bool large = i >= io::kTriangleStreamChunk && i % 11 == 0;
    const auto v = [&](int dx, int dy) {
      return "[" + std::to_string(large ? far(rng) : x + dx) + "," +
             std::to_string(large ? far(rng) : y + dy) + "]";
    };
    tris.push_back(R"({"type":"triangle","v":[)" + v(0, 0) + "," + v(leg(rng), leg(rng)) + "," +
                   v(leg(rng), leg(rng)) + "]}");
  }
  const auto scene = [&](const std::string& before, const std::string& after, std::size_t bad_at) {
    std::string s = R"({"target":{"width":64,"height":60})" + before + R"(,"primitives":[)";
    for (std::size_t i = 0; i < n; ++i)
      s += (i ? "," : "") +
           (i == bad_at ? R"({"type":"triangle","v":[[0,0],[1e9,0],[0,1]]})" : tris[i]);
    return s + "]" + after + "}";
  };
  const TempDir scenes;
  const auto in = scenes.write("s.json", scene(R"(,"cull":"back","fill":"bottom-right")", "", n));
  const auto late =
      scenes.write("late.json", scene(R"(,"fill":"bottom-right")", R"(,"cull":"back")", n));
  const auto bad = scenes.write("bad.json", scene(R"(,"cull":"back")", "", n - 5));
  const TempDir out;
  // What an output holds: standard output for --count, the file for a list.
  const auto run = [&](const std::filesystem::path& file, const std::string& output,
                       std::vector<std::string> extra) {
    auto args = std::vector<std::string>{"render", file.string()};
    if (output == "count")
      args.insert(args.end(), {"--count", "-"});
    else
      args.insert(args.end(), {"--fragments", (out / ("o." + output)).string()});
    args.insert(args.end(), extra.begin(), extra.end());
    rastrules::test::RunResult r = run_cli(args);
    if (output != "count" && r.status == 0) {
      r.out = read_file(out / ("o." + output));
      std::filesystem::remove(out / ("o." + output));
    }
    return r;
  };
  for (const std::string output : {"count", "bin", "json"}) {
    SCOPED_TRACE(output);
    const auto plain = run(in, output, {"--traversal", "plain"});
    ASSERT_EQ(plain.status, 0) << plain.err;
    if (output == "count") {
      EXPECT_EQ(plain.out.rfind("{\"primitives\": " + std::to_string(n) + ",", 0), 0u);
    }
    // The JSON list (34 MB) on the scene and thread counts that reach its own code alone.
    const bool json = output == "json";
    for (const std::filesystem::path& file :
         json ? std::vector<std::filesystem::path>{in} : std::vector{in, late}) {
      for (const std::string& threads :
           json ? std::vector<std::string>{"1", "2"} : std::vector<std::string>{"1", "2", "3"}) {
        const auto r = run(file, output, {"--threads", threads});
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_TRUE(r.out == plain.out) << file << " threads " << threads;
      }
    }
    // The first chunk's work bound is at most 49 a triangle (spans of at most 4 px) and its
    // fragments a few a triangle: under these limits, which the large triangles after it pass.
    const std::uint64_t work_limit = 49 * io::kTriangleStreamChunk + 1000;
    const std::uint64_t fragment_limit = 20 * io::kTriangleStreamChunk;
    std::vector<std::pair<std::filesystem::path, std::vector<std::string>>> refused = {
        {bad, {"--max-work", "100000000"}}, {in, {"--max-work", std::to_string(work_limit)}}};
    if (json)
      refused.erase(refused.begin() + 1); // the work limit is checked before the format matters
    if (output != "count")
      refused.push_back({in, {"--max-fragments", std::to_string(fragment_limit)}});
    for (const auto& [file, limit] : refused) {
      auto extra = limit;
      extra.insert(extra.end(), {"--traversal", "plain"});
      const auto prepared = run(file, output, extra);
      EXPECT_EQ(prepared.status, 2);
      EXPECT_NE(prepared.err.find(file == bad ? "primitives[" + std::to_string(n - 5) + "]"
                                  : limit[0] == "--max-work"
                                      ? "brings the work to more than"
                                      : "more than " + std::to_string(fragment_limit)),
                std::string::npos)
          << prepared.err;
      for (const std::string threads : {"1", "2"}) {
        extra = limit;
        extra.insert(extra.end(), {"--threads", threads});
        const auto fast = run(file, output, extra);
        EXPECT_EQ(fast.status, 2) << file << " threads " << threads;
        EXPECT_EQ(fast.err, prepared.err);
        EXPECT_TRUE(fast.out.empty());
        EXPECT_EQ(entries_of(out.path()), std::vector<std::string>{});
      }
    }
  }
}

// rule: SCENE.OUTPUT.COUNT
TEST(FragmentCount, LargeTargetsCountPrimitivesWithoutTheOverdrawMap) {
  TempDir dir;
  const auto in = dir.write("s.json", R"({"target": {"width": 16384, "height": 8192},
    "primitives": [{"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]]}]})");
  const auto r = run_cli({"render", in.string(), "--count", "-"});
  ASSERT_EQ(r.status, 0) << r.err;
  // Pixel (x, y) is covered when x + y <= 2 (the diagonal is a right edge: excluded).
  EXPECT_EQ(r.out, "{\"primitives\": 1, \"fragments\": 6, \"per_primitive\": [6], "
                   "\"overdraw\": null}\n");
}

// rule: SCENE.OUTPUT.COUNT, SCENE.OUTPUT.BINARY
TEST(FragmentCount, UsageErrorsNameTheOption) {
  TempDir dir;
  const auto in = dir.write("s.json", kScenes.at("triangles"));
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--count", "c.json", "--fragments", "f.json"}, "--count writes the counts alone"},
      {{"--count", ""}, "--count needs a file name"},
      {{"--png", "p.png", "--fragments-format", "binary"}, "--fragments-format needs --fragments"},
      {{"--fragments", "f", "--fragments-format", "csv"},
       "--fragments-format needs \"json\", \"binary\" or \"binary-v1\", got \"csv\""},
  };
  for (const auto& [extra, message] : cases) {
    auto args = std::vector<std::string>{"render", in.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  // The work limit applies before anything is counted.
  const auto r = run_cli({"render", in.string(), "--count", "-", "--max-work", "10"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("primitives[0] brings the work to more than 10"), std::string::npos)
      << r.err;
}

} // namespace
