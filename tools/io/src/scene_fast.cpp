// SPDX-License-Identifier: MIT
// The scene reader's fast path (SCENE.INPUT.FAST_READER): one pass over the common large scene,
// a target and a list of triangles given by "type" and "v" alone, building the primitives
// directly. Anything outside that form returns nullopt and the general reader decides (it also
// gives every error), so the fast path only ever accepts text the general reader reads to the
// same scene: numbers are converted by the same rules (SCENE.NUMBER.FLOAT32: integers rounded
// once, other numbers correctly rounded from their text), and the scene's other fields come
// from the general reader itself, reading the same target with no primitives.
// Implements: SCENE.INPUT.FAST_READER

#include <algorithm>
#include <charconv>
#include <cstdint>
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
// A coordinate as the general reader converts it, or nullopt where the fast path leaves the
// number to it: integers of at most 18 digits (an int64 holds them) rounded once to float32;
// other numbers correctly rounded from their text, when that is a finite float32 reached
// without range error (the general reader's decimal_to_float32 gives the same).
std::optional<float> coordinate(FastScanner& s) {
  bool integral = false;
  const std::optional<std::string_view> t = s.number(integral);
  if (!t)
    return std::nullopt;
  if (integral) {
    const std::size_t digits = t->size() - (t->front() == '-' ? 1 : 0);
    if (digits > 18)
      return std::nullopt;
    std::int64_t v = 0;
    const auto r = std::from_chars(t->data(), t->data() + t->size(), v);
    if (r.ec != std::errc{} || r.ptr != t->data() + t->size())
      return std::nullopt;
    return static_cast<float>(v);
  }
  float f = 0.0f;
  const auto r = std::from_chars(t->data(), t->data() + t->size(), f, std::chars_format::general);
  if (r.ec != std::errc{} || r.ptr != t->data() + t->size() || !(f - f == 0.0f))
    return std::nullopt;
  return f;
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

// [[x, y], [x, y], [x, y]] into out.v.
bool vertices(FastScanner& s, Primitive& out) {
  if (!s.eat('['))
    return false;
  for (std::size_t i = 0; i < 3; ++i) {
    if ((i > 0 && !s.eat(',')) || !s.eat('['))
      return false;
    const std::optional<float> x = coordinate(s);
    if (!x || !s.eat(','))
      return false;
    const std::optional<float> y = coordinate(s);
    if (!y || !s.eat(']'))
      return false;
    out.v[i] = FloatPoint{*x, *y};
  }
  return s.eat(']');
}

// {"type": "triangle", "v": [[x, y], [x, y], [x, y]]} in either key order.
bool triangle(FastScanner& s, Primitive& out) {
  bool have_type = false, have_v = false;
  return two_key_object(s, [&](std::string_view key) {
    if (key == "type" && !have_type) {
      const auto t = s.plain_string();
      return have_type = t && *t == "triangle";
    }
    if (key == "v" && !have_v)
      return have_v = vertices(s, out);
    return false;
  });
}

} // namespace

// rule: SCENE.INPUT.FAST_READER
std::optional<Scene> read_scene_fast(std::string_view json_text) {
  FastScanner s(json_text);
  std::int32_t width = 0, height = 0;
  bool have_target = false, have_primitives = false;
  std::vector<Primitive> primitives;
  const auto list = [&] {
    if (!s.eat('['))
      return false;
    if (s.eat(']'))
      return true;
    // The shortest triangle takes 44 bytes ({"type":"triangle","v":[[0,0],[0,0],[0,0]]},): one
    // allocation holds them all (growing the list moved a million primitives about 20 times;
    // the pages of a list left unused, when the fast path declines, are never touched).
    primitives.reserve(std::min(json_text.size() / 44 + 1, kMaxScenePrimitives));
    do {
      if (primitives.size() >= kMaxScenePrimitives)
        return false; // the general reader names the limit
      Primitive& p = primitives.emplace_back();
      p.type = PrimitiveType::kTriangle;
      if (!triangle(s, p))
        return false;
    } while (s.eat(','));
    return s.eat(']');
  };
  const bool ok = two_key_object(s, [&](std::string_view key) {
    if (key == "target" && !have_target)
      return have_target = target(s, width, height);
    if (key == "primitives" && !have_primitives)
      return have_primitives = list();
    return false;
  });
  if (!ok || !s.at_end())
    return std::nullopt;
  // Every other field as the general reader sets it for this target and no primitives.
  const std::string head = "{\"target\": {\"width\": " + std::to_string(width) +
                           ", \"height\": " + std::to_string(height) + "}, \"primitives\": []}";
  auto base = read_scene_general(head);
  if (!std::holds_alternative<Scene>(base))
    return std::nullopt;
  Scene scene = std::get<Scene>(std::move(base));
  scene.primitives = std::move(primitives);
  return scene;
}

} // namespace rastrules::io
