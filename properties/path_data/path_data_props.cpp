// SPDX-License-Identifier: MIT
// Properties of the SVG path data reader: random contours written as path data in every legal
// spelling (absolute or relative, separators or none where the grammar allows, commands
// repeated implicitly, closed or not) read back to the points a float32 model computes.
// Implements (properties for): SCENE.PATH.DATA

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/io/scene_json.hpp"
#include "rastrules/io/svg_path.hpp"

namespace {

namespace io = rastrules::io;

// A float32 of the kinds paths hold: small integers, quarters, any float of a magnitude in
// [2^-10, 2^14], negative zero.
rc::Gen<float> coordinate() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::inRange(-64, 65), [](int v) { return static_cast<float>(v); }),
      rc::gen::map(rc::gen::inRange(-4096, 4097),
                   [](int v) { return static_cast<float>(v) / 4.0f; }),
      rc::gen::map(rc::gen::pair(rc::gen::inRange(0, 1 << 23), rc::gen::inRange(-10, 15)),
                   [](const std::pair<int, int>& p) {
                     return std::ldexp(1.0f + static_cast<float>(p.first) / 8388608.0f, p.second) *
                            (p.first % 2 == 0 ? 1.0f : -1.0f);
                   }),
      rc::gen::just(-0.0f));
}

struct Piece {
  char command = 'L'; // upper case: M L H V Q T C S Z
  std::vector<float> numbers;
};

// The spelling of one number after the previous token: ".5" for 0.5 and a leading '+' in
// some styles; a sign may follow a number without a separator, otherwise a space or a comma.
void put_number(std::string& out, float v, bool after_number, int style) {
  std::string t = io::format_float(v);
  if (style == 1 && t.rfind("0.", 0) == 0)
    t.erase(0, 1);
  if (style == 2 && t[0] != '-')
    t = "+" + t;
  const bool glued = after_number && style != 0 && (t[0] == '-' || t[0] == '+');
  if (after_number && !glued)
    out += style == 0 ? "," : " ";
  out += t;
}

// rule: SCENE.PATH.DATA
RC_GTEST_PROP(PathData, EverySpellingReadsBackToTheFloat32Model, ()) {
  const int n = *rc::gen::inRange(1, 30);
  const bool relative = *rc::gen::arbitrary<bool>();
  std::string text;
  std::vector<io::SvgContour> model;
  float cx = 0.0f, cy = 0.0f, sx = 0.0f, sy = 0.0f; // current point, contour start
  float qx = 0.0f, qy = 0.0f;                       // previous control point
  char last = 0;
  bool open = false;
  bool after_number = false;
  const auto point = [&](float x, float y) { return io::SvgPoint{x, y, 0}; };
  for (int k = 0; k < n; ++k) {
    char cmd = k == 0 ? 'M' : *rc::gen::element('M', 'L', 'H', 'V', 'Q', 'T', 'C', 'S', 'Z');
    const int style = *rc::gen::inRange(0, 3);
    // Repeating the previous command letter may be left implicit (not after Z, not for M).
    const bool implicit =
        cmd == last && cmd != 'Z' && cmd != 'M' && after_number && *rc::gen::arbitrary<bool>();
    if (!implicit) {
      text += relative ? static_cast<char>(cmd - 'A' + 'a') : cmd;
      if (*rc::gen::arbitrary<bool>())
        text += ' ';
      after_number = false;
    }
    std::vector<float> nums;
    const int count = cmd == 'Z'                 ? 0
                      : cmd == 'H' || cmd == 'V' ? 1
                      : cmd == 'Q' || cmd == 'S' ? 4
                      : cmd == 'C'               ? 6
                                                 : 2;
    for (int j = 0; j < count; ++j) {
      nums.push_back(*coordinate());
      put_number(text, nums.back(), after_number, style);
      after_number = true;
    }
    // The model, in float32.
    const auto abs_x = [&](float v) { return relative && !(k == 0) ? cx + v : v; };
    const auto abs_y = [&](float v) { return relative && !(k == 0) ? cy + v : v; };
    const auto ensure_open = [&] {
      if (!open) {
        model.push_back(io::SvgContour{point(sx, sy), {}});
        cx = sx;
        cy = sy;
        open = true;
      }
    };
    switch (cmd) {
    case 'M':
      cx = abs_x(nums[0]);
      cy = abs_y(nums[1]);
      RC_PRE(std::isfinite(cx) && std::isfinite(cy));
      sx = cx;
      sy = cy;
      model.push_back(io::SvgContour{point(cx, cy), {}});
      open = true;
      break;
    case 'Z':
      cx = sx;
      cy = sy;
      open = false;
      break;
    default: {
      ensure_open();
      io::SvgSegment s;
      std::vector<io::SvgPoint> p;
      if (cmd == 'L') {
        p = {point(abs_x(nums[0]), abs_y(nums[1]))};
      } else if (cmd == 'H') {
        p = {point(abs_x(nums[0]), cy)};
      } else if (cmd == 'V') {
        p = {point(cx, abs_y(nums[0]))};
      } else if (cmd == 'Q') {
        p = {point(abs_x(nums[0]), abs_y(nums[1])), point(abs_x(nums[2]), abs_y(nums[3]))};
      } else if (cmd == 'T') {
        const bool smooth = last == 'Q' || last == 'T';
        p = {smooth ? point(2.0f * cx - qx, 2.0f * cy - qy) : point(cx, cy),
             point(abs_x(nums[0]), abs_y(nums[1]))};
      } else if (cmd == 'C') {
        p = {point(abs_x(nums[0]), abs_y(nums[1])), point(abs_x(nums[2]), abs_y(nums[3])),
             point(abs_x(nums[4]), abs_y(nums[5]))};
      } else { // S
        const bool smooth = last == 'C' || last == 'S';
        p = {smooth ? point(2.0f * cx - qx, 2.0f * cy - qy) : point(cx, cy),
             point(abs_x(nums[0]), abs_y(nums[1])), point(abs_x(nums[2]), abs_y(nums[3]))};
      }
      for (const auto& q : p)
        RC_PRE(std::isfinite(q.x) && std::isfinite(q.y));
      s.kind = cmd == 'Q' || cmd == 'T'   ? io::SvgSegmentKind::kQuadratic
               : cmd == 'C' || cmd == 'S' ? io::SvgSegmentKind::kCubic
                                          : io::SvgSegmentKind::kLine;
      for (std::size_t j = 0; j < p.size(); ++j)
        s.p[j] = p[j];
      if (p.size() >= 2) {
        qx = p[p.size() - 2].x;
        qy = p[p.size() - 2].y;
      }
      cx = p.back().x;
      cy = p.back().y;
      model.back().segments.push_back(s);
      break;
    }
    }
    last = cmd;
  }
  RC_LOG() << text << "\n";
  const auto read = io::parse_svg_path(text, 1000);
  if (const auto* e = std::get_if<io::SvgPathError>(&read))
    RC_FAIL("rejected: " + e->what());
  const auto& got = std::get<std::vector<io::SvgContour>>(read);
  RC_ASSERT(got.size() == model.size());
  const auto same = [](const io::SvgPoint& a, const io::SvgPoint& b) {
    return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
           std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y);
  };
  for (std::size_t c = 0; c < got.size(); ++c) {
    RC_ASSERT(same(got[c].start, model[c].start));
    RC_ASSERT(got[c].segments.size() == model[c].segments.size());
    for (std::size_t j = 0; j < got[c].segments.size(); ++j) {
      RC_ASSERT(got[c].segments[j].kind == model[c].segments[j].kind);
      const std::size_t np = got[c].segments[j].kind == io::SvgSegmentKind::kLine        ? 1
                             : got[c].segments[j].kind == io::SvgSegmentKind::kQuadratic ? 2
                                                                                         : 3;
      for (std::size_t q = 0; q < np; ++q)
        RC_ASSERT(same(got[c].segments[j].p[q], model[c].segments[j].p[q]));
    }
  }
  RC_CLASSIFY(relative, "relative");
}

} // namespace
