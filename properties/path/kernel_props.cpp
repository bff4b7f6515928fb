// SPDX-License-Identifier: MIT
// Properties: the kernel's path coverage (rastrules/path.hpp) equals the exact oracle's on
// random paths (sample masks for every fill convention and the standard patterns of 1, 4 and
// 16 samples, winding numbers on tie samples, exact areas, both fill rules), and the kernel
// keeps the invariants of the definitions: a one-triangle path covers what the triangle rule
// covers, evenodd == nonzero on simple polygons, reversing every contour keeps coverage, every
// contour drawn twice is empty under evenodd, the halves of a polygon cut along a chord
// partition its samples and sum to its areas, translation by whole pixels, and areas within
// the 4 x 4 grid bound of the samples.
// Implements (properties for): PATH.WINDING, PATH.FILL.RULE, PATH.SAMPLE.TIE,
//   PATH.COVER.SAMPLE, PATH.AREA.EXACT, PATH.DEGENERATE

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "path_checks.hpp"
#include "path_gen.hpp"
#include "path_kernel.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/path.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace pg = rastrules::path_gen;
namespace pc = rastrules::path_checks;
namespace kp = rastrules::path;
namespace op = rastrules::oracle::path;
namespace om = rastrules::oracle::msaa;
using pc::kSide;
using pc::show_path;
using pg::Raw2;
using rastrules::path_kernel::kpoint;
using rastrules::path_kernel::to_kernel;

// ---------------------------------------------------------------------------------------------
// Adapters: the generators' description to the kernel's types.

rastrules::FillConvention convention(const std::string& fill) {
  if (fill == "top-left")
    return rastrules::FillConvention::kTopLeft;
  if (fill == "top-right")
    return rastrules::FillConvention::kTopRight;
  if (fill == "bottom-left")
    return rastrules::FillConvention::kBottomLeft;
  if (fill == "bottom-right")
    return rastrules::FillConvention::kBottomRight;
  throw std::invalid_argument("unknown fill convention " + fill);
}

rastrules::SamplePattern kernel_pattern(const std::vector<om::Offset>& offsets) {
  std::vector<rastrules::SampleOffset> v;
  for (const om::Offset& o : offsets)
    v.push_back(
        rastrules::SampleOffset{static_cast<std::int8_t>(o.x), static_cast<std::int8_t>(o.y)});
  return rastrules::custom_pattern(v);
}

pc::Masks kernel_masks(const pg::GPath& p, const rastrules::SamplePattern& pattern,
                       const std::string& fill, std::int32_t side) {
  pc::Masks m;
  for (const kp::SampleCoverage& s :
       kp::cover_samples(to_kernel(p), pattern, convention(fill), side, side))
    m[{s.y, s.x}] = s.mask;
  return m;
}

// The pixels set in the kernel's mono bitmap (PATH.COVER.MONO), as one-sample masks; the
// rows padded by a byte, so that a bit written past w shows as a pixel the oracle lacks.
pc::Masks kernel_mono_masks(const pg::GPath& p, const std::string& fill, std::int32_t side) {
  const std::size_t pitch = (static_cast<std::size_t>(side) + 7) / 8 + 1;
  std::vector<std::uint8_t> bits(pitch * static_cast<std::size_t>(side), 0xFF);
  kp::cover_samples_mono(to_kernel(p), convention(fill), side, side, bits, pitch);
  pc::Masks m;
  for (std::int32_t y = 0; y < side; ++y)
    for (std::int32_t x = 0; static_cast<std::size_t>(x) < pitch * 8; ++x)
      if (kp::mono_bit(bits, pitch, x, y))
        m[{y, x}] = 1;
  return m;
}

pc::Areas kernel_areas(const pg::GPath& p, std::int32_t side) {
  pc::Areas a;
  for (const kp::AreaCoverage& c : kp::cover_area(to_kernel(p), side, side)) {
    if (c.error_bound != 0)
      throw std::logic_error("kernel: a path of lines with a nonzero error bound");
    a[{c.y, c.x}] = pc::rational(boost::multiprecision::numerator(c.area).str(),
                                 boost::multiprecision::denominator(c.area).str());
  }
  return a;
}

template <class M> std::string map_difference(const M& kernel, const M& oracle) {
  for (const auto& [px, v] : kernel) {
    const auto o = oracle.find(px);
    if (o == oracle.end() || o->second != v) {
      std::ostringstream os;
      os << pc::str(px) << ": kernel " << v << ", oracle ";
      if (o == oracle.end())
        os << "nothing";
      else
        os << o->second;
      return os.str();
    }
  }
  for (const auto& [px, v] : oracle) {
    if (kernel.find(px) == kernel.end()) {
      std::ostringstream os;
      os << pc::str(px) << ": kernel nothing, oracle " << v;
      return os.str();
    }
  }
  return "";
}

void classify_ties(const pg::GPath& p, const std::vector<om::Offset>& pattern) {
  const pg::Ties t = pg::ties(p, pattern, kSide);
  RC_CLASSIFY(t.on_vertex, "sample on a vertex");
  RC_CLASSIFY(t.on_edge, "sample on an edge");
  RC_CLASSIFY(t.on_horizontal, "sample on a horizontal edge");
  RC_CLASSIFY(t.on_vertical, "sample on a vertical edge");
}

std::vector<om::Offset> any_standard_pattern() {
  return om::standard_pattern(*rc::gen::element(1u, 4u, 16u));
}

// ---------------------------------------------------------------------------------------------
// Kernel == oracle

// rule: PATH.COVER.SAMPLE, PATH.SAMPLE.TIE, PATH.FILL.RULE, PATH.WINDING, PATH.DEGENERATE
// rule: PATH.GEOMETRY, PATH.COVER.MONO
RC_GTEST_PROP(PathKernel, SampleMasksEqualOracle, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  show_path(p);
  const std::vector<om::Offset> pattern = any_standard_pattern();
  RC_TAG(pg::name(p.kind), pg::fill_rule(p));
  classify_ties(p, pattern);
  const rastrules::SamplePattern kpat =
      rastrules::standard_pattern(static_cast<std::uint32_t>(pattern.size()));
  for (const std::string& fill : pg::conventions()) {
    const std::string diff = map_difference(kernel_masks(p, kpat, fill, kSide),
                                            pc::oracle_masks(p, pattern, fill, kSide));
    if (!diff.empty())
      RC_FAIL(fill + ", " + std::to_string(pattern.size()) + " samples: " + diff);
    if (pattern.size() == 1) {
      const std::string mono = map_difference(kernel_mono_masks(p, fill, kSide),
                                              pc::oracle_masks(p, pattern, fill, kSide));
      if (!mono.empty())
        RC_FAIL(fill + ", mono bitmap: " + mono);
    }
  }
}

// Returns the bound of PATH.WINDING.BOUND, tightened: each piece of degree d crosses a line at
// most d times, each closing line once.
std::int64_t winding_bound(const pg::GPath& p) {
  std::int64_t b = 0;
  for (const pg::GContour& c : p.contours) {
    b += 1;
    for (const pg::GPiece& q : c.pieces)
      b += q.degree;
  }
  return b;
}

// Checks the kernel's winding number (and coverage) against the oracle's on every tie point
// of p, and against the bound.
// Returns whether some tie sample is decided differently by the conventions (it lies on the
// boundary).
bool check_tie_windings(const pg::GPath& p) {
  const kp::Path k = to_kernel(p);
  const op::Path o = pg::to_oracle(p);
  const std::int64_t bound = winding_bound(p);
  bool split = false;
  for (const Raw2& s : pg::tie_points(p)) {
    std::vector<std::int64_t> ws;
    for (const std::string& fill : pg::conventions()) {
      const std::int64_t wk = kp::winding_number(k, kpoint(s), convention(fill));
      const std::int64_t wo = op::winding(o, s, fill);
      if (wk != wo)
        RC_FAIL("(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ") raw, " + fill +
                ": kernel " + std::to_string(wk) + ", oracle " + std::to_string(wo));
      RC_ASSERT(kp::covers_sample(k, kpoint(s), convention(fill)) == op::covers(o, s, fill));
      RC_ASSERT(wk <= bound && -wk <= bound);
      ws.push_back(wk);
    }
    split = split || std::adjacent_find(ws.begin(), ws.end(), std::not_equal_to<>()) != ws.end();
  }
  return split;
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE, PATH.DEGENERATE, PATH.WINDING.BOUND
RC_GTEST_PROP(PathKernel, WindingNumbersEqualOracleOnTies, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  show_path(p);
  RC_TAG(pg::name(p.kind));
  RC_CLASSIFY(check_tie_windings(p), "a tie sample the conventions decide differently");
}

// Up to 32 copies of one contour, each in either direction: w counts every copy (no 4-bit or
// 8-bit accumulator), kernel == oracle.
// rule: PATH.WINDING, PATH.WINDING.BOUND, PATH.FILL.RULE
RC_GTEST_PROP(PathKernel, StackedContoursCountEveryCopy, ()) {
  const pg::GPath one = *pg::path(kSide, false);
  const int n = *rc::gen::inRange(2, 33);
  pg::GPath p{one.kind, one.evenodd, {}};
  for (int i = 0; i < n; ++i) {
    for (const pg::GContour& c : one.contours)
      p.contours.push_back(*rc::gen::inRange(0, 4) == 0 ? pg::reversed(c) : c);
  }
  show_path(one);
  RC_LOG() << n << " copies\n";
  (void)check_tie_windings(p);
}

// Writing the closing line out changes nothing.
// rule: PATH.CONTOUR.CLOSE
RC_GTEST_PROP(PathKernel, AnExplicitClosingLineChangesNothing, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  pg::GPath closed = p;
  for (pg::GContour& c : closed.contours)
    c.pieces.push_back(pg::GPiece{1, {c.start}});
  show_path(p);
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const rastrules::SamplePattern kpat = kernel_pattern(any_standard_pattern());
  RC_ASSERT(
      map_difference(kernel_masks(closed, kpat, fill, kSide), kernel_masks(p, kpat, fill, kSide))
          .empty());
  RC_ASSERT(map_difference(kernel_areas(closed, kSide), kernel_areas(p, kSide)).empty());
}

// rule: PATH.AREA.EXACT, PATH.FILL.RULE, PATH.DEGENERATE
RC_GTEST_PROP(PathKernel, AreasEqualOracle, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  show_path(p);
  RC_TAG(pg::name(p.kind), pg::fill_rule(p));
  const pc::Areas k = kernel_areas(p, kSide);
  RC_CLASSIFY(std::any_of(k.begin(), k.end(), [](const auto& a) { return a.second < 1; }),
              "a partly covered pixel");
  const std::string diff = map_difference(k, pc::oracle_areas(p, kSide));
  if (!diff.empty())
    RC_FAIL(diff);
}

// ---------------------------------------------------------------------------------------------
// Invariants, on the kernel

// rule: PATH.TIE.TRIANGLE, PATH.SAMPLE.TIE, TRI.COVER.SAMPLE, TRI.FILL.CONVENTION
RC_GTEST_PROP(PathKernel, OneTrianglePathCoversWhatTheTriangleRuleCovers, ()) {
  const rastrules::gen::RawTriangle t = *rc::gen::weightedOneOf<rastrules::gen::RawTriangle>({
      {4, rastrules::gen::nondegenerate_raw_triangle_near(4, 4)},
      {1, rastrules::gen::raw_triangle_near(4, 4)},
  });
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  rastrules::RasterState state;
  state.fill = convention(fill);
  const rastrules::TriangleSetup tri = rastrules::setup_triangle(rastrules::gen::to_vec2(t), state);
  pg::GPath p{pg::PathKind::kPolygon,
              *rc::gen::arbitrary<bool>(),
              {pg::polygon({{t[0][0], t[0][1]}, {t[1][0], t[1][1]}, {t[2][0], t[2][1]}})}};
  show_path(p);
  const kp::Path k = to_kernel(p);
  std::vector<Raw2> samples = pg::tie_points(p);
  for (std::int64_t y = 0; y < 4 * 256; y += 32)
    for (std::int64_t x = 0; x < 4 * 256; x += 32)
      samples.push_back({x + 16, y + 16});
  std::size_t covered = 0;
  for (const Raw2& s : samples) {
    const bool by_path = kp::covers_sample(k, kpoint(s), state.fill);
    const bool by_tri = rastrules::covers(
        tri, rastrules::gen::to_vec2(rastrules::gen::RawPoint{static_cast<std::int32_t>(s[0]),
                                                              static_cast<std::int32_t>(s[1])}));
    covered += by_tri ? 1u : 0u;
    if (by_path != by_tri)
      RC_FAIL("(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ") raw, " + fill +
              ": path " + std::to_string(by_path) + ", triangle " + std::to_string(by_tri));
  }
  RC_CLASSIFY(covered == 0, "nothing covered");
}

// Returns a simple polygon: a convex hull or one half of a convex polygon cut along a chord.
pg::GPath simple_polygon() {
  const pg::CutPolygon c = *pg::cut_polygon(kSide);
  const int which = *rc::gen::inRange(0, 3);
  return pg::GPath{pg::PathKind::kPolygon,
                   false,
                   {which == 0   ? c.whole
                    : which == 1 ? c.first
                                 : c.second}};
}

// rule: PATH.FILL.RULE
RC_GTEST_PROP(PathKernel, EvenOddEqualsNonZeroOnSimplePolygons, ()) {
  pg::GPath p = simple_polygon();
  show_path(p);
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const std::vector<om::Offset> pattern = any_standard_pattern();
  const rastrules::SamplePattern kpat = kernel_pattern(pattern);
  const pc::Masks nonzero = kernel_masks(p, kpat, fill, kSide);
  const pc::Areas nonzero_area = kernel_areas(p, kSide);
  p.evenodd = true;
  RC_ASSERT(map_difference(kernel_masks(p, kpat, fill, kSide), nonzero).empty());
  RC_ASSERT(map_difference(kernel_areas(p, kSide), nonzero_area).empty());
}

// rule: PATH.TIE.PARTITION, PATH.WINDING, PATH.FILL.RULE
RC_GTEST_PROP(PathKernel, ReversingEveryContourKeepsCoverage, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  pg::GPath r = p;
  for (pg::GContour& c : r.contours)
    c = pg::reversed(c);
  show_path(p);
  show_path(r);
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const rastrules::SamplePattern kpat = kernel_pattern(any_standard_pattern());
  const std::string masks =
      map_difference(kernel_masks(r, kpat, fill, kSide), kernel_masks(p, kpat, fill, kSide));
  if (!masks.empty())
    RC_FAIL("reversed vs original: " + masks);
  const std::string areas = map_difference(kernel_areas(r, kSide), kernel_areas(p, kSide));
  if (!areas.empty())
    RC_FAIL("reversed vs original: " + areas);
  const kp::Path kpth = to_kernel(p), krev = to_kernel(r);
  for (const Raw2& s : pg::tie_points(p))
    RC_ASSERT(kp::winding_number(krev, kpoint(s), convention(fill)) ==
              -kp::winding_number(kpth, kpoint(s), convention(fill)));
}

// rule: PATH.FILL.RULE, PATH.WINDING, PATH.AREA.EXACT
RC_GTEST_PROP(PathKernel, EveryContourDrawnTwiceIsEmptyUnderEvenOdd, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  pg::GPath twice = p;
  twice.contours.clear();
  for (const pg::GContour& c : p.contours) {
    twice.contours.push_back(c);
    twice.contours.push_back(c);
  }
  show_path(twice);
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const rastrules::SamplePattern kpat = kernel_pattern(any_standard_pattern());
  twice.evenodd = true;
  RC_ASSERT(kernel_masks(twice, kpat, fill, kSide).empty());
  RC_ASSERT(kernel_areas(twice, kSide).empty());
  // Under nonzero, twice covers what once covers (w doubles, its zeros stay).
  twice.evenodd = false;
  pg::GPath once = p;
  once.evenodd = false;
  RC_ASSERT(
      map_difference(kernel_masks(twice, kpat, fill, kSide), kernel_masks(once, kpat, fill, kSide))
          .empty());
  RC_ASSERT(map_difference(kernel_areas(twice, kSide), kernel_areas(once, kSide)).empty());
}

// rule: PATH.TIE.PARTITION, PATH.SAMPLE.TIE, PATH.AREA.EXACT
RC_GTEST_PROP(PathKernel, PolygonCutAlongAChordPartitionsSamplesAndAreas, ()) {
  const pc::CutCase c = pc::cut_case(kSide);
  const rastrules::SamplePattern kpat = kernel_pattern(c.pattern);
  pc::check_cut(
      c, [&](const pg::GPath& p) { return kernel_masks(p, kpat, c.fill, kSide); },
      [&](const pg::GPath& p) { return kernel_areas(p, kSide); });
}

// rule: PATH.SAMPLE.TIE, PATH.AREA.EXACT
RC_GTEST_PROP(PathKernel, TranslationByWholePixels, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  const std::int32_t dx = *rc::gen::inRange(-2, 3), dy = *rc::gen::inRange(-2, 3);
  const pg::GPath q = pg::translated(p, 256 * dx, 256 * dy);
  show_path(p);
  RC_PRE(pg::in_range(q));
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const rastrules::SamplePattern kpat = kernel_pattern(any_standard_pattern());
  // On a target of 2 side: compare the pixels whose translate lies in the target too.
  const std::int32_t big = 2 * kSide;
  const pc::Masks mp = kernel_masks(p, kpat, fill, big), mq = kernel_masks(q, kpat, fill, big);
  const pc::Areas ap = kernel_areas(p, big), aq = kernel_areas(q, big);
  for (std::int32_t y = 0; y < big; ++y) {
    for (std::int32_t x = 0; x < big; ++x) {
      const std::int32_t tx = x + dx, ty = y + dy;
      if (tx < 0 || ty < 0 || tx >= big || ty >= big)
        continue;
      const auto m0 = mp.find({y, x}), m1 = mq.find({ty, tx});
      const std::uint32_t v0 = m0 == mp.end() ? 0u : m0->second;
      const std::uint32_t v1 = m1 == mq.end() ? 0u : m1->second;
      if (v0 != v1)
        RC_FAIL(pc::str({y, x}) + ": mask " + std::to_string(v0) + ", translated " +
                std::to_string(v1));
      const auto a0 = ap.find({y, x}), a1 = aq.find({ty, tx});
      const mpq_class w0 = a0 == ap.end() ? mpq_class(0) : a0->second;
      const mpq_class w1 = a1 == aq.end() ? mpq_class(0) : a1->second;
      if (w0 != w1)
        RC_FAIL(pc::str({y, x}) + ": area " + w0.get_str() + ", translated " + w1.get_str());
    }
  }
}

// rule: PATH.AREA.EXACT, PATH.COVER.SAMPLE
RC_GTEST_PROP(PathKernel, AreaWithinTheGridBoundOfItsSamples, ()) {
  const pg::GPath p = *pg::path(kSide, false);
  show_path(p);
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const std::string problem = pc::grid_bound_problem(
      p, kernel_masks(p, kernel_pattern(pc::grid4()), fill, kSide), kernel_areas(p, kSide), kSide);
  if (!problem.empty())
    RC_FAIL(problem);
}

// The row walk takes the rows in bands of up to 16 sample rows, each line and curve asked once
// a band for the rows within its y-range (PATH.COVER.SAMPLE; kernel/src/path.cpp): the bands
// change no sample. On paths scaled to 32 px (curves split at t = 1/2) and moved down by 0-15
// px, so that band boundaries fall at every offset in the path, the whole target's masks equal,
// row by row, those of a one-row target that holds the row alone (the path moved up by whole
// pixels, which moves no sample: TranslationByWholePixels). The properties above use 4 px
// targets, inside one band.
// rule: PATH.COVER.SAMPLE
RC_GTEST_PROP(PathKernel, BandsOfRowsChangeNoSample, ()) {
  const std::int32_t shift = *rc::gen::inRange(0, 16);
  const pg::GPath p =
      pg::translated(pg::scaled_and_split(*pg::path(kSide, true), 8), 0, 256 * shift);
  show_path(p);
  RC_PRE(pg::in_range(p));
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const rastrules::SamplePattern kpat = kernel_pattern(any_standard_pattern());
  constexpr std::int32_t side = 8 * kSide + 16;
  const pc::Masks whole = kernel_masks(p, kpat, fill, side);
  pc::Masks by_rows;
  for (std::int32_t y = 0; y < side; ++y)
    for (const kp::SampleCoverage& s :
         kp::cover_samples(to_kernel(pg::translated(p, 0, -256 * std::int64_t{y})), kpat,
                           convention(fill), side, 1))
      by_rows[{y, s.x}] = s.mask;
  RC_CLASSIFY(whole.size() > 64, "more than 64 pixels covered");
  const std::string diff = map_difference(whole, by_rows);
  if (!diff.empty())
    RC_FAIL(fill + ", " + std::to_string(kpat.count()) + " samples, moved down " +
            std::to_string(shift) + " px: whole target against one row at a time: " + diff);
}

// ---------------------------------------------------------------------------------------------
// Curves: exact sample decisions, kernel == oracle.

// rule: PATH.CURVE.SAMPLE, PATH.WINDING, PATH.SAMPLE.TIE, PATH.COVER.SAMPLE, PATH.GEOMETRY
// rule: PATH.TIE.PARTITION, PATH.COVER.MONO, PATH.CURVE.COARSE
TEST(PathKernel, CurveSampleMasksAndTieWindingsEqualOracle) {
  EXPECT_TRUE(rc::check("curve sample masks and tie windings, kernel == oracle", [] {
    pg::GPath p;
    p.kind = pg::PathKind::kCurves;
    p.evenodd = *rc::gen::arbitrary<bool>();
    const int n = *rc::gen::inRange(1, 3);
    for (int i = 0; i < n; ++i)
      p.contours.push_back(*pg::curve_contour(kSide));
    show_path(p);
    const std::string fill = *rc::gen::elementOf(pg::conventions());
    const std::vector<om::Offset> pattern = any_standard_pattern();
    const std::string diff = map_difference(kernel_masks(p, kernel_pattern(pattern), fill, kSide),
                                            pc::oracle_masks(p, pattern, fill, kSide));
    if (!diff.empty())
      RC_FAIL(fill + ": " + diff);
    if (pattern.size() == 1) {
      const std::string mono = map_difference(kernel_mono_masks(p, fill, kSide),
                                              pc::oracle_masks(p, pattern, fill, kSide));
      if (!mono.empty())
        RC_FAIL(fill + ", mono bitmap: " + mono);
    }
    const kp::Path k = to_kernel(p);
    const bool split = check_tie_windings(p);
    RC_CLASSIFY(split, "a tie sample the conventions decide differently");
    // Reversing every contour negates w; splitting every curve at t = 1/2 (all coordinates
    // times 8, so that the halves' controls are raw points) keeps it.
    pg::GPath rev = p;
    for (pg::GContour& c : rev.contours)
      c = pg::reversed(c);
    const kp::Path kr = to_kernel(rev), ks = to_kernel(pg::scaled_and_split(p, 8));
    for (const Raw2& s : pg::tie_points(p)) {
      const rastrules::FillConvention f = convention(fill);
      const std::int64_t w = kp::winding_number(k, kpoint(s), f);
      RC_ASSERT(kp::winding_number(kr, kpoint(s), f) == -w);
      RC_ASSERT(kp::winding_number(ks, kpoint({8 * s[0], 8 * s[1]}), f) == w);
    }
  }));
}

} // namespace

namespace {

// The kernel's curve areas within their stated error bound plus the oracle's certified one
// (depth 6: 64 pieces per curve) of the exact area, in every pixel, and every bound at most
// 2^-32 px^2 (PATH.AREA.CURVE).
// rule: PATH.AREA.EXACT, PATH.AREA.CURVE
TEST(PathKernel, CurveAreasWithinTheBoundsOfTheCertifiedOracle) {
  EXPECT_TRUE(rc::check("curve areas, kernel within bounds of the oracle", [] {
    pg::GPath p{pg::PathKind::kCurves, *rc::gen::arbitrary<bool>(), {}};
    const int n = *rc::gen::inRange(1, 3);
    for (int i = 0; i < n; ++i)
      p.contours.push_back(*pg::curve_contour(kSide));
    show_path(p);
    std::map<pc::Pixel, std::array<mpq_class, 4>> all; // kernel area, bound; oracle area, bound
    for (const kp::AreaCoverage& c : kp::cover_area(to_kernel(p), kSide, kSide)) {
      all[{c.y, c.x}][0] = pc::rational(boost::multiprecision::numerator(c.area).str(),
                                        boost::multiprecision::denominator(c.area).str());
      all[{c.y, c.x}][1] = pc::rational(boost::multiprecision::numerator(c.error_bound).str(),
                                        boost::multiprecision::denominator(c.error_bound).str());
      const pc::Pixel px{c.y, c.x};
      RC_ASSERT(all[px][1] <= mpq_class(1) / (mpq_class(65536) * 65536)); // 2^-32
    }
    for (const op::PixelAreaBound& a : op::cover_area_bounded(pg::to_oracle(p), kSide, kSide, 6)) {
      all[{a.area.y, a.area.x}][2] = pc::rational(a.area.num, a.area.den);
      all[{a.area.y, a.area.x}][3] = pc::rational(a.bound_num, a.bound_den);
    }
    for (const auto& [px, v] : all) {
      if (abs(v[0] - v[2]) > v[1] + v[3])
        RC_FAIL(pc::str(px) + ": kernel " + v[0].get_str() + " +- " + v[1].get_str() + ", oracle " +
                v[2].get_str() + " +- " + v[3].get_str());
    }
  }));
}

} // namespace
