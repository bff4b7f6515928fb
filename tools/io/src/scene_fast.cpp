// SPDX-License-Identifier: MIT
// The scene reader's fast path (SCENE.INPUT.FAST_READER): one pass over the common large scene,
// a target and a list of triangles given by "type" and "v" alone (with, optionally, the
// version and the window-space state: cull, front_face, fill, line_mode), building the
// primitives directly. Anything outside that form returns nullopt and the general reader decides
// (it also gives every error), so the fast path only ever accepts text the general reader reads to
// the same scene: numbers are converted by the same rules (SCENE.NUMBER.FLOAT32: integers rounded
// once, other numbers correctly rounded from their text), and the scene's other fields come
// from the general reader itself, reading the same target and keys with no primitives.
// Implements: SCENE.INPUT.FAST_READER

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <variant>

#include "rastrules/io/scene_json.hpp"

namespace rastrules::io {
namespace {

class FastScanner {
public:
  explicit FastScanner(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  void skip_ws() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t'))
      ++p_;
  }
  // Consumes c (after whitespace); false when the next character is another.
  bool eat(char c) {
    skip_ws();
    if (p_ < end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }
  [[nodiscard]] bool at_end() {
    skip_ws();
    return p_ == end_;
  }
  // A string without escapes or control characters; nullopt otherwise.
  std::optional<std::string_view> plain_string() {
    if (!eat('"'))
      return std::nullopt;
    const char* start = p_;
    while (p_ < end_ && *p_ != '"') {
      const auto c = static_cast<unsigned char>(*p_);
      if (c == '\\' || c < 0x20)
        return std::nullopt;
      ++p_;
    }
    if (p_ == end_)
      return std::nullopt;
    const std::string_view s(start, static_cast<std::size_t>(p_ - start));
    ++p_;
    return s;
  }
  // Consumes the exact bytes lit when the text goes on with them; false, consuming nothing,
  // otherwise.
  bool literal(std::string_view lit) {
    if (static_cast<std::size_t>(end_ - p_) < lit.size() ||
        std::memcmp(p_, lit.data(), lit.size()) != 0)
      return false;
    p_ += lit.size();
    return true;
  }
  // A JSON integer token of 1 to 18 digits (an int64 holds it), consumed and its value
  // returned; nullopt, consuming nothing but whitespace, for any other token (a fraction, an
  // exponent, more digits, a leading zero: the caller then reads it with number()).
  std::optional<std::int64_t> short_integer() {
    skip_ws();
    const char* q = p_;
    const bool negative = q < end_ && *q == '-';
    if (negative)
      ++q;
    const char* first = q;
    std::int64_t v = 0;
    while (q < end_ && q - first < 18 && *q >= '0' && *q <= '9') {
      v = 10 * v + (*q - '0');
      ++q;
    }
    if (q == first || (q - first > 1 && *first == '0'))
      return std::nullopt;
    if (q < end_ && ((*q >= '0' && *q <= '9') || *q == '.' || *q == 'e' || *q == 'E'))
      return std::nullopt;
    p_ = q;
    return negative ? -v : v;
  }
  // A JSON number token: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?. integral: no fraction
  // or exponent.
  std::optional<std::string_view> number(bool& integral) {
    skip_ws();
    const char* start = p_;
    if (p_ < end_ && *p_ == '-')
      ++p_;
    if (p_ == end_)
      return std::nullopt;
    if (*p_ == '0') {
      ++p_;
    } else if (*p_ >= '1' && *p_ <= '9') {
      while (p_ < end_ && *p_ >= '0' && *p_ <= '9')
        ++p_;
    } else {
      return std::nullopt;
    }
    integral = true;
    if (p_ < end_ && *p_ == '.') {
      integral = false;
      ++p_;
      if (!digits())
        return std::nullopt;
    }
    if (p_ < end_ && (*p_ == 'e' || *p_ == 'E')) {
      integral = false;
      ++p_;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-'))
        ++p_;
      if (!digits())
        return std::nullopt;
    }
    return std::string_view(start, static_cast<std::size_t>(p_ - start));
  }

private:
  bool digits() {
    const char* start = p_;
    while (p_ < end_ && *p_ >= '0' && *p_ <= '9')
      ++p_;
    return p_ > start;
  }

  const char* p_;
  const char* end_;
};

// rule: SCENE.NUMBER.FLOAT32
// Reads a coordinate into out as the general reader converts it; false where the fast path
// leaves the number to it (a bool and an out-parameter: an optional<float> returned through
// two stack stores and one load stalled store forwarding, a quarter of the parse): integers of at
// most 18 digits (an int64 holds them) rounded once to float32; other numbers correctly rounded
// from their text, when that is a finite float32 reached without range error (the general reader's
// decimal_to_float32 gives the same).
bool coordinate(FastScanner& s, float& out) {
  if (const std::optional<std::int64_t> v = s.short_integer()) {
    out = static_cast<float>(*v);
    return true;
  }
  // An integer short_integer() did not take has more than 18 digits or a leading zero (then
  // the JSON number is the "0" alone, and the digit after it no separator): the general
  // reader decides.
  bool integral = false;
  const std::optional<std::string_view> t = s.number(integral);
  if (!t || integral)
    return false;
  float f = 0.0f;
  const auto r = std::from_chars(t->data(), t->data() + t->size(), f, std::chars_format::general);
  if (r.ec != std::errc{} || r.ptr != t->data() + t->size() || !(f - f == 0.0f))
    return false;
  out = f;
  return true;
}

// An int32 written as a JSON integer of at most 9 digits.
std::optional<std::int32_t> small_int(FastScanner& s) {
  bool integral = false;
  const std::optional<std::string_view> t = s.number(integral);
  if (!t || !integral || t->size() - (t->front() == '-' ? 1 : 0) > 9)
    return std::nullopt;
  std::int32_t v = 0;
  const auto r = std::from_chars(t->data(), t->data() + t->size(), v);
  if (r.ec != std::errc{} || r.ptr != t->data() + t->size())
    return std::nullopt;
  return v;
}

// An object of exactly two keys: value(key) reads each key's value, false to decline (a key it
// does not take, or takes once and sees again).
template <class Value> bool two_key_object(FastScanner& s, Value&& value) {
  if (!s.eat('{'))
    return false;
  for (int k = 0; k < 2; ++k) {
    if (k > 0 && !s.eat(','))
      return false;
    const auto key = s.plain_string();
    if (!key || !s.eat(':') || !value(*key))
      return false;
  }
  return s.eat('}');
}

// An object of one or more keys: value(key) reads each key's value, false to decline.
template <class Value> bool object_of_keys(FastScanner& s, Value&& value) {
  if (!s.eat('{'))
    return false;
  do {
    const auto key = s.plain_string();
    if (!key || !s.eat(':') || !value(*key))
      return false;
  } while (s.eat(','));
  return s.eat('}');
}

// The root keys besides "target" and "primitives" that the fast form takes: the general reader
// reads each from the head text (and names a bad value); none of them changes how a triangle
// is read, and the state they set (TRI.CULL.MODE, TRI.FILL.CONVENTION) is the prepared scene's.
constexpr std::array<std::string_view, 4> kStateKeys = {"cull", "front_face", "fill", "line_mode"};

// {"width": W, "height": H} in either order.
bool target(FastScanner& s, std::int32_t& width, std::int32_t& height) {
  bool have_w = false, have_h = false;
  return two_key_object(s, [&](std::string_view key) {
    const bool is_w = key == "width";
    if ((!is_w && key != "height") || (is_w ? have_w : have_h))
      return false;
    const std::optional<std::int32_t> v = small_int(s);
    if (!v)
      return false;
    (is_w ? width : height) = *v;
    (is_w ? have_w : have_h) = true;
    return true;
  });
}

// [[x, y], [x, y], [x, y]] into xy (x0 y0 x1 y1 x2 y2).
bool vertices(FastScanner& s, std::array<float, 6>& xy) {
  if (!s.eat('['))
    return false;
  for (std::size_t i = 0; i < 3; ++i) {
    if ((i > 0 && !s.eat(',')) || !s.eat('['))
      return false;
    if (!coordinate(s, xy[2 * i]) || !s.eat(',') || !coordinate(s, xy[2 * i + 1]) || !s.eat(']'))
      return false;
  }
  return s.eat(']');
}

// {"type": "triangle", "v": [[x, y], [x, y], [x, y]]} in either key order.
bool triangle(FastScanner& s, std::array<float, 6>& xy) {
  // The spelling without whitespace, which generated scenes use, is matched at once: the same
  // tokens the object's general form below reads.
  s.skip_ws();
  if (s.literal(R"({"type":"triangle","v":)"))
    return vertices(s, xy) && s.eat('}');
  bool have_type = false, have_v = false;
  return two_key_object(s, [&](std::string_view key) {
    if (key == "type" && !have_type) {
      const auto t = s.plain_string();
      return have_type = t && *t == "triangle";
    }
    if (key == "v" && !have_v)
      return have_v = vertices(s, xy);
    return false;
  });
}

// Scans the fast form: sink.reserve(n) once with a bound on the triangles the text can hold,
// then sink.add(xy) for each triangle in order. Returns the scene the general reader gives for
// the target with no primitives (every other field as it sets them), or nullopt where the fast
// path declines (the sink may then hold part of the list).
template <class Sink> std::optional<Scene> scan_fast(std::string_view json_text, Sink& sink) {
  FastScanner s(json_text);
  std::int32_t width = 0, height = 0;
  bool have_target = false, have_primitives = false;
  const auto list = [&] {
    if (!s.eat('['))
      return false;
    if (s.eat(']'))
      return true;
    // The shortest triangle takes 44 bytes ({"type":"triangle","v":[[0,0],[0,0],[0,0]]},): one
    // allocation holds them all (growing the list moved a million primitives about 20 times;
    // the pages of a list left unused, when the fast path declines, are never touched).
    sink.reserve(std::min(json_text.size() / 44 + 1, kMaxScenePrimitives));
    std::size_t n = 0;
    std::array<float, 6> xy{};
    do {
      if (n++ >= kMaxScenePrimitives)
        return false; // the general reader names the limit
      if (!triangle(s, xy))
        return false;
      sink.add(xy);
    } while (s.eat(','));
    return s.eat(']');
  };
  // The other keys' text, for the general reader: "version" (an integer) and kStateKeys (plain
  // strings), each once.
  std::string others;
  std::array<bool, kStateKeys.size() + 1> seen{};
  const auto other = [&](std::string_view key) {
    const auto at = std::find(kStateKeys.begin(), kStateKeys.end(), key);
    const auto k = static_cast<std::size_t>(at - kStateKeys.begin()); // size(): "version"
    if ((at == kStateKeys.end() && key != "version") || seen[k])
      return false;
    seen[k] = true;
    others += ", \"";
    others += key;
    others += "\": ";
    if (at == kStateKeys.end()) {
      const std::optional<std::int64_t> v = s.short_integer();
      if (!v)
        return false;
      others += std::to_string(*v);
      return true;
    }
    const std::optional<std::string_view> v = s.plain_string();
    if (!v)
      return false;
    others += '"';
    others += *v;
    others += '"';
    return true;
  };
  const bool ok = object_of_keys(s, [&](std::string_view key) {
    if (key == "target")
      return !have_target && (have_target = target(s, width, height));
    if (key == "primitives")
      return !have_primitives && (have_primitives = list());
    return other(key);
  });
  if (!ok || !have_target || !have_primitives || !s.at_end())
    return std::nullopt;
  const std::string head = "{\"target\": {\"width\": " + std::to_string(width) +
                           ", \"height\": " + std::to_string(height) + "}, \"primitives\": []" +
                           others + "}";
  auto base = read_scene_general(head);
  if (!std::holds_alternative<Scene>(base))
    return std::nullopt;
  return std::get<Scene>(std::move(base));
}

} // namespace

// rule: SCENE.INPUT.FAST_READER
std::optional<Scene> read_scene_fast(std::string_view json_text) {
  struct Primitives {
    std::vector<Primitive> list;
    void reserve(std::size_t n) { list.reserve(n); }
    void add(const std::array<float, 6>& xy) {
      Primitive& p = list.emplace_back();
      p.type = PrimitiveType::kTriangle;
      for (std::size_t i = 0; i < 3; ++i)
        p.v[i] = FloatPoint{xy[2 * i], xy[2 * i + 1]};
    }
  } sink;
  std::optional<Scene> scene = scan_fast(json_text, sink);
  if (scene)
    scene->primitives = std::move(sink.list);
  return scene;
}

// rule: SCENE.INPUT.FAST_READER
std::optional<FastTriangles> read_triangles_fast(std::string_view json_text) {
  struct Coordinates {
    std::vector<float> xy;
    void reserve(std::size_t n) { xy.reserve(6 * n); }
    void add(const std::array<float, 6>& t) { xy.insert(xy.end(), t.begin(), t.end()); }
  } sink;
  std::optional<Scene> scene = scan_fast(json_text, sink);
  if (!scene)
    return std::nullopt;
  return FastTriangles{std::move(*scene), std::move(sink.xy)};
}

} // namespace rastrules::io
