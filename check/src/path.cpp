// SPDX-License-Identifier: MIT
// Kernel against oracle for path primitives (check.hpp): the kernel's path fragments against
// the exact path oracle (rastrules/oracle/path.hpp), which shares no kernel code.
// Implements: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA (checks)

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "checker.hpp"
#include "rastrules/names.hpp"
#include "rastrules/oracle/path.hpp"

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
      if (!f->area) {
        c.note(at + ": no area on a fragment of area coverage");
        continue;
      }
      if (f->mask != keep)
        c.note(at + ": mask " + std::to_string(f->mask) + ", not the kept samples " +
               std::to_string(keep));
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
