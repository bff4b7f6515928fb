// SPDX-License-Identifier: MIT
// 2D paths: winding numbers, sample coverage and exact area coverage (spec/rules/path.md).

#include "rastrules/path.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <span>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/formula/path.hpp"

namespace rastrules::path {
namespace {

using detail::ActiveEdges;
using detail::Crossing;
using detail::down_edges_into;
using detail::DownEdge;
using detail::Edge;
using detail::line_threshold;
using detail::Tie;

// Returns the contribution of the directed line edge e to w(s') at sample (sx, sy): +1 down,
// -1 up, 0 when it does not cross the displaced ray (PATH.SAMPLE.TIE, line form).
// rule: PATH.SAMPLE.TIE, PATH.WINDING
int line_contribution(const Edge& e, std::int64_t sx, std::int64_t sy, Tie t) {
  const bool spans = t.y_down ? formula::path_edge_spans<true>(e.y0, e.y1, sy)
                              : formula::path_edge_spans<false>(e.y0, e.y1, sy);
  if (!spans)
    return 0;
  const std::int64_t ev = formula::edge_value<std::int64_t>(e.x0, e.y0, e.x1, e.y1, sx, sy);
  const bool right = t.x_right ? formula::path_crossing_right<true>(ev, e.y0, e.y1)
                               : formula::path_crossing_right<false>(ev, e.y0, e.y1);
  if (!right)
    return 0;
  return e.y1 > e.y0 ? 1 : -1;
}

// A curve and the y-range of its control points (the curve lies in their convex hull, so no
// row outside the range crosses it).
struct CurveRange {
  std::int64_t lo = 0, hi = 0;
  const detail::Curve* curve = nullptr;
};

// Curves whose control points' y-range holds a sample row, kept while the rows go down, each
// prepared (detail::prepare_curve) when it first meets a row (in ranges, prepared and live,
// which the caller owns and may reuse).
class ActiveCurves {
public:
  ActiveCurves(const std::vector<detail::Curve>& curves, std::vector<CurveRange>& ranges,
               std::vector<detail::PreparedCurve>& prepared,
               std::vector<const detail::PreparedCurve*>& live)
      : ranges_(ranges), prepared_(prepared), live_(live) {
    ranges_.clear();
    live_.clear();
    ranges_.reserve(curves.size());
    for (const detail::Curve& c : curves) {
      std::int64_t lo = c.p[0].y, hi = c.p[0].y;
      for (int k = 1; k <= c.degree; ++k) {
        lo = std::min<std::int64_t>(lo, c.p[static_cast<std::size_t>(k)].y);
        hi = std::max<std::int64_t>(hi, c.p[static_cast<std::size_t>(k)].y);
      }
      ranges_.push_back(CurveRange{lo, hi, &c});
    }
    // By lo, then by position in the boundary (the order of the crossings changes no answer).
    std::sort(ranges_.begin(), ranges_.end(), [](const CurveRange& p, const CurveRange& q) {
      return p.lo != q.lo ? p.lo < q.lo : p.curve < q.curve;
    });
    if (prepared_.size() < ranges_.size())
      prepared_.resize(ranges_.size());
  }
  // The curves whose range meets [y_lo, y_hi] (lo <= y_hi, hi >= y_lo). Calls must come with
  // non-decreasing y_lo and y_hi.
  const std::vector<const detail::PreparedCurve*>& advance(std::int64_t y_lo, std::int64_t y_hi) {
    while (next_ < ranges_.size() && ranges_[next_].lo <= y_hi) {
      detail::prepare_curve(*ranges_[next_].curve, prepared_[next_]);
      live_.push_back(&prepared_[next_++]);
    }
    std::erase_if(live_, [&](const detail::PreparedCurve* p) { return p->ymax < y_lo; });
    return live_;
  }

private:
  std::vector<CurveRange>& ranges_;
  std::vector<detail::PreparedCurve>& prepared_;
  std::vector<const detail::PreparedCurve*>& live_;
  std::size_t next_ = 0;
};

} // namespace

namespace detail {

Tie tie_of(FillConvention f) {
  switch (f) {
  case FillConvention::kTopLeft:
    return Tie{true, true};
  case FillConvention::kTopRight:
    return Tie{false, true};
  case FillConvention::kBottomLeft:
    return Tie{true, false};
  case FillConvention::kBottomRight:
    return Tie{false, false};
  }
  return Tie{true, true};
}

// rule: PATH.CONTOUR.CLOSE, PATH.GEOMETRY, PATH.DEGENERATE
Boundary boundary_of(const Path& path) {
  Boundary b;
  boundary_into(path, b);
  return b;
}

// rule: PATH.CONTOUR.CLOSE, PATH.GEOMETRY, PATH.DEGENERATE
void boundary_into(const Path& path, Boundary& b) {
  b.lines.clear();
  b.curves.clear();
  for (std::size_t ci = 0; ci < path.contours.size(); ++ci) {
    const Contour& c = path.contours[ci];
    Point cur = c.start;
    for (std::size_t si = 0; si < c.segments.size(); ++si) {
      const Segment& s = c.segments[si];
      switch (s.kind) {
      case SegmentKind::kLine:
        b.lines.push_back(Edge{cur.x, cur.y, s.p[0].x, s.p[0].y, ci, si});
        cur = s.p[0];
        break;
      case SegmentKind::kQuadratic:
        b.curves.push_back(Curve{2, {cur, s.p[0], s.p[1], s.p[1]}, ci, si});
        cur = s.p[1];
        break;
      case SegmentKind::kCubic:
        b.curves.push_back(Curve{3, {cur, s.p[0], s.p[1], s.p[2]}, ci, si});
        cur = s.p[2];
        break;
      }
    }
    // rule: PATH.CONTOUR.CLOSE
    if (!(cur == c.start))
      b.lines.push_back(Edge{cur.x, cur.y, c.start.x, c.start.y, ci, c.segments.size()});
  }
}

// rule: PATH.GEOMETRY
void segments_in_order(const Boundary& b, std::vector<SegmentRef>& refs) {
  refs.clear();
  for (std::size_t i = 0; i < b.lines.size(); ++i)
    refs.push_back(SegmentRef{b.lines[i].contour, b.lines[i].segment, false, i});
  for (std::size_t i = 0; i < b.curves.size(); ++i)
    refs.push_back(SegmentRef{b.curves[i].contour, b.curves[i].segment, true, i});
  std::sort(refs.begin(), refs.end(), [](const SegmentRef& p, const SegmentRef& q) {
    return p.contour != q.contour ? p.contour < q.contour : p.segment < q.segment;
  });
}

// rule: PATH.GEOMETRY
int control_points(const Boundary& b, const SegmentRef& r, std::array<Point, 4>& cp) {
  if (r.curve) {
    const Curve& c = b.curves[r.index];
    cp = c.p;
    return c.degree;
  }
  const Edge& e = b.lines[r.index];
  cp = {};
  cp[0] = Point{static_cast<std::int32_t>(e.x0), static_cast<std::int32_t>(e.y0)};
  cp[1] = Point{static_cast<std::int32_t>(e.x1), static_cast<std::int32_t>(e.y1)};
  return 1;
}

std::pair<double, double> control_y_range(const std::array<Point, 4>& cp, int degree) {
  std::int32_t lo = cp[0].y, hi = lo;
  for (int k = 1; k <= degree; ++k) {
    lo = std::min(lo, cp[static_cast<std::size_t>(k)].y);
    hi = std::max(hi, cp[static_cast<std::size_t>(k)].y);
  }
  return {lo, hi};
}

} // namespace detail

// rule: PATH.WINDING, PATH.SAMPLE.TIE
std::vector<SampleCrossing> crossings(const Path& path, Point s, FillConvention fill) {
  const Tie t = detail::tie_of(fill);
  const detail::Boundary b = detail::boundary_of(path);
  std::vector<SampleCrossing> out;
  for (const Edge& e : b.lines) {
    if (const int dir = line_contribution(e, s.x, s.y, t); dir != 0)
      out.push_back(SampleCrossing{e.contour, e.segment, dir});
  }
  for (const detail::Curve& c : b.curves) {
    for (const Crossing& x : detail::curve_crossings(c, s.y, t)) {
      if (x.counts_at(s.x))
        out.push_back(SampleCrossing{c.contour, c.segment, x.dir});
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const SampleCrossing& p, const SampleCrossing& q) {
    return std::tie(p.contour, p.segment) < std::tie(q.contour, q.segment);
  });
  return out;
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
std::int64_t winding_number(const Path& path, Point s, FillConvention fill) {
  std::int64_t w = 0;
  for (const SampleCrossing& x : crossings(path, s, fill))
    w += x.dir;
  return w;
}

// rule: PATH.SAMPLE.TIE, PATH.FILL.RULE
bool covers_sample(const Path& path, Point s, FillConvention fill) {
  return fill_holds(path.fill_rule, winding_number(path, s, fill));
}

namespace {

// The memory of a row walk: kept between calls on one thread, so that a glyph-sized call
// allocates nothing once the vectors have grown. A walk started from inside emit (the busy
// one is in use) takes a fresh one.
struct SampleWork {
  detail::Boundary boundary;
  std::vector<DownEdge> edges;
  std::vector<const DownEdge*> active_edges;
  std::vector<CurveRange> curve_ranges;
  std::vector<detail::PreparedCurve> prepared_curves;
  std::vector<const detail::PreparedCurve*> live_curves;
  std::vector<Crossing> curve_out, curve_left;
  std::vector<detail::BandRow> band;           // the sample rows of a band of pixel rows
  std::vector<detail::RowCrossings> crossings; // their crossings, each in room of
  std::vector<Crossing> room;                  // this buffer
  std::vector<std::uint32_t> masks;
  bool busy = false;
};

// The row walk of cover_samples, emit called for each pixel with a sample covered, row by row:
// a template, so that the vector form appends without a call through std::function a pixel.
// rule: PATH.COVER.SAMPLE
template <class Emit>
void walk_samples_with(SampleWork& work, const Path& path, const SamplePattern& pattern,
                       FillConvention fill, std::int32_t w, std::int32_t h, Emit&& emit) {
  const Tie t = detail::tie_of(fill);
  detail::boundary_into(path, work.boundary);
  down_edges_into(work.boundary, work.edges);
  ActiveEdges active(work.edges, work.active_edges);
  ActiveCurves curves(work.boundary.curves, work.curve_ranges, work.prepared_curves,
                      work.live_curves);

  // The pattern's samples grouped by their row offset, top row first (a mask has 32 bits; a
  // pattern at most kMaxSamples = 16 samples).
  struct Sample {
    std::uint32_t bit = 0;
    std::int64_t x_offset = 0; // raw x of the sample in pixel column 0
  };
  struct SampleRow {
    std::int32_t oy = 0;
    std::size_t first = 0, count = 0; // into samples
  };
  std::array<Sample, 32> samples{};
  std::array<SampleRow, 32> rows{};
  std::size_t n_rows = 0, n_samples = 0;
  {
    std::array<std::size_t, 32> order{};
    const std::size_t n = std::min<std::size_t>(pattern.positions.size(), order.size());
    for (std::size_t k = 0; k < n; ++k)
      order[k] = k;
    // By row offset, then by sample index: the rows' samples in the order of the pattern.
    std::stable_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n),
                     [&](std::size_t p, std::size_t q) {
                       return pattern.positions[p].y < pattern.positions[q].y;
                     });
    for (std::size_t i = 0; i < n; ++i) {
      const SampleOffset o = pattern.positions[order[i]];
      if (n_rows == 0 || rows[n_rows - 1].oy != o.y)
        rows[n_rows++] = SampleRow{o.y, n_samples, 0};
      samples[n_samples++] =
          Sample{std::uint32_t{1} << order[i],
                 std::int64_t{kSubpixelHalf} + std::int64_t{o.x} * kSampleGridUnit};
      ++rows[n_rows - 1].count;
    }
  }
  // One sample a pixel: each row's covered pixels are emitted straight from its intervals,
  // which come left to right and hold disjoint pixels (one sample each).
  const bool single = n_samples == 1;

  std::vector<std::uint32_t>& masks = work.masks;
  if (!single)
    masks.assign(static_cast<std::size_t>(w), 0);
  // Pixel rows go in bands of up to kBandRows sample rows (whole pixel rows; at least one):
  // each curve is asked for all its rows of a band at once (detail::curve_crossings_band).
  // The band holds every crossing of its rows at once, so a boundary of many segments takes
  // fewer rows a band: at most about 2^16 segment rows (a few MiB of crossings). Each row has
  // room for what can cross it: one crossing a live line, three a live curve.
  constexpr std::size_t kBandRows = 16, kBandSegmentRows = std::size_t{1} << 16;
  const std::size_t segments =
      std::max<std::size_t>(1, work.boundary.lines.size() + work.boundary.curves.size());
  const auto band_pixels = static_cast<std::int32_t>(
      std::max<std::size_t>(1, std::min(kBandRows, kBandSegmentRows / segments) / n_rows));
  const std::int64_t off_lo = kSubpixelHalf + std::int64_t{rows[0].oy} * kSampleGridUnit,
                     off_hi = kSubpixelHalf + std::int64_t{rows[n_rows - 1].oy} * kSampleGridUnit;
  std::vector<detail::BandRow>& band = work.band;
  std::vector<detail::RowCrossings>& crossings = work.crossings;
  crossings.resize(static_cast<std::size_t>(band_pixels) * n_rows);
  for (std::int32_t j0 = 0; j0 < h; j0 += band_pixels) {
    const std::int32_t j1 = std::min(h, j0 + band_pixels);
    band.clear();
    for (std::int32_t j = j0; j < j1; ++j) {
      for (std::size_t r = 0; r < n_rows; ++r) {
        const std::int64_t sy = std::int64_t{j} * kSubpixelOne + kSubpixelHalf +
                                std::int64_t{rows[r].oy} * kSampleGridUnit;
        // One sample in this row of the pattern: a curve's crossing needs only the samples'
        // class (PATH.CURVE.COARSE).
        const std::int64_t sample_x =
            rows[r].count == 1 ? samples[rows[r].first].x_offset : detail::kExactThresholds;
        band.push_back(detail::BandRow{sy, sample_x});
      }
    }
    const std::vector<const DownEdge*>& lines = active.advance(band.front().sy, band.back().sy);
    const std::vector<const detail::PreparedCurve*>& live =
        curves.advance(band.front().sy, band.back().sy);
    const std::size_t room = lines.size() + 3 * live.size();
    if (work.room.size() < room * band.size())
      work.room.resize(room * band.size());
    for (std::size_t i = 0; i < band.size(); ++i)
      crossings[i] = detail::RowCrossings{work.room.data() + i * room, 0, room};
    // The band's sample rows that may lie within [lo, hi], as the first and the count: whole
    // pixel rows, those of pixel j lying at 256 j + off_lo .. 256 j + off_hi. (Shifts right of
    // signed values are floor divisions by 256: arithmetic since C++20.)
    const auto rows_within = [&](std::int64_t lo, std::int64_t hi) {
      const std::int64_t first = std::max<std::int64_t>(j0, -((off_hi - lo) >> kSubpixelBits));
      const std::int64_t last = std::min<std::int64_t>(j1 - 1, (hi - off_lo) >> kSubpixelBits);
      return first > last ? std::pair<std::size_t, std::size_t>{0, 0}
                          : std::pair{static_cast<std::size_t>(first - j0) * n_rows,
                                      static_cast<std::size_t>(last - first + 1) * n_rows};
    };
    // The lines first, then the curves, into each row (the lines of the band found once).
    for (const DownEdge* e : lines) {
      const auto [at, count] = rows_within(e->ya, e->yb);
      for (std::size_t i = at; i < at + count; ++i) {
        const std::int64_t sy = band[i].sy;
        const bool spans = t.y_down ? formula::path_edge_spans<true>(e->ya, e->yb, sy)
                                    : formula::path_edge_spans<false>(e->ya, e->yb, sy);
        if (spans)
          crossings[i].push_back(Crossing{line_threshold(*e, sy, t), e->dir});
      }
    }
    // Each curve gets the rows within its control points' y-range.
    for (const detail::PreparedCurve* c : live) {
      const auto [at, count] = rows_within(c->ymin, c->ymax);
      if (count == 0)
        continue;
      detail::curve_crossings_band(*c, std::span{band}.subspan(at, count), t,
                                   std::span{crossings}.subspan(at, count), work.curve_out,
                                   work.curve_left);
    }
    for (std::int32_t j = j0; j < j1; ++j) {
      std::int64_t touched_lo = w, touched_hi = -1;
      for (std::size_t r = 0; r < n_rows; ++r) {
        detail::RowCrossings& row = crossings[static_cast<std::size_t>(j - j0) * n_rows + r];
        if (row.empty())
          continue;
        // By threshold (the order of equal thresholds changes no winding on an interval that
        // holds a sample). Two crossings, the most common row of a glyph: one comparison.
        if (row.size() == 2) {
          if (row[1].threshold < row[0].threshold)
            std::swap(row[0], row[1]);
        } else {
          std::sort(row.begin(), row.end(),
                    [](const Crossing& p, const Crossing& q) { return p.threshold < q.threshold; });
        }
        // Winding on each interval of sample x: (T[m-1], T[m]] has the sum of dir over l >= m,
        // the total less the sum over l < m.
        std::int64_t total = 0;
        for (const Crossing& c : row)
          total += c.dir;
        for (std::size_t k = rows[r].first; k < rows[r].first + rows[r].count; ++k) {
          const Sample& smp = samples[k];
          std::int64_t winding = total;
          for (std::size_t m = 0; m <= row.size(); ++m) {
            if (m > 0)
              winding -= row[m - 1].dir;
            if (!fill_holds(path.fill_rule, winding))
              continue;
            // Pixels i with A < 256 i + x_offset <= B.
            std::int64_t i_lo = 0, i_hi = std::int64_t{w} - 1;
            if (m > 0)
              i_lo = std::max(i_lo, ((row[m - 1].threshold - smp.x_offset) >> kSubpixelBits) + 1);
            if (m < row.size())
              i_hi = std::min(i_hi, (row[m].threshold - smp.x_offset) >> kSubpixelBits);
            if (i_lo > i_hi)
              continue;
            if (single) {
              if constexpr (requires { emit.span(i_lo, i_hi, j, smp.bit); }) {
                emit.span(i_lo, i_hi, j, smp.bit);
              } else {
                for (std::int64_t i = i_lo; i <= i_hi; ++i)
                  emit(SampleCoverage{static_cast<std::int32_t>(i), j, smp.bit});
              }
              continue;
            }
            for (std::int64_t i = i_lo; i <= i_hi; ++i)
              masks[static_cast<std::size_t>(i)] |= smp.bit;
            touched_lo = std::min(touched_lo, i_lo);
            touched_hi = std::max(touched_hi, i_hi);
          }
        }
      }
      for (std::int64_t i = touched_lo; i <= touched_hi; ++i) {
        std::uint32_t& m = masks[static_cast<std::size_t>(i)];
        if (m != 0)
          emit(SampleCoverage{static_cast<std::int32_t>(i), j, m});
        m = 0;
      }
    }
  }
}

// rule: PATH.COVER.SAMPLE
template <class Emit>
void walk_samples(const Path& path, const SamplePattern& pattern, FillConvention fill,
                  std::int32_t w, std::int32_t h, Emit&& emit) {
  if (w <= 0 || h <= 0 || pattern.positions.empty())
    return;
  thread_local SampleWork kept;
  if (kept.busy) { // a walk from inside emit: its own memory
    SampleWork fresh;
    walk_samples_with(fresh, path, pattern, fill, w, h, emit);
    return;
  }
  kept.busy = true;
  struct Release {
    SampleWork& work;
    ~Release() {
      // Memory kept for glyph-sized paths and targets, not for the largest ever walked.
      constexpr std::size_t kKeep = std::size_t{1} << 14;
      if (work.boundary.lines.capacity() + work.boundary.curves.capacity() > kKeep ||
          work.masks.capacity() > kKeep || work.room.capacity() > kKeep)
        work = SampleWork{};
      work.busy = false;
    }
  } release{kept};
  walk_samples_with(kept, path, pattern, fill, w, h, emit);
}

} // namespace

// rule: PATH.COVER.SAMPLE
void cover_samples(const Path& path, const SamplePattern& pattern, FillConvention fill,
                   std::int32_t w, std::int32_t h,
                   const std::function<void(const SampleCoverage&)>& emit) {
  walk_samples(path, pattern, fill, w, h, emit);
}

namespace {

// The pixels of one row's run as a forward range, from the pixel `at` up to the end iterator's x
// (vector::insert then grows the vector once and constructs the run in one loop).
struct RunIterator {
  using iterator_category = std::forward_iterator_tag;
  using value_type = SampleCoverage;
  using difference_type = std::ptrdiff_t;
  using pointer = const SampleCoverage*;
  using reference = const SampleCoverage&;
  SampleCoverage at;
  reference operator*() const { return at; }
  pointer operator->() const { return &at; }
  RunIterator& operator++() {
    ++at.x;
    return *this;
  }
  RunIterator operator++(int) {
    RunIterator r = *this;
    ++at.x;
    return r;
  }
  friend bool operator==(const RunIterator& a, const RunIterator& b) { return a.at.x == b.at.x; }
};

} // namespace

// rule: PATH.COVER.SAMPLE
std::vector<SampleCoverage> cover_samples(const Path& path, const SamplePattern& pattern,
                                          FillConvention fill, std::int32_t w, std::int32_t h) {
  std::vector<SampleCoverage> out;
  // Room for a small target's pixels at once (at most 2^12 entries, 48 KiB, below malloc's
  // mmap threshold): glyph-sized results then grow without copies.
  if (w > 0 && h > 0)
    out.reserve(std::min<std::size_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h),
                                      std::size_t{1} << 12));
  // Pixels one at a time (the masks of several samples), or a run of one row at once (one
  // sample a pixel: a row's interval): the run grows the vector once and is written in a plain
  // loop, not a push_back (a capacity test and a store of the end) a pixel.
  struct Append {
    std::vector<SampleCoverage>& out;
    void operator()(const SampleCoverage& c) const { out.push_back(c); }
    void span(std::int64_t lo, std::int64_t hi, std::int32_t y, std::uint32_t bit) const {
      out.insert(out.end(), RunIterator{SampleCoverage{static_cast<std::int32_t>(lo), y, bit}},
                 RunIterator{SampleCoverage{static_cast<std::int32_t>(hi + 1), y, bit}});
    }
  };
  walk_samples(path, pattern, fill, w, h, Append{out});
  return out;
}

// rule: PATH.COVER.MONO
void cover_samples_mono(const Path& path, FillConvention fill, std::int32_t w, std::int32_t h,
                        std::span<std::uint8_t> bits, std::size_t pitch) {
  if (w < 0 || h < 0 || w > kMaxTargetSide || h > kMaxTargetSide)
    throw std::invalid_argument(
        "path: a mono bitmap's width and height must be in [0, 16384] (PATH.COVER.MONO)");
  if (pitch < (static_cast<std::size_t>(w) + 7) / 8)
    throw std::invalid_argument("path: a mono bitmap's pitch is below (w + 7) / 8 bytes "
                                "(PATH.COVER.MONO)");
  const auto rows = static_cast<std::size_t>(h);
  if ((rows != 0 && pitch > bits.size() / rows) || bits.size() != pitch * rows)
    throw std::invalid_argument("path: a mono bitmap's buffer is not h * pitch bytes "
                                "(PATH.COVER.MONO)");
  std::fill(bits.begin(), bits.end(), std::uint8_t{0});
  // A row's covered pixels come as runs, left to right and disjoint (one sample a pixel): the
  // run's partial bytes at both ends are masked in, the bytes between filled.
  struct SetBits {
    std::uint8_t* bits;
    std::size_t pitch;
    void run(std::int64_t lo, std::int64_t hi, std::int32_t y) const {
      std::uint8_t* row = bits + static_cast<std::size_t>(y) * pitch;
      const auto b0 = static_cast<std::size_t>(lo >> 3), b1 = static_cast<std::size_t>(hi >> 3);
      // Pixel x is bit 7 - x % 8: pixels lo % 8 .. 7 of the first byte, 0 .. hi % 8 of the last.
      const auto first = static_cast<std::uint8_t>(0xFFu >> (lo & 7));
      const auto last = static_cast<std::uint8_t>(0xFFu << (7 - (hi & 7)));
      if (b0 == b1) {
        row[b0] |= static_cast<std::uint8_t>(first & last);
        return;
      }
      row[b0] |= first;
      std::fill(row + b0 + 1, row + b1, std::uint8_t{0xFF});
      row[b1] |= last;
    }
    void operator()(const SampleCoverage& c) const { run(c.x, c.x, c.y); }
    void span(std::int64_t lo, std::int64_t hi, std::int32_t y, std::uint32_t) const {
      run(lo, hi, y);
    }
  };
  static const SamplePattern centre = standard_pattern(1);
  walk_samples(path, centre, fill, w, h, SetBits{bits.data(), pitch});
}

} // namespace rastrules::path
