// SPDX-License-Identifier: MIT
// Path primitives in the scene: snapping, work and fragments (kernel/src/path_scene.hpp), and
// the exact area a path fragment carries (ExactArea).

#include "path_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/path.hpp"
#include "rastrules/snap.hpp"

namespace rastrules {

namespace {

using Rational = boost::multiprecision::cpp_rational;
using BigInt = boost::multiprecision::cpp_int;

const Rational& value_of(const ExactArea& a) {
  return a.get()->area;
}

} // namespace

// rule: SCENE.OUTPUT.AREA
std::string ExactArea::text() const {
  if (!value_)
    return {};
  const Rational& q = value_->area;
  const BigInt& d = boost::multiprecision::denominator(q);
  if (d == 1)
    return boost::multiprecision::numerator(q).str();
  return boost::multiprecision::numerator(q).str() + "/" + d.str();
}

// rule: SCENE.OUTPUT.AREA
std::uint8_t ExactArea::alpha() const {
  return value_ ? path::detail::alpha_of(value_->area) : std::uint8_t{0};
}

// rule: SCENE.OUTPUT.AREA
double ExactArea::approx() const {
  if (!value_)
    return 0.0;
  // Correctly rounded (to nearest, ties to even) from the exact fraction: a 54-bit quotient
  // with a sticky remainder.
  BigInt n = boost::multiprecision::numerator(value_->area);
  const BigInt d = boost::multiprecision::denominator(value_->area);
  if (n == 0)
    return 0.0;
  const bool negative = n < 0;
  if (negative)
    n = -n;
  // n / d lies in [2^(k-1), 2^(k+1)) for k = msb(n) - msb(d); scaled by 2^(54-k) its quotient
  // has 54 or 55 bits: 53 kept, one rounding bit, the rest and the remainder sticky.
  const long long k = static_cast<long long>(boost::multiprecision::msb(n)) -
                      static_cast<long long>(boost::multiprecision::msb(d));
  const long long shift = 54 - k;
  const BigInt scaled_n = shift >= 0 ? BigInt(n << static_cast<unsigned>(shift)) : n;
  const BigInt scaled_d = shift >= 0 ? d : BigInt(d << static_cast<unsigned>(-shift));
  BigInt q = scaled_n / scaled_d;
  bool sticky = q * scaled_d != scaled_n;
  long long e = -shift;
  if (q >= (BigInt(1) << 54)) {
    sticky = sticky || (q & 1) != 0;
    q >>= 1;
    ++e;
  }
  auto m = q.convert_to<std::uint64_t>(); // in [2^53, 2^54)
  const bool round_bit = (m & 1u) != 0;
  m >>= 1;
  ++e;
  if (round_bit && (sticky || (m & 1u) != 0))
    ++m; // 2^53 after a carry is still exact in a double
  const double v = std::ldexp(static_cast<double>(m), static_cast<int>(e));
  return negative ? -v : v;
}

// rule: SCENE.OUTPUT.AREA, PATH.AREA.CURVE
std::string ExactArea::bound_text() const {
  if (!value_ || value_->error_bound == 0)
    return {};
  const Rational& q = value_->error_bound;
  return boost::multiprecision::numerator(q).str() + "/" +
         boost::multiprecision::denominator(q).str();
}

bool operator==(const ExactArea& a, const ExactArea& b) {
  if (!a || !b)
    return !a && !b;
  return value_of(a) == value_of(b) && a.get()->error_bound == b.get()->error_bound;
}

namespace detail {

namespace {

std::string field_of(std::size_t p) {
  return "primitives[" + std::to_string(p) + "]";
}

} // namespace

// rule: SCENE.PRIM.PATH, SNAP.VERTEX.INVALID, SCENE.INPUT.LIMITS
std::optional<SceneError> prepare_path(const FloatPath& in, std::size_t p,
                                       PreparedPrimitive& prim) {
  std::size_t segments = 0;
  for (const FloatContour& c : in.contours)
    segments += c.segments.size();
  if (segments > kMaxPathSegments) {
    return SceneError{field_of(p) + ".path",
                      "has " + std::to_string(segments) + " segments, more than " +
                          std::to_string(kMaxPathSegments) + " (limit SCENE.INPUT.LIMITS)"};
  }
  std::size_t point_index = 0; // in reading order, for d_offsets
  auto snap = [&](const FloatPoint& fp, std::size_t c, std::optional<std::size_t> s, std::size_t k,
                  path::Point& out) -> std::optional<SceneError> {
    std::int32_t raw[2] = {0, 0};
    for (std::size_t a = 0; a < 2; ++a) {
      const SnapResult r = snap_to_subpixel(fp[a]);
      if (r.status != SnapStatus::kOk) {
        const std::string what =
            std::string(a == 0 ? "x" : "y") + " is " + std::string(to_string(r.status));
        if (in.d_offsets.size() > point_index) {
          return SceneError{field_of(p) + ".d", "the point at character " +
                                                    std::to_string(in.d_offsets[point_index]) +
                                                    ": " + what};
        }
        // The number in the JSON contour form: contours[c][command][1 + 2 k + a], command 0
        // the contour's "M" and command s + 1 its segment s.
        const std::size_t command = s ? *s + 1 : 0;
        return SceneError{field_of(p) + ".contours[" + std::to_string(c) + "][" +
                              std::to_string(command) + "][" + std::to_string(1 + 2 * k + a) + "]",
                          "is " + std::string(to_string(r.status))};
      }
      raw[a] = r.value.raw();
    }
    out = path::Point{raw[0], raw[1]};
    ++point_index;
    return std::nullopt;
  };
  auto out = std::make_shared<path::Path>();
  out->fill_rule = in.fill_rule;
  out->contours.reserve(in.contours.size());
  for (std::size_t c = 0; c < in.contours.size(); ++c) {
    const FloatContour& fc = in.contours[c];
    path::Contour pc;
    if (auto err = snap(fc.start, c, std::nullopt, 0, pc.start))
      return err;
    pc.segments.reserve(fc.segments.size());
    for (std::size_t s = 0; s < fc.segments.size(); ++s) {
      const FloatPathSegment& fs = fc.segments[s];
      path::Segment ps;
      ps.kind = fs.kind;
      for (std::size_t k = 0; k < path::point_count(fs.kind); ++k) {
        if (auto err = snap(fs.p[k], c, s, k, ps.p[k]))
          return err;
      }
      pc.segments.push_back(ps);
    }
    out->contours.push_back(std::move(pc));
  }
  prim.path = std::move(out);
  prim.coverage = in.coverage;
  return std::nullopt;
}

namespace {

constexpr std::uint64_t kWorkCap = std::uint64_t{1} << 62;

std::uint64_t sat_mul(std::uint64_t a, std::uint64_t b) {
  return (a != 0 && b > kWorkCap / a) ? kWorkCap : std::min(a * b, kWorkCap);
}
std::uint64_t sat_add(std::uint64_t a, std::uint64_t b) {
  return std::min(a + b, kWorkCap);
}

} // namespace

// rule: SCENE.INPUT.LIMITS
std::uint64_t path_work(const PreparedScene& scene, const PreparedPrimitive& prim) {
  // Per pixel row of the target, the pieces (segments and closing lines) whose control hull
  // reaches it, widened by a row each way: a difference array over the rows.
  const path::Path& pth = *prim.path;
  const std::int32_t h = scene.height;
  // diff[0]: every piece; diff[1]: the curves among them.
  std::vector<std::int64_t> diff[2] = {std::vector<std::int64_t>(static_cast<std::size_t>(h) + 1),
                                       std::vector<std::int64_t>(static_cast<std::size_t>(h) + 1)};
  std::int64_t x_lo = std::numeric_limits<std::int64_t>::max();
  std::int64_t x_hi = std::numeric_limits<std::int64_t>::min();
  auto add_piece = [&](std::int64_t lo, std::int64_t hi, bool curve) {
    const std::int64_t a = std::max<std::int64_t>(floor_div(lo, kSubpixelOne) - 1, 0);
    const std::int64_t b = std::min<std::int64_t>(floor_div(hi, kSubpixelOne) + 1, h - 1);
    if (a > b)
      return;
    for (int d = 0; d < (curve ? 2 : 1); ++d) {
      ++diff[d][static_cast<std::size_t>(a)];
      --diff[d][static_cast<std::size_t>(b) + 1];
    }
  };
  for (const path::Contour& c : pth.contours) {
    path::Point cur = c.start;
    for (const path::Segment& s : c.segments) {
      std::int64_t lo = cur.y, hi = cur.y;
      for (std::size_t k = 0; k < path::point_count(s.kind); ++k) {
        lo = std::min<std::int64_t>(lo, s.p[k].y);
        hi = std::max<std::int64_t>(hi, s.p[k].y);
        x_lo = std::min<std::int64_t>(x_lo, s.p[k].x);
        x_hi = std::max<std::int64_t>(x_hi, s.p[k].x);
      }
      const bool curve = s.kind != path::SegmentKind::kLine;
      add_piece(lo, hi, curve);
      cur = s.p[path::point_count(s.kind) - 1];
    }
    add_piece(std::min(cur.y, c.start.y), std::max(cur.y, c.start.y), false); // closing line
    x_lo = std::min<std::int64_t>(x_lo, c.start.x);
    x_hi = std::max<std::int64_t>(x_hi, c.start.x);
  }
  const std::int64_t c0 = std::max<std::int64_t>(floor_div(x_lo, kSubpixelOne) - 1, 0);
  const std::int64_t c1 =
      std::min<std::int64_t>(floor_div(x_hi, kSubpixelOne) + 1, std::int64_t{scene.width} - 1);
  const std::uint64_t cols = c1 < c0 ? 0 : static_cast<std::uint64_t>(c1 - c0 + 1);
  const std::uint64_t n = scene.msaa.pattern.count();
  const bool samples = prim.coverage == path::Coverage::kSamples;
  std::uint64_t work = 0;
  std::int64_t in_row = 0, curves_in_row = 0;
  for (std::int32_t r = 0; r < h; ++r) {
    in_row += diff[0][static_cast<std::size_t>(r)];
    curves_in_row += diff[1][static_cast<std::size_t>(r)];
    const auto c = static_cast<std::uint64_t>(in_row);
    if (samples) {
      // Per sample: the row's line pieces tested (kPathPieceWork each), its curves' exact
      // crossings (kPathCurveWork each) and its pixels filled.
      const auto cc = static_cast<std::uint64_t>(curves_in_row);
      const std::uint64_t row = sat_add(
          sat_add(sat_mul(c - cc, kPathPieceWork), sat_mul(cc, kPathCurveWork)), c == 0 ? 0 : cols);
      work = sat_add(work, sat_mul(n, row));
    } else if (c != 0) {
      // Area: every pair of the row's pieces (their crossings cut it into slabs: at most
      // 2c + c(c-1)/2 + 1), and per slab its pieces sorted, in exact rationals (kPathAreaWork
      // each); then each pixel's exact area (kPathAreaPixelWork).
      const std::uint64_t slabs = sat_add(sat_add(2 * c, sat_mul(c, c - 1) / 2), 1);
      const std::uint64_t ops = sat_add(sat_mul(c, c), sat_mul(slabs, c));
      work = sat_add(work, sat_add(sat_mul(ops, kPathAreaWork), sat_mul(cols, kPathAreaPixelWork)));
    }
  }
  return work;
}

// rule: PATH.COVER.SAMPLE, PATH.AREA.EXACT, SCENE.OUTPUT.AREA, MSAA.MASK.AND
void path_fragments(const PreparedScene& scene, std::size_t p,
                    const std::function<void(Fragment&&)>& emit) {
  const PreparedPrimitive& prim = scene.primitives[p];
  const auto id = static_cast<std::uint32_t>(p);
  const std::uint32_t keep = scene.msaa.effective_mask();
  if (keep == 0)
    return; // the sample mask removes every sample (MSAA.MASK.AND)
  if (prim.coverage == path::Coverage::kSamples) {
    path::cover_samples(*prim.path, scene.msaa.pattern, scene.conventions.fill, scene.width,
                        scene.height, [&](const path::SampleCoverage& c) {
                          if (const std::uint32_t m = c.mask & keep; m != 0)
                            emit(Fragment{id, c.x, c.y, m});
                        });
    return;
  }
  path::cover_area(*prim.path, scene.width, scene.height, [&](const path::AreaCoverage& a) {
    if (a.area == 0)
      return; // a pixel listed for its error bound alone (curves, PATH.AREA.CURVE)
    Fragment f{id, a.x, a.y, keep};
    f.area =
        ExactArea(std::make_shared<const path::AreaValue>(path::AreaValue{a.area, a.error_bound}));
    emit(std::move(f));
  });
}

} // namespace detail

} // namespace rastrules
