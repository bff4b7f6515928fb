// SPDX-License-Identifier: MIT
// A 2D library's raster against the exact path coverage: what is legal (the boundary convention
// of an aliased pixel, 8-bit quantisation within a stated tolerance) and, for every larger
// difference, the model that explains it (FUZZ.PATH.CLASSIFY).
// Implements: FUZZ.PATH.COMPARE, FUZZ.PATH.CLASSIFY

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <variant>

#include "rastrules/fuzzer/paths.hpp"
#include "rastrules/path.hpp"

namespace rastrules::fuzzer::paths {

namespace {

using boost::multiprecision::cpp_rational;

// rule: PATH.AREA.ALPHA
int alpha_of(const cpp_rational& a) {
  // The kernel's own rounding (ExactArea::alpha), not a second copy of it.
  return ExactArea(std::make_shared<const path::AreaValue>(path::AreaValue{a, 0})).alpha();
}

// The path with f applied to every control point.
template <class F> path::Path with_points(path::Path p, F f) {
  for (path::Contour& c : p.contours) {
    c.start = f(c.start);
    for (path::Segment& s : c.segments)
      for (std::size_t i = 0; i < path::point_count(s.kind); ++i)
        s.p[i] = f(s.p[i]);
  }
  return p;
}

std::size_t at(std::int32_t w, std::int32_t x, std::int32_t y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
}

std::vector<std::uint8_t> samples_raster(const path::Path& p, FillConvention fill, std::int32_t w,
                                         std::int32_t h) {
  std::vector<std::uint8_t> r(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (const path::SampleCoverage& c : path::cover_samples(p, SamplePattern{}, fill, w, h))
    r[at(w, c.x, c.y)] = 1;
  return r;
}

std::vector<std::uint8_t> alpha_raster(const path::Path& p, std::int32_t w, std::int32_t h) {
  std::vector<std::uint8_t> r(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  path::cover_area_alpha(p, w, h, r);
  return r;
}

// The path with every control point rounded to a multiple of g raw units (half to even).
path::Path snapped(path::Path p, std::int32_t g) {
  auto round = [g](std::int32_t v) {
    const std::int64_t q = v >= 0 ? v / g : -((-static_cast<std::int64_t>(v) + g - 1) / g);
    const std::int64_t r = v - q * g; // in [0, g)
    std::int64_t n = q;
    if (2 * r > g || (2 * r == g && (q & 1) != 0))
      ++n;
    return static_cast<std::int32_t>(n * g);
  };
  return with_points(std::move(p), [&](path::Point q) {
    return path::Point{round(q.x), round(q.y)};
  });
}

bool has_curves(const path::Path& p) {
  for (const path::Contour& c : p.contours)
    for (const path::Segment& s : c.segments)
      if (s.kind != path::SegmentKind::kLine)
        return true;
  return false;
}

// Whether the control-point box of segment s (from prev) meets [x0, x1] x [y0, y1] (raw): the
// curve lies in the hull of its control points, so it can meet the box only then.
bool box_meets(path::Point prev, const path::Segment& s, std::int64_t x0, std::int64_t y0,
               std::int64_t x1, std::int64_t y1) {
  std::int64_t lx = prev.x, hx = prev.x, ly = prev.y, hy = prev.y;
  for (std::size_t i = 0; i < path::point_count(s.kind); ++i) {
    lx = std::min<std::int64_t>(lx, s.p[i].x);
    hx = std::max<std::int64_t>(hx, s.p[i].x);
    ly = std::min<std::int64_t>(ly, s.p[i].y);
    hy = std::max<std::int64_t>(hy, s.p[i].y);
  }
  return hx >= x0 && lx <= x1 && hy >= y0 && ly <= y1;
}

// Whether pixel (x, y), grown by one pixel on every side, meets the control-point box of a
// curve of the path: where a flattening of that curve can change the pixel.
bool near_curve(const path::Path& p, std::int32_t x, std::int32_t y) {
  const std::int64_t one = kSubpixelOne;
  const std::int64_t x0 = (x - 1) * one, x1 = (x + 2) * one, y0 = (y - 1) * one, y1 = (y + 2) * one;
  for (const path::Contour& c : p.contours) {
    path::Point prev = c.start;
    for (const path::Segment& s : c.segments) {
      if (s.kind != path::SegmentKind::kLine && box_meets(prev, s, x0, y0, x1, y1))
        return true;
      prev = s.p[path::point_count(s.kind) - 1];
    }
  }
  return false;
}

// Whether the boundary crosses one of the centre lines of pixel (x, y) inside the pixel, where a
// scanline rasterizer's dropout control looks for spans that hold no pixel centre: a line that
// meets the horizontal line through the centre between the pixel's left and right edges, or the
// vertical one between its top and bottom edges (exact: integer cross-multiplication); a curve
// whose control-point box meets the pixel (its hull holds the curve).
bool crosses_centre_lines(const path::Path& p, std::int32_t x, std::int32_t y) {
  const std::int64_t one = kSubpixelOne;
  const std::int64_t x0 = x * one, x1 = (x + 1) * one, y0 = y * one, y1 = (y + 1) * one;
  // Whether segment a-b meets the segment {v = c, u in [lo, hi]} (u, v: the other axis and this).
  auto meets = [](std::int64_t au, std::int64_t av, std::int64_t bu, std::int64_t bv,
                  std::int64_t c, std::int64_t lo, std::int64_t hi) {
    if ((av < c && bv < c) || (av > c && bv > c))
      return false;
    if (av == bv)
      return std::max(au, bu) >= lo && std::min(au, bu) <= hi;
    // u at v = c is au + (c - av) (bu - au) / (bv - av): compare with lo and hi exactly.
    std::int64_t num = au * (bv - av) + (c - av) * (bu - au), den = bv - av;
    if (den < 0) {
      num = -num;
      den = -den;
    }
    return num >= lo * den && num <= hi * den;
  };
  auto line = [&](path::Point a, path::Point b) {
    return meets(a.x, a.y, b.x, b.y, y0 + one / 2, x0, x1) ||
           meets(a.y, a.x, b.y, b.x, x0 + one / 2, y0, y1);
  };
  for (const path::Contour& c : p.contours) {
    path::Point prev = c.start;
    for (const path::Segment& s : c.segments) {
      const std::size_t n = path::point_count(s.kind);
      if (s.kind == path::SegmentKind::kLine) {
        if (line(prev, s.p[0]))
          return true;
      } else {
        if (box_meets(prev, s, x0, y0, x1, y1))
          return true;
      }
      prev = s.p[n - 1];
    }
    if (line(prev, c.start))
      return true;
  }
  return false;
}

// The path moved by (dx, dy) raw units.
path::Path moved(path::Path p, std::int32_t dx, std::int32_t dy) {
  return with_points(std::move(p), [&](path::Point q) { return path::Point{q.x + dx, q.y + dy}; });
}

// A winding number as a 4-bit signed accumulator holds it: w mod 16 in [-8, 8).
std::int64_t wrap4(std::int64_t w) {
  return ((w + 8) % 16 + 16) % 16 - 8;
}

std::string text(const cpp_rational& r) {
  return r.str();
}

// The lazily computed models of one primitive.
class Models {
public:
  Models(const path::Path& p, const Scene& scene, bool antialiased, const PathCompareOptions& o)
      : path_(p), scene_(scene), aa_(antialiased), options_(o) {}

  // rule: FUZZ.PATH.CLASSIFY
  DiffClass classify(std::int32_t x, std::int32_t y, int actual, std::string& why) {
    const std::int32_t w = scene_.width, h = scene_.height;
    auto close = [&](int model) {
      return aa_ ? std::abs(model - actual) <= options_.alpha_tolerance : model == actual;
    };
    if (aa_) {
      const path::PixelWindings pw = path::winding_areas(path_, x, y, w, h);
      std::size_t nonzero_parts = 0;
      cpp_rational acc = 0, wrapped = 0;
      bool big = false;
      std::string parts;
      for (const path::WindingArea& part : pw.parts) {
        acc += part.area * part.winding;
        if (part.winding != 0)
          ++nonzero_parts;
        big = big || std::abs(part.winding) >= 8;
        if (path::fill_holds(path_.fill_rule, wrap4(part.winding)))
          wrapped += part.area;
        parts +=
            (parts.empty() ? "" : ", ") + std::to_string(part.winding) + ": " + text(part.area);
      }
      cpp_rational folded = abs(acc);
      if (path_.fill_rule == path::FillRule::kNonZero) {
        folded = std::min<cpp_rational>(folded, 1);
      } else {
        while (folded > 2)
          folded -= 2;
        if (folded > 1)
          folded = 2 - folded;
      }
      if (nonzero_parts > 0 && close(alpha_of(folded))) {
        why = "windings {" + parts + "}: the signed-area sum " + text(acc) + " gives alpha " +
              std::to_string(alpha_of(folded));
        return DiffClass::kConflation;
      }
      if (big && close(alpha_of(wrapped))) {
        why = "windings {" + parts + "}: wrapped to 4 bits they fill " + text(wrapped);
        return DiffClass::kWindingOverflow;
      }
    } else {
      const path::Point centre{x * kSubpixelOne + kSubpixelOne / 2,
                               y * kSubpixelOne + kSubpixelOne / 2};
      const std::int64_t wn = path::winding_number(path_, centre, scene_.conventions.fill);
      if (std::abs(wn) >= 8 && (path::fill_holds(path_.fill_rule, wrap4(wn)) ? 1 : 0) == actual) {
        why = "winding number " + std::to_string(wn) + " is " + std::to_string(wrap4(wn)) +
              " in 4 bits";
        return DiffClass::kWindingOverflow;
      }
    }
    {
      auto& r = models_[kOtherRule];
      if (r.empty()) {
        path::Path o = path_;
        o.fill_rule = o.fill_rule == path::FillRule::kNonZero ? path::FillRule::kEvenOdd
                                                              : path::FillRule::kNonZero;
        r = aa_ ? alpha_raster(o, w, h) : samples_raster(o, scene_.conventions.fill, w, h);
      }
      if (close(r[at(w, x, y)])) {
        why = std::string("the exact coverage under the other fill rule (") +
              (path_.fill_rule == path::FillRule::kNonZero ? "evenodd" : "nonzero") + ") gives " +
              std::to_string(r[at(w, x, y)]);
        return DiffClass::kFillRule;
      }
    }
    for (const std::int32_t g : {4, 16}) {
      auto& r = models_[g];
      if (r.empty()) {
        const path::Path s = snapped(path_, g);
        r = aa_ ? alpha_raster(s, w, h) : samples_raster(s, scene_.conventions.fill, w, h);
      }
      if (close(r[at(w, x, y)])) {
        why = "the exact coverage of the path on a grid of " + std::to_string(g) +
              "/256 px gives " + std::to_string(r[at(w, x, y)]);
        return DiffClass::kGridSnapping;
      }
    }
    if (!aa_) {
      // The sample (or the path) off by one 16.8 unit: a library that samples 1/256 px away
      // from the centre, or rounds its coordinates once more.
      constexpr std::array<std::array<std::int32_t, 2>, 4> kShifts = {
          {{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
      for (std::size_t k = 0; k < kShifts.size(); ++k) {
        auto& r = models_[-1 - static_cast<std::int32_t>(k)];
        if (r.empty())
          r = samples_raster(moved(path_, kShifts[k][0], kShifts[k][1]), scene_.conventions.fill, w,
                             h);
        if (close(r[at(w, x, y)])) {
          why = "the exact coverage with the sample 1/256 px off the centre (" +
                std::to_string(-kShifts[k][0]) + ", " + std::to_string(-kShifts[k][1]) +
                " raw) gives " + std::to_string(r[at(w, x, y)]);
          return DiffClass::kGridSnapping;
        }
      }
    }
    if (!aa_ && actual == 1 && crosses_centre_lines(path_, x, y)) {
      why = "the boundary crosses the pixel's centre lines but covers no centre: a dropout pixel";
      return DiffClass::kDropout;
    }
    if (has_curves(path_) && near_curve(path_, x, y)) {
      why = "within 1 px of a curve's control points";
      return DiffClass::kFlattening;
    }
    why = "no model explains it";
    return DiffClass::kOther;
  }

private:
  const path::Path& path_;
  const Scene& scene_;
  bool aa_;
  const PathCompareOptions& options_;
  // The models' rasters, computed when first needed: by grid step (4, 16), the path moved by
  // one unit (-1 .. -4), the other fill rule (kOtherRule).
  static constexpr std::int32_t kOtherRule = -100;
  std::map<std::int32_t, std::vector<std::uint8_t>> models_;
};

} // namespace

// rule: FUZZ.PATH.CLASSIFY
std::string_view to_string(DiffClass c) {
  constexpr std::array<std::string_view, kDiffClassCount> names = {
      "boundary tie",  "conflation",       "winding overflow", "fill rule",
      "grid snapping", "curve flattening", "dropout",          "other"};
  return names[static_cast<std::size_t>(c)];
}

// rule: FUZZ.PATH.CLASSIFY
DiffClass PathComparison::main_class() const {
  std::size_t best = kDiffClassCount - 1;
  for (std::size_t i = kDiffClassCount; i-- > 0;)
    if (by_class[i] > 0 && by_class[i] >= by_class[best])
      best = i;
  return static_cast<DiffClass>(best);
}

// rule: FUZZ.PATH.COMPARE, FUZZ.PATH.CLASSIFY
std::optional<PathComparison> compare_paths(const Scene& scene, const std::vector<Fragment>& actual,
                                            const PathCompareOptions& options, std::string* error) {
  auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared)) {
    *error = "invalid scene: " + e->what();
    return std::nullopt;
  }
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  const std::int32_t w = ps.width, h = ps.height;
  PathComparison out;
  for (std::size_t i = 0; i < ps.primitives.size(); ++i) {
    const PreparedPrimitive& prim = ps.primitives[i];
    if (!prim.path) {
      *error = "primitives[" + std::to_string(i) + "] is not a path";
      return std::nullopt;
    }
    const bool aa = prim.coverage == path::Coverage::kArea;
    out.antialiased = out.antialiased || aa;
    std::vector<std::uint8_t> got(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
    for (const Fragment& f : actual) {
      if (f.prim != i || f.x < 0 || f.y < 0 || f.x >= w || f.y >= h)
        continue;
      got[at(w, f.x, f.y)] = static_cast<std::uint8_t>(aa ? (f.area ? f.area.alpha() : 255) : 1);
    }
    const path::Path& p = *prim.path;
    std::vector<std::uint8_t> exact =
        aa ? alpha_raster(p, w, h) : samples_raster(p, ps.conventions.fill, w, h);
    std::array<std::vector<std::uint8_t>, 4> ties;
    Models models(p, scene, aa, options);
    if (!aa)
      for (std::size_t k = 0; k < ties.size(); ++k)
        ties[k] = samples_raster(p, static_cast<FillConvention>(k), w, h);
    for (std::int32_t y = 0; y < h; ++y)
      for (std::int32_t x = 0; x < w; ++x) {
        ++out.pixels;
        const int e = exact[at(w, x, y)], a = got[at(w, x, y)];
        if (!aa) {
          // rule: FUZZ.PATH.COMPARE
          // A pixel the conventions decide differently: which of them give the library's answer.
          std::uint8_t agree = 0, differ = 0;
          for (std::size_t k = 0; k < ties.size(); ++k) {
            agree = static_cast<std::uint8_t>(agree | (ties[k][at(w, x, y)] == a ? 1u << k : 0u));
            differ = static_cast<std::uint8_t>(
                differ | (ties[k][at(w, x, y)] != ties[0][at(w, x, y)] ? 1 : 0));
          }
          if (differ != 0) {
            ++out.tie_pixels;
            out.conventions = static_cast<std::uint8_t>(out.conventions & agree);
          }
        }
        if (e == a)
          continue;
        bool tie = false;
        if (aa) {
          const int d = std::abs(a - e);
          out.max_alpha_error = std::max(out.max_alpha_error, d);
          if (d <= options.alpha_tolerance) {
            ++out.within;
            continue;
          }
        } else {
          // rule: FUZZ.PATH.COMPARE
          // The pixel centre on the boundary: another convention of PATH.SAMPLE.TIE decides it.
          for (std::size_t k = 0; k < ties.size() && !tie; ++k)
            tie = ties[k][at(w, x, y)] == a;
          if (tie && options.legal) {
            ++out.legal_ties;
            continue;
          }
        }
        PixelDiff d;
        d.prim = static_cast<std::uint32_t>(i);
        d.x = x;
        d.y = y;
        d.expected = e;
        d.actual = a;
        if (tie) {
          d.klass = DiffClass::kBoundaryTie;
          d.why = "the pixel centre is on the boundary: another convention of PATH.SAMPLE.TIE "
                  "decides it";
        } else {
          d.klass = models.classify(x, y, a, d.why);
        }
        ++out.by_class[static_cast<std::size_t>(d.klass)];
        out.diffs.push_back(std::move(d));
      }
    out.expected.push_back(std::move(exact));
    out.actual.push_back(std::move(got));
  }
  out.match = out.diffs.empty();
  return out;
}

} // namespace rastrules::fuzzer::paths
