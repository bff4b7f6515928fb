// SPDX-License-Identifier: MIT
// Properties of the scene reader's fast path: random scenes of triangles, written with every
// spelling of their numbers (integers, shortest decimals, 9 and 17 significant digits, exponent
// forms, -0), any whitespace and either key order, are read by read_scene_fast to exactly the
// scene read_scene_general reads; and any text near them (one character inserted, deleted or
// replaced) is either left to the general reader or read to the same scene. The coordinates-only
// form (read_triangles_fast, render --count) declines and reads alike.
// Implements (properties for): SCENE.INPUT.FAST_READER

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/io/scene_json.hpp"

namespace {

namespace io = rastrules::io;

// A float32: small integers, quarters, any finite float of magnitude in [2^-20, 2^40], zeros.
rc::Gen<float> coordinate() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::inRange(-5000, 5001), [](int v) { return static_cast<float>(v); }),
      rc::gen::map(rc::gen::inRange(-40000, 40001),
                   [](int v) { return static_cast<float>(v) / 4.0f; }),
      rc::gen::map(rc::gen::tuple(rc::gen::inRange(0, 1 << 23), rc::gen::inRange(-20, 41),
                                  rc::gen::arbitrary<bool>()),
                   [](const std::tuple<int, int, bool>& t) {
                     const float m = 1.0f + static_cast<float>(std::get<0>(t)) / 8388608.0f;
                     return std::ldexp(m, std::get<1>(t)) * (std::get<2>(t) ? -1.0f : 1.0f);
                   }),
      rc::gen::element(0.0f, -0.0f));
}

// v written in one of several JSON spellings; every one reads back (SCENE.NUMBER.FLOAT32) to
// v, or for the 9-digit forms to the float32 nearest that decimal, which is v.
std::string spell(float v, int how) {
  char buf[64];
  switch (how) {
  case 0:
    return io::format_float(v);
  case 1:
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
    return buf;
  case 2:
    std::snprintf(buf, sizeof buf, "%.17e", static_cast<double>(v));
    return buf;
  case 3:
    std::snprintf(buf, sizeof buf, "%.8E", static_cast<double>(v));
    return buf;
  default:
    // An integer spelling where v is an integer (of any size: long ones are left to the
    // general reader), else the shortest.
    if (std::trunc(v) == v && std::fabs(v) < 1e30f) {
      std::snprintf(buf, sizeof buf, "%.0f", static_cast<double>(v));
      return buf;
    }
    return io::format_float(v);
  }
}

std::string ws(int k) {
  static const char* const kinds[] = {"", " ", "\n", "\t ", "\r\n  "};
  return kinds[k % 5];
}

struct Written {
  std::string text;
  bool expect_fast = true; // every number is in a form the fast path takes
};

rc::Gen<Written> scene_text() {
  return rc::gen::exec([] {
    const int w = *rc::gen::inRange(-3, 20000);
    const int h = *rc::gen::inRange(0, 20000);
    // Compact: no whitespace anywhere, as generated scenes are written (the fast reader's
    // compact_vertices reads such triangles in one pass, where 128 bytes of text remain).
    const bool compact = *rc::gen::arbitrary<bool>();
    const auto n = *rc::gen::inRange<std::size_t>(0, compact ? 16 : 12);
    const auto gap = [compact] { return compact ? std::string() : ws(*rc::gen::inRange(0, 5)); };
    Written out;
    const bool target_first = *rc::gen::arbitrary<bool>();
    const std::string target =
        "\"target\"" + gap() + ":" + gap() + "{" + gap() +
        (*rc::gen::arbitrary<bool>() ? "\"width\":" + gap() + std::to_string(w) + "," + gap() +
                                           "\"height\":" + std::to_string(h)
                                     : "\"height\":" + std::to_string(h) + gap() + "," +
                                           "\"width\":" + gap() + std::to_string(w)) +
        gap() + "}";
    std::string prims = "\"primitives\"" + gap() + ":" + gap() + "[";
    for (std::size_t i = 0; i < n; ++i) {
      std::string v = "[";
      for (int k = 0; k < 3; ++k) {
        v += (k > 0 ? "," + gap() : "") + "[";
        for (int c = 0; c < 2; ++c) {
          const float f = *coordinate();
          const int how = *rc::gen::inRange(0, 5);
          const std::string s = spell(f, how);
          const std::size_t digits = s.size() - (s[0] == '-' ? 1 : 0);
          if (s.find_first_of(".eE") == std::string::npos && digits > 18)
            out.expect_fast = false;
          v += (c > 0 ? "," + gap() : gap()) + s;
        }
        v += gap() + "]";
      }
      v += "]";
      const std::string type = "\"type\"" + gap() + ":" + gap() + "\"triangle\"";
      const std::string vert = "\"v\"" + gap() + ":" + gap() + v;
      prims +=
          (i > 0 ? ",\n" : "") + gap() + "{" +
          (*rc::gen::arbitrary<bool>() ? type + "," + gap() + vert : vert + gap() + "," + type) +
          "}";
    }
    prims += gap() + "]";
    // The root's keys: target, primitives and some of the optional ones the fast form takes,
    // in any order. A key twice, a value the general reader refuses ("sideways", version 2), a
    // value the fast form does not take (version 1.0) or a key it does not take ("samples")
    // sends the text to the general reader.
    std::vector<std::string> keys = {target, prims};
    if (!target_first)
      std::swap(keys[0], keys[1]);
    struct Key {
      const char* name;
      std::vector<const char*> values; // JSON texts; the first `fast` are taken
      std::size_t fast;
    };
    static const std::vector<Key> kKeys = {
        {"cull", {"\"none\"", "\"back\"", "\"front\"", "\"sideways\""}, 3},
        {"front_face", {"\"cw\"", "\"ccw\""}, 2},
        {"fill", {"\"top-left\"", "\"top-right\"", "\"bottom-left\"", "\"bottom-right\""}, 4},
        {"line_mode", {"\"d3d\"", "\"vulkan-bresenham\"", "\"quad-wide\"", "\"quad-narrow\""}, 4},
        {"version", {"1", "2", "1.0"}, 1},
        {"samples", {"1"}, 0},
    };
    std::vector<int> times(kKeys.size(), 0);
    const auto extra = *rc::gen::container<std::vector<std::size_t>>(
        *rc::gen::inRange<std::size_t>(0, 4), rc::gen::inRange<std::size_t>(0, kKeys.size()));
    for (const std::size_t k : extra) {
      const Key& key = kKeys[k];
      const auto v = *rc::gen::inRange<std::size_t>(0, key.values.size());
      if (v >= key.fast || ++times[k] > 1)
        out.expect_fast = false;
      const auto at = *rc::gen::inRange<std::size_t>(0, keys.size() + 1);
      keys.insert(keys.begin() + static_cast<std::ptrdiff_t>(at),
                  std::string("\"") + key.name + "\"" + gap() + ":" + gap() + key.values[v]);
    }
    std::string body;
    for (std::size_t k = 0; k < keys.size(); ++k)
      body += (k > 0 ? "," + gap() : "") + keys[k];
    out.text = gap() + "{" + gap() + body + gap() + "}" + gap();
    return out;
  });
}

// read_triangles_fast declines exactly where read_scene_fast does, and otherwise holds the same
// scene without its primitives and their coordinates, in order.
void check_triangles_agree(const std::string& text, const std::optional<rastrules::Scene>& fast) {
  // One thread, and the list in parts on several (parts of at least 1 to 40 bytes, so that
  // texts of a few triangles split, at any guess of a part's start): the same result.
  const auto threads = *rc::gen::inRange(2u, 6u);
  const auto part_bytes = *rc::gen::inRange<std::size_t>(1, 41);
  for (const std::optional<io::FastTriangles>& t :
       {io::read_triangles_fast(text), io::read_triangles_fast(text, threads, part_bytes)}) {
    RC_ASSERT(t.has_value() == fast.has_value());
    if (!fast)
      continue;
    rastrules::Scene bare = *fast;
    bare.primitives.clear();
    RC_ASSERT(io::same_scene(t->scene, bare));
    std::vector<float> xy;
    for (const rastrules::Primitive& p : fast->primitives) {
      RC_ASSERT(p.type == rastrules::PrimitiveType::kTriangle);
      for (const rastrules::FloatPoint& v : p.v)
        xy.insert(xy.end(), {v[0], v[1]});
    }
    RC_ASSERT(t->xy.size() == xy.size());
    for (std::size_t i = 0; i < xy.size(); ++i)
      RC_ASSERT(std::bit_cast<std::uint32_t>(t->xy[i]) == std::bit_cast<std::uint32_t>(xy[i]));
  }
  // stream_triangles_fast: the same scene and coordinates, handed over in chunks after the
  // head, wherever "primitives" is the last root key (the text ends with "]", whitespace, "}");
  // it declines wherever read_scene_fast does or a key follows the list.
  struct Collect final : io::TriangleStream {
    std::optional<rastrules::Scene> head;
    std::vector<float> xy;
    bool begin(const rastrules::Scene& h) override {
      RC_ASSERT(!head.has_value());
      head = h;
      return true;
    }
    bool triangles(std::span<const float> chunk) override {
      RC_ASSERT(head.has_value());
      RC_ASSERT(!chunk.empty() && chunk.size() % 6 == 0);
      RC_ASSERT(chunk.size() <= 6 * io::kTriangleStreamChunk);
      xy.insert(xy.end(), chunk.begin(), chunk.end());
      return true;
    }
  } collect;
  const std::optional<rastrules::Scene> streamed = io::stream_triangles_fast(text, collect);
  std::size_t end = text.find_last_not_of(" \t\r\n");
  const bool list_last = end != std::string::npos && text[end] == '}' && end > 0 &&
                         (end = text.find_last_not_of(" \t\r\n", end - 1)) != std::string::npos &&
                         text[end] == ']';
  RC_CLASSIFY(streamed.has_value(), "streamed");
  RC_ASSERT(streamed.has_value() == (fast.has_value() && list_last));
  if (!streamed)
    return;
  rastrules::Scene bare = *fast;
  bare.primitives.clear();
  RC_ASSERT(io::same_scene(*streamed, bare));
  RC_ASSERT(io::same_scene(*collect.head, bare));
  RC_ASSERT(collect.xy.size() == 6 * fast->primitives.size());
  for (std::size_t i = 0; i < collect.xy.size(); ++i) {
    const rastrules::FloatPoint& v = fast->primitives[i / 6].v[(i % 6) / 2];
    RC_ASSERT(std::bit_cast<std::uint32_t>(collect.xy[i]) ==
              std::bit_cast<std::uint32_t>(v[i % 2]));
  }
}

// rule: SCENE.INPUT.FAST_READER, SCENE.NUMBER.FLOAT32
RC_GTEST_PROP(FastSceneReader, ReadsTheSceneTheGeneralReaderReads, ()) {
  const Written w = *scene_text();
  const std::optional<rastrules::Scene> fast = io::read_scene_fast(w.text);
  const auto general = io::read_scene_general(w.text);
  RC_CLASSIFY(fast.has_value(), "fast path taken");
  RC_CLASSIFY(w.text.find(R"({"type":"triangle","v":[[)") != std::string::npos,
              "compact triangles");
  if (w.expect_fast)
    RC_ASSERT(fast.has_value());
  if (fast) {
    RC_ASSERT(std::holds_alternative<rastrules::Scene>(general));
    RC_ASSERT(io::same_scene(*fast, std::get<rastrules::Scene>(general)));
  }
  check_triangles_agree(w.text, fast);
  // read_scene is the fast path when it is taken, the general reader otherwise.
  const auto both = io::read_scene(w.text);
  RC_ASSERT(both.index() == general.index());
  if (const auto* s = std::get_if<rastrules::Scene>(&both))
    RC_ASSERT(io::same_scene(*s, std::get<rastrules::Scene>(general)));
}

// rule: SCENE.INPUT.FAST_READER, SCENE.INPUT.ERRORS
// One character inserted, deleted or replaced anywhere: the fast path either declines or reads
// what the general reader reads, and read_scene's errors are the general reader's.
RC_GTEST_PROP(FastSceneReader, NearMissesAreLeftToTheGeneralReaderOrReadAlike, ()) {
  std::string text = (*scene_text()).text;
  RC_PRE(!text.empty());
  const auto at = *rc::gen::inRange<std::size_t>(0, text.size());
  const char c = *rc::gen::element('0', '9', '-', '.', 'e', '"', ',', '[', ']', '{', '}', ':', ' ',
                                   'x', '\\', '\0', '+', 'E');
  switch (*rc::gen::inRange(0, 3)) {
  case 0:
    text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c);
    break;
  case 1:
    text.erase(at, 1);
    break;
  default:
    text[at] = c;
    break;
  }
  const std::optional<rastrules::Scene> fast = io::read_scene_fast(text);
  const auto general = io::read_scene_general(text);
  RC_CLASSIFY(fast.has_value(), "fast path taken");
  RC_CLASSIFY(std::holds_alternative<rastrules::SceneError>(general), "an error");
  if (fast) {
    RC_ASSERT(std::holds_alternative<rastrules::Scene>(general));
    RC_ASSERT(io::same_scene(*fast, std::get<rastrules::Scene>(general)));
  }
  check_triangles_agree(text, fast);
  const auto both = io::read_scene(text);
  RC_ASSERT(both.index() == general.index());
  if (const auto* e = std::get_if<rastrules::SceneError>(&both))
    RC_ASSERT(e->what() == std::get<rastrules::SceneError>(general).what());
}

// rule: SCENE.INPUT.FAST_READER, SCENE.NUMBER.FLOAT32
// Short decimals (at most 8 digits, up to 12 after the point, near 2^24 and near ties of
// float32 rounding): the fast reader, which divides two exact float32 values where the digits
// allow it (Clinger's fast path), reads every one as the general reader and std::from_chars do,
// bit for bit.
RC_GTEST_PROP(FastSceneReader, ShortDecimalsReadAsTheGeneralReaderReadsThem, ()) {
  const std::uint32_t m =
      *rc::gen::oneOf(rc::gen::inRange<std::uint32_t>(0, 100000000),
                      rc::gen::inRange<std::uint32_t>((1u << 24) - 64, (1u << 24) + 64),
                      rc::gen::map(rc::gen::inRange<std::uint32_t>(0, 1u << 20),
                                   [](std::uint32_t v) { return 16 * v + 8; })); // halves of 16ths
  const int after = *rc::gen::inRange(1, 13);
  std::string digits = std::to_string(m);
  if (static_cast<int>(digits.size()) <= after)
    digits.insert(0, static_cast<std::size_t>(after) + 1 - digits.size(), '0');
  digits.insert(digits.size() - static_cast<std::size_t>(after), ".");
  if (*rc::gen::arbitrary<bool>())
    digits.insert(0, "-");
  RC_TAG(digits.size() - (digits.front() == '-' ? 2 : 1) <= 8 && after <= 10 && m <= (1u << 24)
             ? "the fast path's form"
             : "left to from_chars");
  // Spaced, or compact with room after it (the compact reader's one pass, compact_vertices).
  const bool compact = *rc::gen::arbitrary<bool>();
  const std::string text =
      compact ? R"({"target":{"width":4,"height":4},"primitives":[{"type":"triangle","v":[[)" +
                    digits + R"(,1],[2,1],[1,3]]})" + std::string(150, ' ') + "]}"
              : "{\"target\": {\"width\": 4, \"height\": 4}, \"primitives\": "
                "[{\"type\": \"triangle\", \"v\": [[" +
                    digits + ", 1], [2, 1], [1, 3]]}]}";
  const std::optional<rastrules::Scene> fast = io::read_scene_fast(text);
  RC_ASSERT(fast.has_value());
  const auto general = io::read_scene_general(text);
  RC_ASSERT(std::holds_alternative<rastrules::Scene>(general));
  const float got = fast->primitives.at(0).v[0][0];
  float want = 0.0f;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), want);
  RC_ASSERT(r.ec == std::errc{});
  RC_LOG() << digits << ": fast " << got << ", from_chars " << want << "\n";
  RC_ASSERT(std::bit_cast<std::uint32_t>(got) == std::bit_cast<std::uint32_t>(want));
  RC_ASSERT(io::same_scene(*fast, std::get<rastrules::Scene>(general)));
}

} // namespace
