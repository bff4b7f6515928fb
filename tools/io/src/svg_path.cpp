// SPDX-License-Identifier: MIT
// SVG path data reader (spec/scene.md SCENE.PATH.DATA).
// Implements: SCENE.PATH.DATA

#include "rastrules/io/svg_path.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "rastrules/io/scene_json.hpp"

namespace rastrules::io {

std::string SvgPathError::what() const {
  return "at character " + std::to_string(at) + ": " + problem;
}

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Thrown inside the reader; caught by parse_svg_path.
struct Stop {
  SvgPathError error;
};

class Reader {
public:
  Reader(std::string_view d, std::size_t max_pieces) : d_(d), max_pieces_(max_pieces) {}

  std::vector<SvgContour> read() {
    skip_space();
    if (at_end())
      return std::move(contours_);
    if (d_[i_] != 'M' && d_[i_] != 'm')
      fail("path data must begin with a move ('M' or 'm'), not " + shown(d_[i_]));
    while (!at_end()) {
      const char c = d_[i_];
      if (!is_command(c)) {
        if (c == 'A' || c == 'a')
          fail("arcs ('" + std::string(1, c) + "') are not supported; write them as cubic curves");
        fail("expected a command letter, not " + shown(c));
      }
      ++i_;
      command(c);
      skip_space();
    }
    return std::move(contours_);
  }

private:
  static bool is_command(char c) {
    switch (c) {
    case 'M':
    case 'm':
    case 'L':
    case 'l':
    case 'H':
    case 'h':
    case 'V':
    case 'v':
    case 'Q':
    case 'q':
    case 'T':
    case 't':
    case 'C':
    case 'c':
    case 'S':
    case 's':
    case 'Z':
    case 'z':
      return true;
    default:
      return false;
    }
  }

  static std::string shown(char c) { return "'" + printable(std::string_view(&c, 1)) + "'"; }

  [[noreturn]] void fail(std::string problem) const {
    throw Stop{SvgPathError{i_, std::move(problem)}};
  }

  [[nodiscard]] bool at_end() const { return i_ >= d_.size(); }

  void skip_space() {
    while (!at_end() && is_space(d_[i_]))
      ++i_;
  }
  // Whitespace with at most one comma among it.
  void skip_separator() {
    skip_space();
    if (!at_end() && d_[i_] == ',') {
      ++i_;
      skip_space();
    }
  }
  // Whether a number starts here (after separators).
  bool number_follows() {
    skip_separator();
    if (at_end())
      return false;
    const char c = d_[i_];
    return is_digit(c) || c == '+' || c == '-' || c == '.';
  }

  // An SVG number: sign? (digits ('.' digits?)? | '.' digits) (('e'|'E') sign? digits)?.
  float number(char cmd) {
    skip_separator();
    const std::size_t start = i_;
    std::string text; // JSON number syntax for decimal_to_float32
    if (!at_end() && (d_[i_] == '+' || d_[i_] == '-')) {
      if (d_[i_] == '-')
        text += '-';
      ++i_;
    }
    std::string whole, fraction;
    while (!at_end() && is_digit(d_[i_]))
      whole += d_[i_++];
    if (!at_end() && d_[i_] == '.') {
      ++i_;
      while (!at_end() && is_digit(d_[i_]))
        fraction += d_[i_++];
    }
    if (whole.empty() && fraction.empty()) {
      i_ = start;
      fail(std::string("expected a number after '") + cmd + "'" +
           (at_end() ? ", found the end" : ", found " + shown(d_[i_])));
    }
    text += whole.empty() ? "0" : whole;
    if (!fraction.empty())
      text += "." + fraction;
    if (!at_end() && (d_[i_] == 'e' || d_[i_] == 'E')) {
      std::size_t j = i_ + 1;
      std::string exponent = "e";
      if (j < d_.size() && (d_[j] == '+' || d_[j] == '-'))
        exponent += d_[j++];
      if (j < d_.size() && is_digit(d_[j])) {
        while (j < d_.size() && is_digit(d_[j]))
          exponent += d_[j++];
        text += exponent;
        i_ = j;
      }
    }
    const std::optional<float> v = decimal_to_float32(text);
    if (!v || !std::isfinite(*v)) {
      const std::size_t end = i_;
      i_ = start;
      fail("the number " + printable(d_.substr(start, end - start)) +
           " is beyond float32 (SCENE.NUMBER.FLOAT32)");
    }
    return *v;
  }

  SvgPoint point(char cmd, bool relative) {
    const std::size_t at = (skip_separator(), i_);
    const float x = number(cmd);
    const float y = number(cmd);
    return finite_point(relative ? cur_.x + x : x, relative ? cur_.y + y : y, at);
  }

  SvgPoint finite_point(float x, float y, std::size_t at) const {
    if (!std::isfinite(x) || !std::isfinite(y)) {
      throw Stop{SvgPathError{at, "the point is beyond float32 (a relative coordinate added to "
                                  "the current point overflowed)"}};
    }
    return SvgPoint{x, y, at};
  }

  // One more contour or segment.
  void count_piece() {
    if (++pieces_ > max_pieces_) {
      i_ = piece_at_;
      fail("the path has more than " + std::to_string(max_pieces_) +
           " segments and moves (SCENE.INPUT.LIMITS)");
    }
  }

  void move_to(SvgPoint p) { // by value: p may be a contour's start, and contours_ grows
    count_piece();
    contours_.push_back(SvgContour{p, {}});
    cur_ = p;
    open_ = true;
  }
  // Before a drawing command: after "Z" the next contour starts where the closed one did.
  void ensure_open() {
    if (!open_)
      move_to(contours_.back().start);
  }
  void add(SvgSegmentKind kind, std::array<SvgPoint, 3> p, std::size_t n) {
    count_piece();
    contours_.back().segments.push_back(SvgSegment{kind, p});
    cur_ = p[n - 1];
  }
  // 2 * current - previous, in float32 (2 * current is exact unless it overflows).
  SvgPoint reflect(const SvgPoint& prev) const {
    return finite_point(2.0f * cur_.x - prev.x, 2.0f * cur_.y - prev.y, cur_.at);
  }

  void command(char c) {
    const bool rel = c >= 'a' && c <= 'z';
    const char up = static_cast<char>(rel ? c - 'a' + 'A' : c);
    if (up == 'Z') {
      // rule: SCENE.PATH.DATA
      if (!contours_.empty())
        cur_ = contours_.back().start;
      open_ = false;
      last_ = 'Z';
      return;
    }
    bool first = true;
    piece_at_ = i_ - 1; // the command letter
    do {
      if (!first)
        piece_at_ = i_; // an implicit repetition: its first number
      switch (up) {
      case 'M':
        if (first) {
          move_to(point(c, rel && !contours_.empty()));
        } else { // further pairs are lines
          ensure_open();
          add(SvgSegmentKind::kLine, {point(c, rel)}, 1);
        }
        break;
      case 'L':
        ensure_open();
        add(SvgSegmentKind::kLine, {point(c, rel)}, 1);
        break;
      case 'H': {
        ensure_open();
        const std::size_t at = (skip_separator(), i_);
        const float x = number(c);
        add(SvgSegmentKind::kLine, {finite_point(rel ? cur_.x + x : x, cur_.y, at)}, 1);
        break;
      }
      case 'V': {
        ensure_open();
        const std::size_t at = (skip_separator(), i_);
        const float y = number(c);
        add(SvgSegmentKind::kLine, {finite_point(cur_.x, rel ? cur_.y + y : y, at)}, 1);
        break;
      }
      case 'Q':
      case 'T':
      case 'C':
      case 'S': {
        ensure_open();
        // T and S: the first control point reflected from the previous curve of their kind
        // (Q or T, C or S), else the current point.
        const bool cubic = up == 'C' || up == 'S';
        const bool after_same = cubic ? last_ == 'C' || last_ == 'S' : last_ == 'Q' || last_ == 'T';
        const std::size_t n = cubic ? 3 : 2;
        std::array<SvgPoint, 3> p{};
        p[0] = up == 'Q' || up == 'C' ? point(c, rel) : after_same ? reflect(ctrl_) : cur_;
        for (std::size_t k = 1; k < n; ++k)
          p[k] = point(c, rel);
        ctrl_ = p[n - 2];
        add(cubic ? SvgSegmentKind::kCubic : SvgSegmentKind::kQuadratic, p, n);
        break;
      }
      default:
        break;
      }
      last_ = up == 'M' && !first ? 'L' : up;
      first = false;
    } while (number_follows());
  }

  std::string_view d_;
  std::size_t max_pieces_;
  std::size_t i_ = 0;
  std::size_t pieces_ = 0;
  std::size_t piece_at_ = 0; // where the segment or move being read begins
  std::vector<SvgContour> contours_;
  SvgPoint cur_;
  SvgPoint ctrl_; // the last quadratic or second cubic control point
  char last_ = 0; // the last command, upper case ('L' for a move's implicit lines)
  bool open_ = false;
};

} // namespace

// rule: SCENE.PATH.DATA
std::variant<std::vector<SvgContour>, SvgPathError> parse_svg_path(std::string_view d,
                                                                   std::size_t max_segments) {
  try {
    return Reader(d, max_segments).read();
  } catch (const Stop& stop) {
    return stop.error;
  }
}

} // namespace rastrules::io
