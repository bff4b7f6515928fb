// SPDX-License-Identifier: MIT
// Kernel against oracle for path primitives (check.hpp): the kernel's path fragments against
// the exact path oracle (rastrules/oracle/path.hpp), which shares no kernel code.
// Implements: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA (checks)

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "checker.hpp"
#include "rastrules/names.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/path.hpp"

namespace rastrules::check {

// rule: SCENE.PRIM.PATH
oracle::path::Path oracle_path(const FloatPath& path) {
  oracle::path::Path out;
  out.fill_rule = std::string(name_of(path.fill_rule));
  for (const FloatContour& c : path.contours) {
    oracle::path::Contour oc;
    oc.start = oracle_raw(c.start);
    for (const FloatPathSegment& s : c.segments) {
      oracle::path::Piece piece;
      piece.kind = s.kind == path::SegmentKind::kLine        ? oracle::path::PieceKind::kLine
                   : s.kind == path::SegmentKind::kQuadratic ? oracle::path::PieceKind::kQuadratic
                                                             : oracle::path::PieceKind::kCubic;
      for (std::size_t k = 0; k < path::point_count(s.kind); ++k)
        piece.to.push_back(oracle_raw(s.p[k]));
      oc.pieces.push_back(std::move(piece));
    }
    out.contours.push_back(std::move(oc));
  }
  return out;
}

namespace detail {

namespace {

std::string pixel_text(std::size_t p, std::int32_t x, std::int32_t y) {
  return "prim " + std::to_string(p) + " pixel (" + std::to_string(x) + ", " + std::to_string(y) +
         ")";
}

// The value a fragment of this pixel must carry: a mask (samples) or an exact area (area).
using Expected = std::map<std::pair<std::int32_t, std::int32_t>, std::string>;

} // namespace

namespace {

using Q = boost::multiprecision::cpp_rational;

// The checks every fragment of area coverage passes: an area, the kept samples as its mask;
// false (noted) where it has no area.
bool area_fragment_ok(const Fragment& f, const std::string& at, std::uint32_t keep, Checker& c) {
  if (!f.area) {
    c.note(at + ": no area on a fragment of area coverage");
    return false;
  }
  if (f.mask != keep)
    c.note(at + ": mask " + std::to_string(f.mask) + ", not the kept samples " +
           std::to_string(keep));
  return true;
}

// The oracle's certified subdivision depth for curve areas: 64 pieces a curve.
constexpr int kCurveDepth = 6;

// Area coverage of a path with curves (PATH.AREA.CURVE): neither side is exact, so each pixel's
// areas must lie within the sum of the two bounds (the oracle's: hulls of its pieces at depth
// kCurveDepth; the kernel's: its fragment's bound, or 2^-32 px^2, the most PATH.AREA.CURVE
// allows, where it lists no fragment).
void check_curve_areas(const Scene& scene, std::size_t p, const oracle::path::Path& op,
                       const std::vector<const Fragment*>& mine, std::uint32_t keep, Checker& c) {
  c.used("path oracle (cover_area_bounded: CGAL arrangement of curves cut at depth 6)");
  std::map<std::pair<std::int32_t, std::int32_t>, std::pair<Q, Q>> want, got;
  for (const oracle::path::PixelAreaBound& a :
       oracle::path::cover_area_bounded(op, scene.width, scene.height, kCurveDepth))
    want[{a.area.y, a.area.x}] = {
        Q(boost::multiprecision::cpp_int(a.area.num), boost::multiprecision::cpp_int(a.area.den)),
        Q(boost::multiprecision::cpp_int(a.bound_num),
          boost::multiprecision::cpp_int(a.bound_den))};
  for (const Fragment* f : mine) {
    const std::string at = pixel_text(p, f->x, f->y);
    if (!area_fragment_ok(*f, at, keep, c))
      continue;
    if (!got.emplace(std::make_pair(f->y, f->x),
                     std::make_pair(f->area.get()->area, f->area.get()->error_bound))
             .second)
      c.note(at + ": twice");
  }
  const Q most = Q(1) / Q(boost::multiprecision::cpp_int(1) << 32);
  std::set<std::pair<std::int32_t, std::int32_t>> pixels;
  for (const auto& [key, v] : want)
    pixels.insert(key);
  for (const auto& [key, v] : got)
    pixels.insert(key);
  for (const auto& key : pixels) {
    const auto w = want.find(key);
    const auto g = got.find(key);
    const Q oa = w == want.end() ? Q(0) : w->second.first;
    const Q ob = w == want.end() ? Q(0) : w->second.second;
    const Q ka = g == got.end() ? Q(0) : g->second.first;
    const Q kb = g == got.end() ? most : g->second.second;
    if (kb > most)
      c.note(pixel_text(p, key.second, key.first) + ": kernel bound " + kb.str() + " above 2^-32");
    if (abs(ka - oa) > kb + ob)
      c.note(pixel_text(p, key.second, key.first) + ": kernel area " + ka.str() + " +- " +
             kb.str() + ", oracle " + oa.str() + " +- " + ob.str());
  }
}

} // namespace

// rule: PATH.COVER.SAMPLE, PATH.AREA.EXACT, SCENE.OUTPUT.AREA, MSAA.MASK.AND
void check_path(const Scene& scene, std::size_t p, const std::vector<const Fragment*>& mine,
                Checker& c) {
  const FloatPath& fp = *scene.primitives[p].path;
  const oracle::path::Path op = oracle_path(fp);
  const std::uint32_t keep = scene.msaa.effective_mask();
  Expected want;
  if (fp.coverage == path::Coverage::kSamples) {
    c.used("path oracle (cover_samples: windings of every sample)");
    std::vector<oracle::msaa::Offset> pattern;
    for (const SampleOffset& o : scene.msaa.pattern.positions)
      pattern.push_back({o.x, o.y});
    const std::string fill(name_of(scene.conventions.fill));
    for (const oracle::path::SampleMask& m :
         oracle::path::cover_samples(op, pattern, fill, scene.width, scene.height)) {
      if ((m.mask & keep) != 0)
        want[{m.y, m.x}] = "mask " + std::to_string(m.mask & keep);
    }
  } else if (keep != 0 && oracle::path::has_curves(op)) {
    check_curve_areas(scene, p, op, mine, keep, c);
    return;
  } else if (keep != 0) { // a sample mask that keeps no sample leaves no fragment (MSAA.MASK.AND)
    c.used("path oracle (cover_area: exact areas from a CGAL arrangement)");
    for (const oracle::path::PixelArea& a :
         oracle::path::cover_area(op, scene.width, scene.height)) {
      // SCENE.OUTPUT.AREA's alpha, floor(area * 255 + 1/2), from the oracle's fraction.
      const boost::multiprecision::cpp_int n(a.num), d(a.den);
      const boost::multiprecision::cpp_int alpha = (n * 510 + d) / (d * 2);
      want[{a.y, a.x}] =
          "area " + (a.den == "1" ? a.num : a.num + "/" + a.den) + " alpha " + alpha.str();
    }
  }
  Expected got;
  for (const Fragment* f : mine) {
    const std::string at = pixel_text(p, f->x, f->y);
    std::string value;
    if (fp.coverage == path::Coverage::kSamples) {
      if (f->area)
        c.note(at + ": an area on a fragment of sample coverage");
      value = "mask " + std::to_string(f->mask);
    } else {
      if (!area_fragment_ok(*f, at, keep, c))
        continue;
      value = "area " + f->area.text() + " alpha " + std::to_string(f->area.alpha());
    }
    if (f->seg || f->sample || f->helper || f->centroid || f->derivatives || f->coverage_q16)
      c.note(at + ": a field a path fragment does not have");
    if (!got.emplace(std::make_pair(f->y, f->x), value).second)
      c.note(at + ": twice");
  }
  for (const auto& [key, value] : got) {
    const std::string at = pixel_text(p, key.second, key.first);
    const auto it = want.find(key);
    if (it == want.end())
      c.note("only the kernel covers " + at + " (" + value + ")");
    else if (it->second != value)
      c.note(at + ": kernel " + value + ", oracle " + it->second);
  }
  for (const auto& [key, value] : want) {
    if (!got.contains(key))
      c.note("only the oracle covers " + pixel_text(p, key.second, key.first) + " (" + value + ")");
  }
}

} // namespace detail

} // namespace rastrules::check
