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
#include "rastrules/parallel.hpp"

namespace rastrules::io {
namespace {

class FastScanner {
public:
  explicit FastScanner(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}
  FastScanner(const char* at, const char* end) : p_(at), end_(end) {}
  [[nodiscard]] const char* at() const { return p_; }
  void seek(const char* at) { p_ = at; }

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
  // The start of a number token at p_ (after whitespace): an optional '-' and 1 to max_digits
  // digits without a leading zero (but "0" itself), their value and where they end; nullopt,
  // consuming nothing but whitespace, where no such start is there.
  struct Lead {
    const char* end;
    bool negative;
    std::int64_t value;
    int count;
  };
  std::optional<Lead> leading_digits(std::ptrdiff_t max_digits) {
    skip_ws();
    const char* q = p_;
    const bool negative = q < end_ && *q == '-';
    if (negative)
      ++q;
    const char* first = q;
    std::int64_t v = 0;
    q = digits_into(q, max_digits, v);
    const auto count = static_cast<int>(q - first);
    if (count == 0 || (count > 1 && *first == '0'))
      return std::nullopt;
    return Lead{q, negative, v, count};
  }
  // Whether the number token goes on at q (a digit beyond the limit, a point, an exponent): the
  // short readers leave such a token to the general one.
  bool number_goes_on(const char* q) const {
    return q < end_ && ((*q >= '0' && *q <= '9') || *q == '.' || *q == 'e' || *q == 'E');
  }
  // rule: SCENE.NUMBER.FLOAT32
  // A JSON number of at most 8 digits without exponent, in one pass: an integer (rounded to
  // float32 as short_integer's value is), or a decimal m / 10^k (k <= 7 digits after the point)
  // with m <= 2^24, which one float32 division of two exact values rounds correctly, to nearest
  // with ties to even (Clinger's fast path; 10^7 is exact in float32): the value
  // std::from_chars gives. Consumed with its
  // value in out; false, consuming nothing but whitespace, for any other token (more digits,
  // an exponent, a leading zero, not a number: the caller reads it the longer way). From
  // scanning each coordinate three times and converting it with from_chars, half of
  // `render --count`'s time on 10^6 triangles with one-decimal coordinates.
  bool short_real(float& out) {
    const std::optional<Lead> lead = leading_digits(8);
    if (!lead)
      return false;
    const char* q = lead->end;
    std::int64_t m = lead->value;
    int after = 0;
    if (q < end_ && *q == '.') {
      const char* frac = q + 1;
      q = digits_into(frac, 8 - lead->count, m);
      after = static_cast<int>(q - frac);
      if (after == 0)
        return false;
    }
    if (number_goes_on(q))
      return false;
    if (after == 0) {
      out = static_cast<float>(lead->negative ? -m : m);
    } else {
      static constexpr float kPow10[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f};
      if (m > (std::int64_t{1} << 24))
        return false;
      const float f = static_cast<float>(m) / kPow10[after];
      out = lead->negative ? -f : f;
    }
    p_ = q;
    return true;
  }
  // rule: SCENE.NUMBER.FLOAT32, SCENE.INPUT.FAST_READER
  // The rest of a triangle spelled without whitespace, [[x,y],[x,y],[x,y]]} (what generated
  // scenes write), where every coordinate is a number short_real takes: read into xy in one
  // pass with no bounds checks (at least kCompactRoom bytes must remain; the longest such text
  // is 74 bytes, each number at most 10 of them and read at most one byte past), the values
  // short_real gives. false, consuming nothing, for any other text (whitespace, longer numbers,
  // an exponent, less room): the caller reads it token by token, which accepts all that this
  // does. (The token reader's bounds and whitespace checks: 6 ms of `render --count`'s 102 on
  // 10^6 small triangles.)
  bool compact_vertices(float* xy) {
    if (end_ - p_ < kCompactRoom)
      return false;
    static constexpr char kAfter[6] = {',', ']', ',', ']', ',', ']'};
    const char* q = p_;
    if (q[0] != '[' || q[1] != '[')
      return false;
    q += 2;
    for (int k = 0; k < 6; ++k) {
      q = compact_number(q, xy[k]);
      if (q == nullptr || *q != kAfter[k])
        return false;
      ++q;
      if (k == 1 || k == 3) { // "],[" between vertices
        if (q[0] != ',' || q[1] != '[')
          return false;
        q += 2;
      }
    }
    if (q[0] != ']' || q[1] != '}')
      return false;
    p_ = q + 2;
    return true;
  }
  // A JSON integer token of 1 to 18 digits (an int64 holds it), consumed and its value
  // returned; nullopt, consuming nothing but whitespace, for any other token (a fraction, an
  // exponent, more digits, a leading zero: the caller then reads it with number()).
  std::optional<std::int64_t> short_integer() {
    const std::optional<Lead> lead = leading_digits(18);
    if (!lead || number_goes_on(lead->end))
      return std::nullopt;
    p_ = lead->end;
    return lead->negative ? -lead->value : lead->value;
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
  static constexpr std::ptrdiff_t kCompactRoom = 128;
  static bool is_digit(char c) { return static_cast<unsigned>(c - '0') < 10u; }
  // short_real's number at q, with at least 11 readable bytes: where its digits end (the
  // caller checks what follows), their value in out; nullptr where short_real would decline. (A
  // digit reader without a branch on the count, eight bytes at a time, was slower here: its chain
  // of dependent operations a number cost more than the loop's mispredicted exit.)
  static const char* compact_number(const char* q, float& out) {
    const bool negative = *q == '-';
    q += negative ? 1 : 0;
    const char* first = q;
    // At most 8 digits in all, so m < 10^8 fits 32 bits (a 64-bit m cost a sign extension a
    // digit, and the count test q - first < 8 two more instructions than a pointer test).
    const char* const last = first + 8;
    std::int32_t m = 0;
    while (q != last && is_digit(*q)) {
      m = 10 * m + (*q - '0');
      ++q;
    }
    const auto count = static_cast<int>(q - first);
    if (count == 0 || (count > 1 && *first == '0'))
      return nullptr;
    int after = 0;
    if (*q == '.') {
      const char* frac = ++q;
      const char* const frac_last = last + 1; // 8 - count digits after the point
      while (q != frac_last && is_digit(*q)) {
        m = 10 * m + (*q - '0');
        ++q;
      }
      after = static_cast<int>(q - frac);
      if (after == 0)
        return nullptr;
    }
    // A number that goes on here (a ninth digit, a point, an exponent) is declined by the
    // caller, which takes only its separator next. The value as short_real's (the same lines:
    // a helper shared by both measured 2 ms slower on `render --count` of 10^6 triangles; the
    // properties compare both readers with the general one).
    if (after == 0) {
      out = static_cast<float>(negative ? -m : m);
    } else {
      static constexpr float kPow10[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f};
      if (m > (std::int32_t{1} << 24))
        return nullptr;
      const float f = static_cast<float>(m) / kPow10[after];
      out = negative ? -f : f;
    }
    return q;
  }
  // Reads decimal digits from q into v (v = 10 v + digit), at most `limit` of them; returns
  // where it stopped.
  const char* digits_into(const char* q, std::ptrdiff_t limit, std::int64_t& v) const {
    const char* first = q;
    while (q < end_ && q - first < limit && *q >= '0' && *q <= '9') {
      v = 10 * v + (*q - '0');
      ++q;
    }
    return q;
  }
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
  if (s.short_real(out))
    return true;
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

// [[x, y], [x, y], [x, y]] into xy[0 .. 6) (x0 y0 x1 y1 x2 y2).
bool vertices(FastScanner& s, float* xy) {
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
// Read into xy[0 .. 6): the sink's own storage (scan_fast), since six floats stored one by one
// and copied at once as 16 and 8 bytes stalled on store forwarding (5 % of `render --fragments
// OUT.bin` of 10^6 small triangles).
bool triangle(FastScanner& s, float* xy) {
  // The spelling without whitespace, which generated scenes use, is matched at once: the same
  // tokens the object's general form below reads.
  s.skip_ws();
  if (s.literal(R"({"type":"triangle","v":)"))
    return s.compact_vertices(xy) || (vertices(s, xy) && s.eat('}'));
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

// The list read in parts by other threads. probe: the scan stops (nullopt) at the list's first
// triangle and sets `first` to where it starts (list context proved there). Otherwise, when the
// scan's next triangle starts at `from`, it takes the `count` triangles of the parts (ok false:
// a part failed, and the scan declines) and goes on after the list at `after`.
struct ListParts {
  bool probe = false;
  const char* first = nullptr;
  const char* from = nullptr;
  const char* after = nullptr;
  std::size_t count = 0;
  bool ok = false;
};

// A sink that takes the triangles as they are read (stream_triangles_fast): begin(head) first.
template <class Sink> constexpr bool kStreams = requires(Sink& sink, const Scene& head) {
  sink.begin(head);
};

// The end of the list for the sink: its finish() where it has one.
template <class Sink> bool finish(Sink& sink) {
  if constexpr (requires { sink.finish(); })
    return sink.finish();
  else
    return true;
}

// Scans the fast form: for a streaming sink (kStreams) sink.begin(head) with the scene of the
// keys before the list, then sink.reserve(n) once with a bound on the triangles the text can
// hold, then for each triangle in order sink.slot() (six floats it is read into) and
// sink.add() (false declines), then finish(sink). Returns
// the scene the general reader gives for the target with no primitives (every other field as it
// sets them), or nullopt where the fast path declines (the sink may then hold part of the list).
// With parts, as ListParts says.
template <class Sink>
std::optional<Scene> scan_fast(std::string_view json_text, Sink& sink, ListParts* parts = nullptr) {
  FastScanner s(json_text);
  std::int32_t width = 0, height = 0;
  bool have_target = false, have_primitives = false;
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
  // The scene the general reader gives for the keys read so far and no primitives.
  const auto head_scene = [&]() -> std::optional<Scene> {
    if (!have_target)
      return std::nullopt;
    const std::string head = "{\"target\": {\"width\": " + std::to_string(width) +
                             ", \"height\": " + std::to_string(height) + "}, \"primitives\": []" +
                             others + "}";
    auto base = read_scene_general(head);
    if (!std::holds_alternative<Scene>(base))
      return std::nullopt;
    return std::get<Scene>(std::move(base));
  };
  const auto list = [&] {
    if (!s.eat('['))
      return false;
    // A streaming sink starts with the keys read so far (all of them: none may follow).
    if constexpr (kStreams<Sink>) {
      const std::optional<Scene> head = head_scene();
      if (!head || !sink.begin(*head))
        return false;
    }
    if (s.eat(']'))
      return finish(sink);
    // The shortest triangle takes 44 bytes ({"type":"triangle","v":[[0,0],[0,0],[0,0]]},): one
    // allocation holds them all (growing the list moved a million primitives about 20 times;
    // the pages of a list left unused, when the fast path declines, are never touched).
    sink.reserve(std::min(json_text.size() / 44 + 1, kMaxScenePrimitives));
    std::size_t n = 0;
    do {
      if (parts != nullptr) {
        s.skip_ws();
        if (parts->probe) {
          parts->first = s.at();
          return false;
        }
        if (s.at() == parts->from) { // the next triangle is the parts' first
          if (!parts->ok || parts->count > kMaxScenePrimitives - n)
            return false;
          s.seek(parts->after);
          return true;
        }
      }
      if (n++ >= kMaxScenePrimitives)
        return false; // the general reader names the limit
      if (!triangle(s, sink.slot()) || !sink.add())
        return false;
    } while (s.eat(','));
    return parts == nullptr && s.eat(']') && finish(sink);
  };
  const bool ok = object_of_keys(s, [&](std::string_view key) {
    if (have_primitives && kStreams<Sink>)
      return false; // a key after the list: a streaming sink has begun without it
    if (key == "target")
      return !have_target && (have_target = target(s, width, height));
    if (key == "primitives")
      return !have_primitives && (have_primitives = list());
    return other(key);
  });
  if (!ok || !have_target || !have_primitives || !s.at_end())
    return std::nullopt;
  return head_scene();
}

} // namespace

// rule: SCENE.INPUT.FAST_READER
std::optional<Scene> read_scene_fast(std::string_view json_text) {
  struct Primitives {
    std::vector<Primitive> list;
    std::array<float, 6> xy{};
    void reserve(std::size_t n) { list.reserve(n); }
    float* slot() { return xy.data(); }
    bool add() {
      Primitive& p = list.emplace_back();
      p.type = PrimitiveType::kTriangle;
      for (std::size_t i = 0; i < 3; ++i)
        p.v[i] = FloatPoint{xy[2 * i], xy[2 * i + 1]};
      return true;
    }
  } sink;
  std::optional<Scene> scene = scan_fast(json_text, sink);
  if (scene)
    scene->primitives = std::move(sink.list);
  return scene;
}

namespace {

// The coordinates scan_fast reads, six floats a triangle.
struct Coordinates {
  std::vector<float> xy;
  void reserve(std::size_t n) { xy.reserve(6 * n); }
  // Six floats at the end (a triangle that fails leaves them: the scan then declines).
  float* slot() {
    xy.resize(xy.size() + 6);
    return xy.data() + xy.size() - 6;
  }
  bool add() { return true; }
};

// Where the part of the list that starts at or after `at` begins: the '{' of a triangle after
// "}", "," (whitespace around the comma); nullptr when there is none. In the fast form "},"
// followed by "{" occurs only between two triangles of the list (strings hold no braces, the
// target's object is followed by a key); a wrong guess only makes the parts fail to join.
const char* part_start(const char* at, const char* end) {
  for (const char* p = at; p < end; ++p) {
    p = static_cast<const char*>(std::memchr(p, '}', static_cast<std::size_t>(end - p)));
    if (p == nullptr)
      return nullptr;
    FastScanner s(p + 1, end);
    if (s.eat(',')) {
      s.skip_ws();
      if (s.at() < end && *s.at() == '{')
        return s.at();
    }
  }
  return nullptr;
}

// One part of the list read on its own: triangles from `from` (a '{'), separated by commas,
// until the next would start at `until` (nullptr: until the list's ']'). end: where the scan
// stopped (`until`, or just after the ']').
struct ListPart {
  std::vector<float> xy;
  const char* end = nullptr;
  bool ok = false;
};

ListPart read_part(const char* from, const char* until, const char* text_end) {
  ListPart part;
  FastScanner s(from, text_end);
  // At least 44 bytes a triangle, comma included (scan_fast's bound).
  part.xy.reserve(6 * (static_cast<std::size_t>((until ? until : text_end) - from) / 44 + 1));
  for (;;) {
    if (part.xy.size() / 6 >= kMaxScenePrimitives)
      return part;
    part.xy.resize(part.xy.size() + 6);
    if (!triangle(s, part.xy.data() + part.xy.size() - 6)) {
      part.xy.resize(part.xy.size() - 6);
      return part;
    }
    if (!s.eat(',')) {
      part.ok = until == nullptr && s.eat(']');
      part.end = s.at();
      return part;
    }
    s.skip_ws();
    if (s.at() == until) {
      part.ok = true;
      part.end = until;
      return part;
    }
  }
}

} // namespace

// rule: SCENE.INPUT.FAST_READER, FAST.THREADS.DETERMINISTIC
std::optional<FastTriangles> read_triangles_fast(std::string_view json_text, unsigned threads,
                                                 std::size_t min_part_bytes) {
  const std::size_t parts_wanted =
      std::min<std::size_t>(std::clamp(threads, 1U, kMaxThreads),
                            json_text.size() / std::max<std::size_t>(min_part_bytes, 1));
  if (parts_wanted < 2)
    return read_triangles_fast(json_text);
  Coordinates none; // the scans below read the keys alone
  // Where the list's first triangle starts (the keys before the list are read, then the scan
  // stops); a scene without triangles, or a text not of the form, is read on one thread.
  ListParts parts;
  parts.probe = true;
  if (scan_fast(json_text, none, &parts) || parts.first == nullptr)
    return read_triangles_fast(json_text);
  const char* end = json_text.data() + json_text.size();
  // Part 0 starts at the first triangle, part k at the first triangle after k / parts_wanted of
  // the text.
  std::vector<const char*> starts = {parts.first};
  for (std::size_t k = 1; k < parts_wanted; ++k) {
    const char* p = part_start(json_text.data() + json_text.size() * k / parts_wanted, end);
    if (p != nullptr && p > starts.back())
      starts.push_back(p);
  }
  std::vector<ListPart> read(starts.size());
  run_units(starts.size(), threads, [&](std::size_t k) {
    read[k] = read_part(starts[k], k + 1 < starts.size() ? starts[k + 1] : nullptr, end);
  });
  parts.probe = false;
  parts.from = parts.first;
  parts.ok = true;
  for (const ListPart& part : read) {
    parts.ok = parts.ok && part.ok;
    parts.count += part.xy.size() / 6;
  }
  parts.after = read.back().end;
  // The keys after the list, and the scene.
  std::optional<Scene> scene = scan_fast(json_text, none, &parts);
  if (!scene) {
    if (parts.ok)
      return std::nullopt;                 // the parts joined: the text is not of the form
    return read_triangles_fast(json_text); // a part guessed wrong: read on one thread
  }
  std::vector<float> xy;
  xy.reserve(6 * parts.count);
  for (ListPart& part : read) {
    xy.insert(xy.end(), part.xy.begin(), part.xy.end());
    std::vector<float>().swap(part.xy);
  }
  return FastTriangles{std::move(*scene), std::move(xy)};
}

// rule: SCENE.INPUT.FAST_READER
std::optional<Scene> stream_triangles_fast(std::string_view json_text, TriangleStream& stream) {
  struct Chunks {
    TriangleStream& stream;
    std::vector<float> xy = std::vector<float>(6 * kTriangleStreamChunk);
    std::size_t n = 0; // floats held
    bool begin(const Scene& head) { return stream.begin(head); }
    void reserve(std::size_t triangles) { stream.reserve(triangles); }
    float* slot() { return xy.data() + n; }
    bool add() {
      n += 6;
      return n < xy.size() || finish();
    }
    bool finish() {
      const bool ok = n == 0 || stream.triangles(std::span<const float>(xy).first(n));
      n = 0;
      return ok;
    }
  } sink{stream};
  return scan_fast(json_text, sink);
}

// rule: SCENE.INPUT.FAST_READER
std::optional<FastTriangles> read_triangles_fast(std::string_view json_text) {
  Coordinates sink;
  std::optional<Scene> scene = scan_fast(json_text, sink);
  if (!scene)
    return std::nullopt;
  return FastTriangles{std::move(*scene), std::move(sink.xy)};
}

} // namespace rastrules::io
