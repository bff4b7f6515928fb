// SPDX-License-Identifier: MIT
// The path ladder (spec/bench.md BENCH.PATH.*): what accuracy costs for 2D paths. One run, the
// rungs alternating within every repeat, medians; errors against the exact areas; and the
// comparisons with FreeType's gray and monochrome rasterizers on the same outlines.
//
//   rastrules_path_ladder [--quick] [--samples-only | --alpha-only] [--repeats N] [--json FILE]
//                         [--plot FILE.png] [--dejavu FONT] [--cubic FONT] [--scenes PREFIX]
//   rastrules_path_ladder --picture FILE.png
//
// Prints the tables (Markdown) on standard output; --json writes the same figures, --plot the
// time against error of every rung. --samples-only runs the sample-coverage comparison alone
// (no area rungs), with the cubic font at every size too; --alpha-only the curved outlines' exact
// alpha against FreeType gray alone, likewise at every size; --scenes runs only the scenes whose
// name begins with PREFIX (e.g. nimbus-cubic-64, for a profile of one scene). --picture writes the
// conflation cases, exact beside FreeType's gray raster, and runs nothing else. Implements:
// BENCH.PATH.RUNGS, BENCH.PATH.SCENES, BENCH.PATH.METRICS, BENCH.PATH.FREETYPE, BENCH.PATH.PICTURES

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "path_detail.hpp"
#include "path_pictures.hpp"
#include "path_rungs.hpp"
#include "rastrules/io/glyph.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/path.hpp"

// A named namespace, not an anonymous one: the JSON conversions that nlohmann's macros define
// for the result structs are partly unused, which clang reports for internal functions.
namespace rastrules::bench::path_ladder {

namespace kp = rastrules::path;
namespace kd = rastrules::path::detail;
namespace op = rastrules::oracle::path;
namespace bp = rastrules::bench::paths;
using rastrules::io::FreeTypeGlyph;
using rastrules::io::Glyph;
using rastrules::io::GlyphBitmap;
using rastrules::io::GlyphError;
using Clock = std::chrono::steady_clock;
using Dense = std::vector<double>;

// The pitch of a 1-bit bitmap w pixels wide, as FreeType's mono bitmaps have it.
std::size_t mono_pitch(std::int32_t w) {
  return (static_cast<std::size_t>(w) + 7) / 8;
}

double median(std::vector<double> v) {
  if (v.empty())
    return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(double v, const char* f = "%.3g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

op::Path to_oracle(const kp::Path& p) {
  op::Path o;
  o.fill_rule = p.fill_rule == kp::FillRule::kEvenOdd ? "evenodd" : "nonzero";
  for (const kp::Contour& c : p.contours) {
    op::Contour oc;
    oc.start = {c.start.x, c.start.y};
    for (const kp::Segment& s : c.segments)
      oc.pieces.push_back(op::Piece{op::PieceKind::kLine, {{s.p[0].x, s.p[0].y}}});
    o.contours.push_back(oc);
  }
  return o;
}

// A scene with FreeType's outlines of its items: the curved one (glyph scenes: the font's own
// outline) and the lines-only one (freetype_outline_of the flattening).
struct Scene {
  bp::PathScene s;
  bool glyphs = false;
  std::vector<FreeTypeGlyph> ft_curved;
  std::vector<FreeTypeGlyph> ft_lines;
};

FreeTypeGlyph outline_or_die(const Glyph& g) {
  auto r = rastrules::io::freetype_outline_of(g);
  if (auto* e = std::get_if<GlyphError>(&r))
    throw std::runtime_error(e->what());
  return std::move(std::get<FreeTypeGlyph>(r));
}

// rule: BENCH.PATH.SCENES
Scene glyph_scene(const std::string& font, const std::string& font_name, const std::u32string& text,
                  int size) {
  Scene sc;
  sc.glyphs = true;
  sc.s.name = font_name + "-" + std::to_string(size);
  sc.s.note = std::to_string(text.size()) + " glyphs";
  for (const char32_t c : text) {
    auto r = rastrules::io::load_freetype_glyph(font, c, size);
    if (auto* e = std::get_if<GlyphError>(&r))
      throw std::runtime_error(e->what());
    FreeTypeGlyph ft = std::move(std::get<FreeTypeGlyph>(r));
    bp::PathItem it;
    it.curved = ft.glyph().path;
    it.lines = bp::flatten(it.curved, bp::kFlattenTolerance);
    it.width = ft.glyph().width;
    it.height = ft.glyph().height;
    sc.ft_lines.push_back(outline_or_die(Glyph{it.lines, it.width, it.height, 0, 0}));
    sc.ft_curved.push_back(std::move(ft));
    sc.s.items.push_back(std::move(it));
  }
  return sc;
}

Scene polygon_scene(std::uint64_t seed, int side) {
  Scene sc;
  sc.s = bp::make_polygon_scene(seed, side);
  for (const bp::PathItem& it : sc.s.items) {
    sc.ft_lines.push_back(outline_or_die(Glyph{it.lines, it.width, it.height, 0, 0}));
    sc.ft_curved.push_back(outline_or_die(Glyph{it.curved, it.width, it.height, 0, 0}));
  }
  return sc;
}

// ---------------------------------------------------------------------------------------------
// Area rungs.

struct AreaRung {
  std::string name;
  std::string what;
  bool slow = false; // timed on fewer repeats
  std::function<void(const bp::PathItem&, const FreeTypeGlyph&, Dense&)> run;
};

std::vector<AreaRung> area_rungs() {
  std::vector<AreaRung> r;
  r.push_back({"ss4", "kernel cover_samples, 4 samples (standard pattern), bits / 4", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 bp::supersample(it.lines, 4, it.width, it.height, out);
               }});
  r.push_back({"ss16", "kernel cover_samples, 16 samples, bits / 16", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 bp::supersample(it.lines, 16, it.width, it.height, out);
               }});
  r.push_back({"float-accum", "signed-area cells in float32", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 bp::accumulate<float>(it.lines, it.width, it.height, out);
               }});
  r.push_back({"fixed-accum", "signed-area cells in 24.8 integers", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 bp::accumulate<std::int64_t>(it.lines, it.width, it.height, out);
               }});
  r.push_back({"freetype-gray", "FreeType's gray raster (8-bit), same lines-only outline", false,
               [](const bp::PathItem& it, const FreeTypeGlyph& ft, Dense& out) {
                 const std::uint8_t* px = ft.raster_gray();
                 out.assign(px, px + static_cast<std::size_t>(it.width) *
                                         static_cast<std::size_t>(it.height));
                 for (double& v : out)
                   v /= 255.0;
               }});
  r.push_back({"exact", "kernel cover_area, exact rationals", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 out.assign(
                     static_cast<std::size_t>(it.width) * static_cast<std::size_t>(it.height), 0.0);
                 for (const kp::AreaCoverage& a : kp::cover_area(it.lines, it.width, it.height))
                   out[static_cast<std::size_t>(a.y) * static_cast<std::size_t>(it.width) +
                       static_cast<std::size_t>(a.x)] = a.area.convert_to<double>();
               }});
  r.push_back({"exact-alpha8", "kernel cover_area_alpha: the exact area's 8-bit alpha", false,
               [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
                 std::vector<std::uint8_t> alpha(static_cast<std::size_t>(it.width) *
                                                 static_cast<std::size_t>(it.height));
                 kp::cover_area_alpha(it.lines, it.width, it.height, alpha);
                 out.assign(alpha.begin(), alpha.end());
                 for (double& v : out)
                   v /= 255.0;
               }});
  r.push_back(
      {"oracle", "CGAL arrangement, exact rationals", true,
       [](const bp::PathItem& it, const FreeTypeGlyph&, Dense& out) {
         out.assign(static_cast<std::size_t>(it.width) * static_cast<std::size_t>(it.height), 0.0);
         for (const op::PixelArea& a : op::cover_area(to_oracle(it.lines), it.width, it.height))
           out[static_cast<std::size_t>(a.y) * static_cast<std::size_t>(it.width) +
               static_cast<std::size_t>(a.x)] = a.approx;
       }});
  return r;
}

// rule: BENCH.PATH.METRICS
struct ErrorFigures {
  double mean = 0; // over the pixels either side covers
  double max = 0;
  std::uint64_t visible = 0;       // |error| > 1/255 + 1e-12
  std::uint64_t on_conflation = 0; // of those, on conflation pixels
  double max_conflation = 0;
};

struct AreaRow {
  std::string rung;
  double seconds = 0; // median per scene (all items)
  int repeats = 0;
  ErrorFigures err;
  std::string note;
};

struct SampleRow {
  double kernel_seconds = 0, bitmap_seconds = 0, mono_seconds = 0;
  int repeats = 0;
  std::uint64_t covered_kernel = 0, covered_mono = 0, differ = 0;
  std::uint64_t near = 0, freetype_only_dropout = 0, freetype_only_other = 0, kernel_only_far = 0;
};

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ErrorFigures, mean, max, visible, on_conflation, max_conflation)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SampleRow, kernel_seconds, bitmap_seconds, mono_seconds, repeats,
                                   covered_kernel, covered_mono, differ, near,
                                   freetype_only_dropout, freetype_only_other, kernel_only_far)

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(AreaRow, rung, note, seconds, repeats, err)

struct SceneResult {
  std::string name, note;
  std::uint64_t items = 0, pixels = 0, segments = 0, touched = 0, conflation = 0;
  std::uint64_t rows_by_cells = 0, rows_by_slabs = 0; // the exact rung's (PATH.AREA.CELLS)
  std::vector<AreaRow> rows;
  std::string curved_exact; // the exact rung on the curved outline
  std::uint64_t oracle_mismatch = 0;
  SampleRow samples;
  // The curved outlines' 8-bit alpha (cover_area_alpha, PATH.AREA.FAST with the exact methods
  // behind it) against FreeType's gray raster on the same curved outlines, alternating; the rows
  // the sweep decided (its whole paths) and those the fast cells decided of the rest, of all
  // rows; pixels whose alpha differs from FreeType's by more than 1.
  double curved_alpha_seconds = 0, curved_gray_seconds = 0;
  std::uint64_t curved_rows = 0, curved_rows_swept = 0, curved_rows_fast = 0,
                curved_alpha_differ = 0;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SceneResult, name, note, items, pixels, segments, touched,
                                   conflation, rows_by_cells, rows_by_slabs, rows, curved_exact,
                                   oracle_mismatch, samples, curved_alpha_seconds,
                                   curved_gray_seconds, curved_rows, curved_rows_swept,
                                   curved_rows_fast, curved_alpha_differ)

// Calls f(a, b) for every segment of the lines-only path, closing lines included (raw).
template <class F> void each_segment(const kp::Path& lines, F&& f) {
  for (const kp::Contour& c : lines.contours) {
    kp::Point a = c.start;
    for (const kp::Segment& s : c.segments) {
      f(a, s.p[0]);
      a = s.p[0];
    }
    f(a, c.start);
  }
}

// Distance (px) from the point (raw) to the nearest segment of the lines-only path.
double distance_to_outline(const kp::Path& lines, double px, double py) {
  double best = 1e300;
  each_segment(lines, [&](kp::Point a, kp::Point b) {
    const double ax = a.x, ay = a.y, dx = b.x - ax, dy = b.y - ay;
    const double len2 = dx * dx + dy * dy;
    const double t =
        std::clamp(len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0, 0.0, 1.0);
    best = std::min(best, std::hypot(ax + t * dx - px, ay + t * dy - py));
  });
  return best / 256.0;
}

// Whether a segment of the lines-only path meets the open pixel (x, y) (Liang-Barsky clip).
bool outline_meets_pixel(const kp::Path& lines, std::int32_t x, std::int32_t y) {
  bool meets = false;
  const double x0 = 256.0 * x, x1 = x0 + 256.0, y0 = 256.0 * y, y1 = y0 + 256.0;
  each_segment(lines, [&](kp::Point a, kp::Point b) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const auto clip = [&](double p, double q) { // keep p t < q
      if (p == 0.0)
        return q > 0.0;
      const double t = q / p;
      if (p < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
      return t0 < t1;
    };
    if (clip(-dx, a.x - x0) && clip(dx, x1 - a.x) && clip(-dy, a.y - y0) && clip(dy, y1 - a.y))
      meets = true;
  });
  return meets;
}

// The curved outlines' alpha against FreeType gray on the same curved outlines (alternating,
// medians), the rows PATH.AREA.FAST decided, and the pixels more than one level apart.
// rule: BENCH.PATH.FREETYPE
void run_curved_alpha(Scene& sc, int repeats, SceneResult& res) {
  std::vector<double> tk, tg;
  std::vector<std::vector<std::uint8_t>> alpha(sc.s.items.size());
  for (std::size_t i = 0; i < sc.s.items.size(); ++i)
    alpha[i].resize(static_cast<std::size_t>(sc.s.items[i].width) *
                    static_cast<std::size_t>(sc.s.items[i].height));
  for (int rep = 0; rep < repeats; ++rep) {
    auto t0 = Clock::now();
    for (std::size_t i = 0; i < sc.s.items.size(); ++i)
      kp::cover_area_alpha(sc.s.items[i].curved, sc.s.items[i].width, sc.s.items[i].height,
                           alpha[i]);
    tk.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    t0 = Clock::now();
    for (const FreeTypeGlyph& ft : sc.ft_curved)
      (void)ft.raster_gray();
    tg.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  res.curved_alpha_seconds = median(tk);
  res.curved_gray_seconds = median(tg);
  for (std::size_t i = 0; i < sc.s.items.size(); ++i) {
    const bp::PathItem& it = sc.s.items[i];
    kd::AreaRows by;
    kd::cover_alpha_by(it.curved, it.width, it.height, kd::AreaMethod::kSweep, alpha[i], &by);
    res.curved_rows += static_cast<std::uint64_t>(it.height);
    res.curved_rows_swept += by.swept;
    res.curved_rows_fast += by.fast;
    const std::uint8_t* g = sc.ft_curved[i].raster_gray();
    for (std::size_t k = 0; k < alpha[i].size(); ++k)
      res.curved_alpha_differ += std::abs(int{alpha[i][k]} - int{g[k]}) > 1 ? 1u : 0u;
  }
}

// The area rungs of one scene: times, errors, conflation pixels, into res.
// rule: BENCH.PATH.METRICS
void run_area(Scene& sc, int repeats, int min_slow_repeats, SceneResult& res) {
  const std::vector<AreaRung> rungs = area_rungs();

  // Exact areas and the conflation pixels (double accumulation off the exact area).
  std::vector<Dense> exact(sc.s.items.size()), acc64(sc.s.items.size());
  std::vector<std::vector<bool>> conflation(sc.s.items.size());
  for (std::size_t i = 0; i < sc.s.items.size(); ++i) {
    const bp::PathItem& it = sc.s.items[i];
    rungs[5].run(it, sc.ft_lines[i], exact[i]);
    bp::accumulate<double>(it.lines, it.width, it.height, acc64[i]);
    conflation[i].assign(exact[i].size(), false);
    for (std::size_t k = 0; k < exact[i].size(); ++k)
      if (std::abs(acc64[i][k] - exact[i][k]) > std::ldexp(1.0, -20)) {
        conflation[i][k] = true;
        ++res.conflation;
      }
  }
  // How the exact rung decided the rows.
  for (const bp::PathItem& it : sc.s.items) {
    kd::AreaRows by;
    kd::cover_area_by(
        it.lines, it.width, it.height, kd::AreaMethod::kCells, [](const kp::AreaCoverage&) {}, &by);
    res.rows_by_cells += by.cells;
    res.rows_by_slabs += by.slabs;
  }
  // The exact rung on the curved outlines (PATH.AREA.CURVE): once, untimed by the ladder's
  // repeats; its time over all the items, and the largest error bound of a pixel.
  res.curved_exact = "lines only: same as exact";
  if (sc.glyphs) {
    boost::multiprecision::cpp_rational worst = 0;
    const auto t0 = Clock::now();
    for (const bp::PathItem& it : sc.s.items)
      for (const kp::AreaCoverage& a : kp::cover_area(it.curved, it.width, it.height))
        worst = std::max(worst, a.error_bound);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    std::ostringstream o;
    o << std::fixed << std::setprecision(1) << ms << " ms once over the curved outlines, largest "
      << "bound " << std::scientific << std::setprecision(2) << worst.convert_to<double>()
      << " px^2 (PATH.AREA.CURVE)";
    res.curved_exact = o.str();
  }
  run_curved_alpha(sc, repeats, res);

  // Timing: every repeat runs every rung once over every item, in turn (alternating).
  std::vector<std::vector<double>> times(rungs.size());
  Dense scratch;
  for (int rep = 0; rep < repeats; ++rep)
    for (std::size_t r = 0; r < rungs.size(); ++r) {
      if (rungs[r].slow && rep >= min_slow_repeats)
        continue;
      const auto t0 = Clock::now();
      for (std::size_t i = 0; i < sc.s.items.size(); ++i)
        rungs[r].run(sc.s.items[i], sc.ft_lines[i], scratch);
      times[r].push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    }

  // Errors (not timed).
  for (std::size_t r = 0; r < rungs.size(); ++r) {
    AreaRow row;
    row.rung = rungs[r].name;
    row.note = rungs[r].what;
    row.seconds = median(times[r]);
    row.repeats = static_cast<int>(times[r].size());
    ErrorFigures e;
    double sum = 0;
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < sc.s.items.size(); ++i) {
      rungs[r].run(sc.s.items[i], sc.ft_lines[i], scratch);
      for (std::size_t k = 0; k < scratch.size(); ++k) {
        if (exact[i][k] == 0.0 && scratch[k] == 0.0)
          continue;
        const double d = std::abs(scratch[k] - exact[i][k]);
        sum += d;
        ++n;
        e.max = std::max(e.max, d);
        if (d > 1.0 / 255.0 + 1e-12) {
          ++e.visible;
          e.on_conflation += conflation[i][k] ? 1u : 0u;
        }
        if (conflation[i][k])
          e.max_conflation = std::max(e.max_conflation, d);
      }
      if (rungs[r].name == "oracle") {
        const auto kernel =
            kp::cover_area(sc.s.items[i].lines, sc.s.items[i].width, sc.s.items[i].height);
        const auto oracle = op::cover_area(to_oracle(sc.s.items[i].lines), sc.s.items[i].width,
                                           sc.s.items[i].height);
        res.oracle_mismatch += kernel.size() == oracle.size() ? 0u : 1u;
        for (std::size_t k = 0; k < std::min(kernel.size(), oracle.size()); ++k) {
          const std::string q = oracle[k].num + (oracle[k].den == "1" ? "" : "/" + oracle[k].den);
          res.oracle_mismatch += (kernel[k].x != oracle[k].x || kernel[k].y != oracle[k].y ||
                                  kernel[k].area.str() != q)
                                     ? 1u
                                     : 0u;
        }
      }
      if (r == 5)
        res.touched = n;
    }
    e.mean = n > 0 ? sum / static_cast<double>(n) : 0.0;
    row.err = e;
    res.rows.push_back(row);
  }
}

// What a run measures: everything, the sample coverage alone, or the curved alpha alone.
enum class Measure { kAll, kSamples, kAlpha };

// rule: BENCH.PATH.METRICS, BENCH.PATH.FREETYPE
SceneResult run_scene(Scene& sc, int repeats, int min_slow_repeats, Measure measure) {
  SceneResult res;
  res.name = sc.s.name;
  res.note = sc.s.note;
  res.items = sc.s.items.size();
  res.pixels = sc.s.pixels();
  res.segments = sc.s.segments();
  if (measure == Measure::kAlpha) {
    run_curved_alpha(sc, repeats, res);
    return res;
  }
  if (measure == Measure::kAll)
    run_area(sc, repeats, min_slow_repeats, res);

  // Sample coverage: the kernel (1 sample at the centre, curves exact) against FreeType's mono
  // raster on the same (curved) outline, alternating: the kernel's list of pixels, and its
  // 1-bit bitmap (PATH.COVER.MONO), FreeType's own output form (buffers sized once, as
  // FreeType's are).
  std::vector<std::vector<std::uint8_t>> bitmaps;
  for (const bp::PathItem& it : sc.s.items)
    bitmaps.emplace_back(mono_pitch(it.width) * static_cast<std::size_t>(it.height));
  const auto draw_bitmaps = [&] {
    for (std::size_t i = 0; i < sc.s.items.size(); ++i) {
      const bp::PathItem& it = sc.s.items[i];
      kp::cover_samples_mono(it.curved, rastrules::FillConvention::kTopLeft, it.width, it.height,
                             bitmaps[i], mono_pitch(it.width));
    }
  };
  std::vector<double> tk, tb, tm;
  for (int rep = 0; rep < repeats; ++rep) {
    auto t0 = Clock::now();
    for (const bp::PathItem& it : sc.s.items)
      (void)kp::cover_samples(it.curved, rastrules::standard_pattern(1),
                              rastrules::FillConvention::kTopLeft, it.width, it.height);
    tk.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    t0 = Clock::now();
    draw_bitmaps();
    tb.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    t0 = Clock::now();
    for (const FreeTypeGlyph& ft : sc.ft_curved)
      (void)ft.raster_mono();
    tm.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  res.samples.kernel_seconds = median(tk);
  res.samples.bitmap_seconds = median(tb);
  res.samples.mono_seconds = median(tm);
  res.samples.repeats = repeats;
  draw_bitmaps();
  GlyphBitmap mono;
  for (std::size_t i = 0; i < sc.s.items.size(); ++i) {
    const bp::PathItem& it = sc.s.items[i];
    std::vector<std::uint8_t> k(
        static_cast<std::size_t>(it.width) * static_cast<std::size_t>(it.height), 0);
    for (const kp::SampleCoverage& s :
         kp::cover_samples(it.curved, rastrules::standard_pattern(1),
                           rastrules::FillConvention::kTopLeft, it.width, it.height))
      k[static_cast<std::size_t>(s.y) * static_cast<std::size_t>(it.width) +
        static_cast<std::size_t>(s.x)] = 1;
    // The bitmap holds the list's pixels (PATH.COVER.MONO); a difference is a kernel defect.
    for (std::int32_t y = 0; y < it.height; ++y)
      for (std::int32_t x = 0; x < it.width; ++x) {
        const bool bit = kp::mono_bit(bitmaps[i], mono_pitch(it.width), x, y);
        if (bit != (k[static_cast<std::size_t>(y) * static_cast<std::size_t>(it.width) +
                      static_cast<std::size_t>(x)] != 0))
          throw std::logic_error("kernel: the mono bitmap differs from the pixel list at (" +
                                 std::to_string(x) + ", " + std::to_string(y) + ") of " +
                                 sc.s.name);
      }
    sc.ft_curved[i].render_mono(mono);
    // Distances to the outline: the curved outline flattened finely.
    const kp::Path fine = bp::flatten(it.curved, 1.0 / 1024.0);
    for (std::int32_t y = 0; y < it.height; ++y)
      for (std::int32_t x = 0; x < it.width; ++x) {
        const std::size_t idx = static_cast<std::size_t>(y) * static_cast<std::size_t>(it.width) +
                                static_cast<std::size_t>(x);
        const bool kc = k[idx] != 0, fc = mono.at(x, y) != 0;
        res.samples.covered_kernel += kc ? 1 : 0;
        res.samples.covered_mono += fc ? 1 : 0;
        if (kc == fc)
          continue;
        ++res.samples.differ;
        const double d = distance_to_outline(fine, 256.0 * x + 128.0, 256.0 * y + 128.0);
        if (d <= 1.0 / 32.0)
          ++res.samples.near;
        else if (!fc)
          ++res.samples.kernel_only_far;
        else if (outline_meets_pixel(fine, x, y))
          ++res.samples.freetype_only_dropout;
        else
          ++res.samples.freetype_only_other;
      }
  }
  return res;
}

std::string seconds_text(double s) {
  if (s >= 1.0)
    return fmt(s, "%.3g s");
  if (s >= 1e-3)
    return fmt(s * 1e3, "%.3g ms");
  return fmt(s * 1e6, "%.3g us");
}

// rule: BENCH.PATH.METRICS
std::string markdown(const std::vector<SceneResult>& results, const std::string& header) {
  std::ostringstream o;
  o << header << "\n";
  const bool areas = std::any_of(results.begin(), results.end(),
                                 [](const SceneResult& r) { return !r.rows.empty(); });
  if (areas) {
    o << "## Area coverage: error against the exact area, and time\n\n";
    o << "Every area rung fills the lines-only flattening of the scene (curves flattened to chords "
         "within 1/64 px, points on the 26.6 grid): exact curve areas are not built. Error: |rung "
         "- "
         "exact| per pixel over the pixels either covers; visible: > 1/255; conflation pixels: "
         "where signed-area accumulation in float64 is off the exact area by more than 2^-20 px^2 "
         "(several windings meet in the pixel). Time: median per scene, rungs alternating.\n\n";
    for (const SceneResult& r : results) {
      if (r.rows.empty())
        continue;
      o << "### " << r.name << " (" << r.note << "; " << r.segments << " line segments, "
        << r.pixels << " pixels, " << r.touched << " covered, " << r.conflation
        << " conflation pixels; exact rows: " << r.rows_by_cells << " by cells, " << r.rows_by_slabs
        << " by slabs)\n\n";
      o << "| rung | time | x exact's time | mean error | max error | visible errors | on "
           "conflation pixels | max error on conflation pixels |\n";
      o << "|---|---|---|---|---|---|---|---|\n";
      double exact_s = 0;
      for (const AreaRow& row : r.rows)
        if (row.rung == "exact")
          exact_s = row.seconds;
      for (const AreaRow& row : r.rows) {
        const ErrorFigures& e = row.err;
        o << "| " << row.rung << " | " << seconds_text(row.seconds) << " | "
          << (exact_s > 0 ? fmt(row.seconds / exact_s) : "-") << " | " << fmt(e.mean) << " | "
          << fmt(e.max) << " | " << e.visible << " | " << e.on_conflation << " | "
          << fmt(e.max_conflation) << " |\n";
      }
      o << "| exact (curved outline) | " << r.curved_exact << " | | | | | | |\n\n";
      if (r.oracle_mismatch != 0)
        o << "**oracle and kernel areas differ on " << r.oracle_mismatch << " pixels**\n\n";
      else
        o << "oracle == exact on every pixel (rationals compared).\n\n";
    }
  }
  const bool samples = std::any_of(results.begin(), results.end(),
                                   [](const SceneResult& r) { return r.samples.repeats > 0; });
  if (samples) {
    o << "## Sample coverage: the kernel against FreeType's monochrome raster\n\n";
    o << "Same outlines, curves kept (the kernel decides curves exactly; FreeType flattens them). "
         "One sample at the pixel centre, top-left rule; FreeType mono has dropout control and its "
         "own boundary rule. Differing pixels: near (the centre within 1/32 px of the outline: "
         "the boundary rule, FreeType's rounding and curve flattening); FreeType only, the outline "
         "meets the pixel but the centre is outside (dropout control: thin parts, and coincident "
         "edges under evenodd); FreeType only, elsewhere; kernel only, farther than 1/32 px.\n\n";
    o << "Kernel times: the list of covered pixels (cover_samples) and the 1-bit bitmap "
         "(cover_samples_mono, FreeType mono's own output form).\n\n";
    o << "| scene | kernel list | kernel bitmap | FreeType mono | list / mono | bitmap / mono | "
         "covered (kernel, mono) | differ | near | FreeType only, dropout | FreeType only, other | "
         "kernel only |\n";
    o << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SceneResult& r : results) {
      const SampleRow& s = r.samples;
      o << "| " << r.name << " | " << seconds_text(s.kernel_seconds) << " | "
        << seconds_text(s.bitmap_seconds) << " | " << seconds_text(s.mono_seconds) << " | "
        << fmt(s.mono_seconds > 0 ? s.kernel_seconds / s.mono_seconds : 0) << " | "
        << fmt(s.mono_seconds > 0 ? s.bitmap_seconds / s.mono_seconds : 0) << " | "
        << s.covered_kernel << ", " << s.covered_mono << " | " << s.differ << " | " << s.near
        << " | " << s.freetype_only_dropout << " | " << s.freetype_only_other << " | "
        << s.kernel_only_far << " |\n";
    }
  }
  const bool curved = std::any_of(results.begin(), results.end(),
                                  [](const SceneResult& r) { return r.curved_rows > 0; });
  if (curved) {
    o << "\n## Curved outlines: exact alpha against FreeType's gray raster (same curved "
         "outlines)\n\n";
    o << "The kernel's cover_area_alpha (the certified sweep, PATH.AREA.SWEEP; for the rows it "
         "leaves, certified floating-point cells, PATH.AREA.FAST, the exact methods behind them) "
         "and FreeType gray on the same curved outlines, alternating. Rows: those the sweep "
         "decided, and those the fast cells decided of the rest, of all rows. Differ: pixels more "
         "than one level apart (FreeType flattens curves and accumulates signed areas).\n\n";
    o << "| scene | exact alpha | FreeType gray | alpha / gray | rows swept, fast | differ > 1 "
         "|\n"
         "|---|---|---|---|---|---|\n";
    for (const SceneResult& r : results) {
      if (r.curved_rows == 0)
        continue;
      o << "| " << r.name << " | " << seconds_text(r.curved_alpha_seconds) << " | "
        << seconds_text(r.curved_gray_seconds) << " | "
        << fmt(r.curved_gray_seconds > 0 ? r.curved_alpha_seconds / r.curved_gray_seconds : 0)
        << " | " << r.curved_rows_swept << ", " << r.curved_rows_fast << " / " << r.curved_rows
        << " | " << r.curved_alpha_differ << " |\n";
    }
  }
  if (!areas)
    return o.str();
  o << "\n## Exact area against FreeType's gray raster (time ratio, same lines-only outlines)\n\n";
  o << "| scene | exact | exact-alpha8 | freetype-gray | exact / gray | exact-alpha8 / gray |\n"
       "|---|---|---|---|---|---|\n";
  for (const SceneResult& r : results) {
    double ex = 0, al = 0, gr = 0;
    for (const AreaRow& row : r.rows) {
      if (row.rung == "exact")
        ex = row.seconds;
      if (row.rung == "exact-alpha8")
        al = row.seconds;
      if (row.rung == "freetype-gray")
        gr = row.seconds;
    }
    o << "| " << r.name << " | " << seconds_text(ex) << " | " << seconds_text(al) << " | "
      << seconds_text(gr) << " | " << fmt(gr > 0 ? ex / gr : 0) << " | "
      << fmt(gr > 0 ? al / gr : 0) << " |\n";
  }
  return o.str();
}

nlohmann::json to_json(const std::vector<SceneResult>& results, int repeats) {
  nlohmann::json j;
  j["freetype"] = FreeTypeGlyph::freetype_version();
  j["repeats"] = repeats;
  j["flatten_tolerance_px"] = bp::kFlattenTolerance;
  j["scenes"] = results;
  return j;
}

// Writes the image as a PNG file; returns 0, or 2 with a one-line error.
int write_png_file(const std::string& file, const rastrules::io::Image& im) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr) {
    std::cerr << "rastrules_path_ladder: cannot write " << file << "\n";
    return 2;
  }
  const std::optional<std::string> err = rastrules::io::write_png(f, im);
  if (std::fclose(f) != 0 || err) {
    std::cerr << "rastrules_path_ladder: cannot write " << file << (err ? ": " + *err : "") << "\n";
    return 2;
  }
  return 0;
}

} // namespace rastrules::bench::path_ladder

int main(int argc, char** argv) {
  using namespace rastrules::bench::path_ladder;
  bool quick = false;
  Measure measure = Measure::kAll;
  int repeats = 0;
  std::string json_path, plot_path, picture_path, scene_prefix;
  std::string dejavu = RASTRULES_FONT_DEJAVU, cubic = RASTRULES_FONT_CUBIC;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "rastrules_path_ladder: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick")
      quick = true;
    else if (a == "--samples-only")
      measure = Measure::kSamples;
    else if (a == "--alpha-only")
      measure = Measure::kAlpha;
    else if (a == "--repeats")
      repeats = std::atoi(value().c_str());
    else if (a == "--json")
      json_path = value();
    else if (a == "--plot")
      plot_path = value();
    else if (a == "--picture")
      picture_path = value();
    else if (a == "--dejavu")
      dejavu = value();
    else if (a == "--cubic")
      cubic = value();
    else if (a == "--scenes")
      scene_prefix = value();
    else {
      std::cerr << "rastrules_path_ladder: unknown argument '" << a << "'\n";
      return 2;
    }
  }
  if (repeats <= 0)
    repeats = quick ? 1 : 21;
  try {
    if (!picture_path.empty()) {
      std::vector<std::string> differing;
      const rastrules::io::Image im = bp::conflation_picture(differing);
      for (const std::string& d : differing)
        std::cout << d << "\n";
      return write_png_file(picture_path, im);
    }
    const std::u32string text = U"ag&@8eS%";
    std::vector<Scene> scenes;
    const std::vector<int> sizes = quick ? std::vector<int>{12} : std::vector<int>{12, 24, 48, 64};
    for (const int size : sizes)
      scenes.push_back(glyph_scene(dejavu, "dejavu", quick ? U"a" : text, size));
    // The cubics at one size, or (one comparison alone, where they cost little) at every size.
    for (const int size : measure != Measure::kAll ? sizes : std::vector<int>{quick ? 12 : 24})
      scenes.push_back(glyph_scene(cubic, "nimbus-cubic", quick ? U"S" : text, size));
    scenes.push_back(polygon_scene(1, quick ? 16 : 64));
    std::erase_if(scenes, [&](const Scene& sc) { return sc.s.name.rfind(scene_prefix, 0) != 0; });
    if (scenes.empty()) {
      std::cerr << "rastrules_path_ladder: no scene's name begins with '" << scene_prefix << "'\n";
      return 2;
    }
    std::vector<SceneResult> results;
    for (Scene& sc : scenes) {
      std::cerr << "scene " << sc.s.name << "\n";
      results.push_back(run_scene(sc, repeats, quick ? 1 : 3, measure));
    }
    std::ostringstream header;
    header << "# Path ladder: what accuracy costs for 2D paths\n\nFreeType "
           << FreeTypeGlyph::freetype_version() << "; " << repeats
           << " repeats a rung (oracle: " << (quick ? 1 : 3) << "), alternating; medians.\n";
    std::cout << markdown(results, header.str());
    if (!plot_path.empty()) {
      std::vector<bp::PlotPoint> points;
      for (const SceneResult& r : results)
        for (const AreaRow& row : r.rows)
          points.push_back({r.name, row.rung, row.seconds, row.err.mean});
      if (const int rc = write_png_file(plot_path, bp::ladder_plot(points)); rc != 0)
        return rc;
    }
    if (!json_path.empty()) {
      std::ofstream out(json_path);
      out << to_json(results, repeats).dump(2) << "\n";
      if (!out) {
        std::cerr << "rastrules_path_ladder: cannot write " << json_path << "\n";
        return 2;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "rastrules_path_ladder: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
