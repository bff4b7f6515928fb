// SPDX-License-Identifier: MIT
// The scene reader and writer and the fragment writer (tools/io), called directly.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <variant>

#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "support.hpp"

namespace {

using rastrules::Scene;
using rastrules::SceneError;

std::uint32_t bits(float f) {
  return std::bit_cast<std::uint32_t>(f);
}

Scene read_ok(const std::string& text) {
  auto r = rastrules::io::read_scene(text);
  if (auto* e = std::get_if<SceneError>(&r))
    ADD_FAILURE() << "unexpected error: " << e->what();
  return std::holds_alternative<Scene>(r) ? std::get<Scene>(r) : Scene{};
}

std::string one_triangle(const std::string& x0) {
  return R"({"target": {"width": 4, "height": 4}, "primitives": [{"type": "triangle", "v": [[)" +
         x0 + R"(, 0], [4, 0], [0, 4]]}]})";
}

// rule: SCENE.NUMBER.FLOAT32
TEST(SceneNumberFloat32, DecimalTextIsRoundedOnceStraightToFloat32) {
  // 1 + 2^-24 + 1e-20 lies just above the midpoint between the floats 1 and 1 + 2^-23.
  // Correct rounding gives 1 + 2^-23; going through double first lands exactly on the
  // midpoint and then ties to even, giving 1.
  const std::string text = "1.00000005960464477539062501";
  const auto f = rastrules::io::decimal_to_float32(text);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(bits(*f), bits(1.00000011920928955078125f));
  EXPECT_EQ(bits(static_cast<float>(std::stod(text))), bits(1.0f)); // the double rounding avoided
}

// rule: SCENE.NUMBER.FLOAT32, SNAP.VERTEX.ROUND
TEST(SceneNumberFloat32, DoubleRoundingWouldChangeTheSnappedVertex) {
  // 16384 + 1/256 + 1/1024 + 1e-20: float32 spacing here is 1/512. Directly: 16384 + 3/512
  // (snaps to raw 4194306 by ties-to-even); through double: 16384 + 2/512 (raw 4194305).
  const Scene s = read_ok(one_triangle("16384.00488281250000000001"));
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(bits(s.primitives[0].v[0][0]), bits(16384.005859375f));
}

// rule: SCENE.NUMBER.FLOAT32
TEST(SceneNumberFloat32, IntegersAreRoundedToFloat32TiesToEven) {
  EXPECT_EQ(bits(read_ok(one_triangle("16777217")).primitives[0].v[0][0]), bits(16777216.0f));
  EXPECT_EQ(bits(read_ok(one_triangle("16777219")).primitives[0].v[0][0]), bits(16777220.0f));
  EXPECT_EQ(bits(read_ok(one_triangle("-3")).primitives[0].v[0][0]), bits(-3.0f));
}

// rule: SCENE.NUMBER.FLOAT32
TEST(SceneNumberFloat32, NumbersBeyondFloat32BecomeInfinitiesAndTinyOnesZeros) {
  using rastrules::io::decimal_to_float32;
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(decimal_to_float32("1e39"), inf);
  EXPECT_EQ(decimal_to_float32("-1e39"), -inf);
  EXPECT_EQ(decimal_to_float32("3.40282357e38"), inf); // above FLT_MAX's rounding boundary
  EXPECT_EQ(bits(*decimal_to_float32("3.4028235e38")), bits(std::numeric_limits<float>::max()));
  EXPECT_EQ(bits(*decimal_to_float32("1e-50")), bits(0.0f));
  EXPECT_EQ(bits(*decimal_to_float32("-1e-50")), bits(-0.0f));
  EXPECT_EQ(bits(*decimal_to_float32("0.00000000000000000000000000000000000000000000140129846")),
            bits(std::numeric_limits<float>::denorm_min()));
  EXPECT_FALSE(decimal_to_float32("abc").has_value());
  EXPECT_FALSE(decimal_to_float32("inf").has_value());
  EXPECT_FALSE(decimal_to_float32("1.5x").has_value());
}

// rule: SCENE.NUMBER.FLOAT32
TEST(SceneNumberFloat32, SpecialValueStringsAreReadAsTheirFloats) {
  const Scene s = read_ok(R"({"target": {"width": 4, "height": 4}, "primitives": [
      {"type": "triangle", "v": [["NaN", 0], ["Infinity", 0], [0, "-Infinity"]]}]})");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_TRUE(std::isnan(s.primitives[0].v[0][0]));
  EXPECT_EQ(s.primitives[0].v[1][0], std::numeric_limits<float>::infinity());
  EXPECT_EQ(s.primitives[0].v[2][1], -std::numeric_limits<float>::infinity());
}

// rule: SCENE.FORMAT.V1
TEST(SceneFormatV1, OptionalKeysTakeTheirDefaults) {
  const Scene s = read_ok(R"({"target": {"width": 16, "height": 8}, "primitives": []})");
  EXPECT_EQ(s.width, 16);
  EXPECT_EQ(s.height, 8);
  EXPECT_EQ(s.cull, rastrules::CullMode::kNone);
  EXPECT_EQ(s.conventions.front_face, rastrules::FrontFace::kClockwise);
  EXPECT_EQ(s.conventions.fill, rastrules::FillConvention::kTopLeft);
  EXPECT_TRUE(s.primitives.empty());
}

// rule: SCENE.FORMAT.V1
TEST(SceneFormatV1, EveryKeyOfTheSpecExampleIsRead) {
  const Scene s = read_ok(R"({
    "version": 1,
    "target": {"width": 16, "height": 8},
    "cull": "front",
    "front_face": "ccw",
    "fill": "bottom-right",
    "primitives": [
      {"type": "triangle", "v": [[1.0, 1.0], [9.5, 2.0], [2.0, 7.25]]}
    ]
  })");
  EXPECT_EQ(s.cull, rastrules::CullMode::kFront);
  EXPECT_EQ(s.conventions.front_face, rastrules::FrontFace::kCounterClockwise);
  EXPECT_EQ(s.conventions.fill, rastrules::FillConvention::kBottomRight);
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].v[1][0], 9.5f);
  EXPECT_EQ(s.primitives[0].v[2][1], 7.25f);
}

// rule: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32
TEST(SceneFormatV1, WrittenScenesReadBackBitForBit) {
  Scene s;
  s.width = 7;
  s.height = 3;
  s.cull = rastrules::CullMode::kBack;
  s.conventions.fill = rastrules::FillConvention::kTopRight;
  const float values[] = {0.1f,
                          -0.0f,
                          1e-45f,
                          3.4028235e38f,
                          16384.005859375f,
                          1.0f / 3.0f,
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(),
                          std::numeric_limits<float>::quiet_NaN(),
                          32767.99609375f,
                          -32768.0f,
                          7.0f};
  rastrules::Primitive p;
  for (std::size_t i = 0; i < std::size(values); ++i) {
    p.v[(i / 2) % 3][i % 2] = values[i];
    if (i % 6 == 5)
      s.primitives.push_back(p);
  }
  const std::string text = rastrules::io::write_scene(s);
  const Scene back = read_ok(text);
  EXPECT_EQ(rastrules::io::write_scene(back), text);
  ASSERT_EQ(back.primitives.size(), s.primitives.size());
  for (std::size_t n = 0; n < s.primitives.size(); ++n) {
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 2; ++k) {
        // NaN is written as "NaN" and read as the quiet NaN, the one stored here.
        EXPECT_EQ(bits(back.primitives[n].v[i][k]), bits(s.primitives[n].v[i][k]))
            << "primitive " << n << " v[" << i << "][" << k << "] written as " << text;
      }
    }
  }
  EXPECT_EQ(back.cull, rastrules::CullMode::kBack);
  EXPECT_EQ(back.conventions.fill, rastrules::FillConvention::kTopRight);
}

// rule: SCENE.INPUT.ERRORS
TEST(SceneInputErrors, TheFirstErrorInReadingOrderNamesItsField) {
  auto r = rastrules::io::read_scene(R"({"target": {"width": 4, "height": 4}, "primitives": [
      {"type": "triangle", "v": [[0, 0], [1, 0], [0, 1]]},
      {"type": "triangle", "v": [[0, 0], [1, "x"], [0, 1]], "extra": 1}]})");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_EQ(std::get<SceneError>(r).field, "primitives[1].v[1][1]");
}

// rule: SCENE.INPUT.ERRORS
TEST(SceneInputErrors, ControlAndNonAsciiBytesInMessagesAreEscaped) {
  auto r = rastrules::io::read_scene(
      "{\"fill\": \"top-\xc3\xa9\\n\", \"target\": {\"width\": 1, \"height\": 1}}");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  const std::string what = std::get<SceneError>(r).what();
  EXPECT_EQ(what.find('\n'), std::string::npos);
  EXPECT_NE(what.find("top-\\xc3\\xa9\\x0a"), std::string::npos) << what;
}

// rule: SCENE.OUTPUT.FRAGMENTS
TEST(SceneOutputFragments, WriterStreamsInOrderAndRefusesFragmentsOutOfOrder) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  rastrules::io::FragmentWriter w(f);
  EXPECT_TRUE(w.add({0, 3, 1, 1}));
  EXPECT_TRUE(w.add({0, 0, 2, 1}));
  EXPECT_FALSE(w.add({0, 5, 1, 1})); // row 1 after row 2
  EXPECT_FALSE(w.add({0, 0, 2, 1})); // a duplicate
  EXPECT_TRUE(w.add({1, 0, 0, 1}));
  ASSERT_TRUE(w.finish());
  EXPECT_EQ(w.count(), 3u);
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;)
    text += static_cast<char>(c);
  std::fclose(f);
  EXPECT_EQ(text, "{\"fragments\": [\n"
                  "  {\"prim\": 0, \"x\": 3, \"y\": 1, \"mask\": 1},\n"
                  "  {\"prim\": 0, \"x\": 0, \"y\": 2, \"mask\": 1},\n"
                  "  {\"prim\": 1, \"x\": 0, \"y\": 0, \"mask\": 1}\n"
                  "]}\n");
  EXPECT_EQ(rastrules::io::fragments_to_json({{0, 3, 1, 1}, {0, 0, 2, 1}, {1, 0, 0, 1}}), text);
  EXPECT_EQ(rastrules::io::fragments_to_json({}), "{\"fragments\": []}\n");
}

std::string file_text(std::FILE* f) {
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;)
    text += static_cast<char>(c);
  return text;
}

// rule: SCENE.OUTPUT.FRAGMENTS
// A run's text (add_run, RunText: digits incremented in place) is the text of its fragments
// added one by one, across every carry (9 -> 10, 999 -> 1000, 16383 -> 16384), at x = 0, at a
// negative x (never from a target, written the plain way) and with the largest prim.
TEST(SceneOutputFragments, RunsAreWrittenAsTheirFragmentsOneByOne) {
  struct Run {
    std::uint32_t prim;
    std::int32_t y, x;
    std::uint32_t n;
  };
  const std::vector<Run> runs = {{0, 0, 0, 1},     {0, 0, 5, 7},
                                 {0, 1, 0, 120},   {0, 2, 990, 20},
                                 {3, 0, 9995, 10}, {3, 7, 16370, 14},
                                 {4, -3, -12, 15}, {5, 9, 98, 1},
                                 {5, 9, 100, 900}, {4294967295u, 16383, 0, 2}};
  std::FILE* one = std::tmpfile();
  std::FILE* run = std::tmpfile();
  ASSERT_NE(one, nullptr);
  ASSERT_NE(run, nullptr);
  {
    rastrules::io::FragmentWriter by_one(one);
    rastrules::io::FragmentWriter by_run(run);
    rastrules::io::RunText run_text; // keeps a primitive's head across its runs
    for (const Run& r : runs) {
      std::string encoded_one, encoded_run;
      for (std::uint32_t k = 0; k < r.n; ++k) {
        const rastrules::Fragment f(r.prim, r.x + static_cast<std::int32_t>(k), r.y, 1);
        ASSERT_TRUE(by_one.add(f));
        rastrules::io::FragmentWriter::encode(f, encoded_one);
      }
      ASSERT_TRUE(by_run.add_run(r.prim, r.y, r.x, r.n));
      run_text.append(encoded_run, r.prim, r.y, r.x, r.n, false);
      EXPECT_EQ(encoded_run, encoded_one) << "run at x " << r.x;
    }
    EXPECT_FALSE(by_run.add_run(5, 9, 100, 1)); // before the last fragment: refused
    ASSERT_TRUE(by_one.finish());
    ASSERT_TRUE(by_run.finish());
    EXPECT_EQ(by_run.count(), by_one.count());
  }
  const std::string text = file_text(run);
  EXPECT_EQ(text, file_text(one));
  EXPECT_NE(text.find("\"x\": 16383,"), std::string::npos);
  std::fclose(one);
  std::fclose(run);
}

} // namespace

namespace {

// rule: SCENE.INPUT.FAST_READER, SCENE.NUMBER.FLOAT32
// The fast path reads its one form to the general reader's scene, numbers rounded alike, and
// declines everything else, whose result (or error) is then the general reader's.
// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
// open_scene_file maps a regular file and otherwise reads as read_scene_file does: the same
// text, the same errors (a missing file, a directory, the size limit), an empty file empty.
TEST(SceneFile, MappedTextIsTheFileAndErrorsAreReadSceneFilesOwn) {
  namespace io = rastrules::io;
  using rastrules::io::kMaxSceneBytes;
  const rastrules::test::TempDir dir;
  const std::string body = R"({"target": {"width": 4, "height": 4}, "primitives": []})";
  const auto file = dir.write("s.json", body);
  auto mapped = io::open_scene_file(file.string());
  ASSERT_TRUE(std::holds_alternative<io::SceneText>(mapped));
  EXPECT_TRUE(std::get<io::SceneText>(mapped).mapped());
  EXPECT_EQ(std::get<io::SceneText>(mapped).view(), body);
  io::SceneText moved = std::move(std::get<io::SceneText>(mapped));
  EXPECT_EQ(moved.view(), body);

  const auto empty = dir.write("empty.json", "");
  auto e = io::open_scene_file(empty.string());
  ASSERT_TRUE(std::holds_alternative<io::SceneText>(e));
  EXPECT_TRUE(std::get<io::SceneText>(e).view().empty());

  const auto big = dir / "big.json";
  {
    std::FILE* f = std::fopen(big.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(::ftruncate(::fileno(f), static_cast<off_t>(kMaxSceneBytes + 1)), 0);
    std::fclose(f);
  }
  for (const std::string& path :
       {(dir / "missing.json").string(), dir.path().string(), big.string()}) {
    auto a = io::open_scene_file(path);
    auto b = io::read_scene_file(path);
    ASSERT_TRUE(std::holds_alternative<SceneError>(a)) << path;
    ASSERT_TRUE(std::holds_alternative<SceneError>(b)) << path;
    EXPECT_EQ(std::get<SceneError>(a).what(), std::get<SceneError>(b).what());
  }
}

TEST(FastSceneReader, ReadsItsFormAsTheGeneralReaderAndDeclinesTheRest) {
  const auto tri = [](const std::string& v) {
    return R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "triangle", "v": )" +
           v + "}]}";
  };
  const std::vector<std::string> taken = {
      tri("[[0, 0], [4, 0], [0, 4]]"),
      tri("[[-0, -0.0], [1e2, 0.1], [16777217, 16777217.0]]"), // -0 is the integer 0
      tri("[[1.00000005960464477539, 3.4028235e38], [1E-45, -2.5e-3], [123456789012345678, 0]]"),
      R"( { "primitives" : [ ] , "target" : { "height" : 3 , "width" : -7 } } )",
      "{\"primitives\":[{\"v\":[[1,2],[3,4],[5,6]],\"type\":\"triangle\"},\n"
      "{\"type\":\"triangle\",\"v\":[[0.5,0.5],[2.5,0.5],[0.5,2.5]]}],"
      "\"target\":{\"width\":16384,\"height\":1}}",
      // The version and the window-space state, each once, in any order.
      R"({"version": 1, "cull": "back", "target": {"width": 8, "height": 8}, "fill": )"
      R"("bottom-right", "primitives": [], "front_face": "ccw", "line_mode": "quad-wide"})",
  };
  for (const std::string& text : taken) {
    SCOPED_TRACE(text);
    const auto fast = rastrules::io::read_scene_fast(text);
    ASSERT_TRUE(fast.has_value());
    const auto general = rastrules::io::read_scene_general(text);
    ASSERT_TRUE(std::holds_alternative<Scene>(general));
    EXPECT_TRUE(rastrules::io::same_scene(*fast, std::get<Scene>(general)));
  }
  // 16777217 is not a float32: both readers round it once, to 16777216.
  const auto rounded = rastrules::io::read_scene_fast(taken[1]);
  EXPECT_EQ(rounded->primitives[0].v[2][0], 16777216.0f);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(rounded->primitives[0].v[0][0]), 0u); // +0
  EXPECT_TRUE(std::signbit(rounded->primitives[0].v[0][1]));                   // -0.0

  const std::vector<std::string> declined = {
      tri("[[0, 0], [4, 0], [0, \"NaN\"]]"),
      tri("[[0, 0], [4, 0], [0, 1e400]]"),
      tri("[[0, 0], [4, 0], [0, 1e-50]]"),
      tri("[[0, 0], [4, 0], [0, 1234567890123456789]]"),
      tri("[[0, 0], [4, 0], [0, 4], [1, 1]]"),
      tri("[[0, 0], [4, 0], [0, 4, 1]]"),
      tri("[[0, 0], [4, 0], [0, 4]], \"aa\": true"),
      tri("[[0, 0], [4, 0], [0, 04]]"),
      tri("[[0, 0], [4, 0], [0, +4]]"),
      tri("[[0, 0], [4, 0], [0, 4.]]"),
      tri("[[0, 0], [4, 0], [0, 4]]}, {\"type\": \"point\", \"v\": [[1, 1]]"),
      R"({"target": {"width": 8, "height": 8}, "cull": "sideways", "primitives": []})",
      R"({"target": {"width": 8, "height": 8}, "cull": "back", "cull": "back", "primitives": []})",
      R"({"target": {"width": 8, "height": 8}, "cull": "b\u0061ck", "primitives": []})",
      R"({"version": 2, "target": {"width": 8, "height": 8}, "primitives": []})",
      R"({"version": 1.0, "target": {"width": 8, "height": 8}, "primitives": []})",
      R"({"target": {"width": 8, "height": 8}, "samples": 1, "primitives": []})",
      R"({"target": {"width": 8, "width": 8}, "primitives": []})",
      R"({"target": {"width": 8.0, "height": 8}, "primitives": []})",
      R"({"target": {"width": 8, "height": 8}, "primitives": [], "primitives": []})",
      R"({"target": {"width": 8, "height": 8}, "primitives": [{"type": "tri\u0061ngle", "v": [[0, 0], [4, 0], [0, 4]]}]})",
      R"({"target": {"width": 8, "height": 8}, "primitives": [,]})",
      R"({"target": {"width": 8, "height": 8}, "primitives": []} x)",
      R"({"target": {"width": 8, "height": 8}})",
      "",
  };
  for (const std::string& text : declined) {
    SCOPED_TRACE(text);
    EXPECT_FALSE(rastrules::io::read_scene_fast(text).has_value());
    // read_scene is then the general reader, errors included.
    const auto both = rastrules::io::read_scene(text);
    const auto general = rastrules::io::read_scene_general(text);
    ASSERT_EQ(both.index(), general.index());
    if (const auto* e = std::get_if<SceneError>(&both)) {
      EXPECT_EQ(e->what(), std::get<SceneError>(general).what());
    }
  }
}

// rule: SCENE.INPUT.FAST_READER, SCENE.NUMBER.FLOAT32
// A triangle written without whitespace, with 128 bytes of text after it, is read in one pass
// (compact_vertices); each spelling below, at each of the six coordinates, reads as the same
// triangle written with spaces (which the token reader reads), or is declined alike, and never
// differs from the general reader: leading zeros, a ninth digit, points and exponents, signs.
TEST(FastSceneReader, CompactTrianglesReadAsSpacedOnesAndDeclineAlike) {
  const std::vector<std::string> spellings = {
      "0",          "-0",         "-0.0",      "01",        "-01",         "00",
      "1.",         ".5",         "-",         "--1",       "+1",          "1.5",
      "-1.25",      "12345678",   "123456789", "1234567.8", "1234567.89",  "0.0000001",
      "0.00000001", "16777216.5", "1677721.7", "1677721.6", "-1677721.7",  "1e2",
      "1E2",        "1.5e1",      "7",         "99999999",  "999999999.0", "0.10000000"};
  const std::string more = R"({"type":"triangle","v":[[1,1],[5,1],[1,5]]})";
  for (const std::string& sp : spellings)
    for (int at = 0; at < 6; ++at) {
      std::string c[6] = {"0", "0", "4", "0", "0", "4"};
      c[at] = sp;
      const std::string compact = R"({"target":{"width":8,"height":8},"primitives":[)"
                                  R"({"type":"triangle","v":[[)" +
                                  c[0] + "," + c[1] + "],[" + c[2] + "," + c[3] + "],[" + c[4] +
                                  "," + c[5] + "]]}," + more + "," + more + "," + more + "]}";
      const std::string spaced = R"({"target": {"width": 8, "height": 8}, "primitives": [)"
                                 R"({"type": "triangle", "v": [[)" +
                                 c[0] + ", " + c[1] + "], [" + c[2] + ", " + c[3] + "], [" + c[4] +
                                 ", " + c[5] + "]]}, " + more + ", " + more + ", " + more + "]}";
      SCOPED_TRACE(compact);
      const auto fast = rastrules::io::read_scene_fast(compact);
      const auto fast_spaced = rastrules::io::read_scene_fast(spaced);
      const auto general = rastrules::io::read_scene_general(compact);
      ASSERT_EQ(fast.has_value(), fast_spaced.has_value());
      if (!fast) {
        continue;
      }
      EXPECT_TRUE(rastrules::io::same_scene(*fast, *fast_spaced));
      ASSERT_TRUE(std::holds_alternative<Scene>(general));
      EXPECT_TRUE(rastrules::io::same_scene(*fast, std::get<Scene>(general)));
    }
}

} // namespace
