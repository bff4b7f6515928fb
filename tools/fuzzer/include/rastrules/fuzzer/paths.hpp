// SPDX-License-Identifier: MIT
// The 2D campaign (spec/driver.md FUZZ.PATH.*): seeded path generators that find the known
// classes of 2D-library differences fast, the comparison of a library's raster with the exact
// path coverage that knows what is legal (boundary ties, the library's grid, 8-bit quantisation
// within a stated tolerance) and classifies every larger difference, shrinking to a minimal
// path, and the report.
// Implements: FUZZ.PATH.GENERATE, FUZZ.PATH.COMPARE, FUZZ.PATH.CLASSIFY, FUZZ.PATH.SHRINK,
//             FUZZ.PATH.REPORT

#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::fuzzer::paths {

// The path families, in the order generate_path_case() draws from them (FUZZ.PATH.GENERATE).
// rule: FUZZ.PATH.GENERATE
inline constexpr std::array<std::string_view, 9> kPathFamilies = {
    "polygon",   // random simple or self-intersecting polygons, 3-8 vertices
    "overlap",   // two or three contours overlapping inside a few pixels
    "twice",     // one contour drawn twice, the same or the opposite way
    "doubled",   // a contour that runs back along itself (a doubled-back edge)
    "stack",     // 6-20 thin contours crossing one pixel: windings up to 20
    "cusp",      // cubics with cusps and loops, quadratics folded back
    "near-flat", // curves whose control points are almost on their chord
    "ties",      // edges and vertices on pixel centres and grid lines
    "glyph",     // a glyph of DejaVu Sans (quadratics) or Nimbus Sans (cubics) at 6-14 px
};

// The families generate_path_case() draws for a driver: those of kPathFamilies (or of `only`)
// that it can draw (no curves: no "cusp", "near-flat", "glyph"; "glyph" also needs the fonts of
// the build, read through FreeType).
// rule: FUZZ.PATH.GENERATE
[[nodiscard]] std::vector<std::string_view>
available_path_families(const driver::DriverInfo& info, const std::vector<std::string>& only = {});

// A generated case: the scene (one path primitive) and its family.
struct PathCase {
  Scene scene;
  std::string family;
};

// Returns case `index` of the campaign with seed `seed` for a driver: the same (seed, index, what
// the driver supports) always gives the same scene. Coverage "samples" or "area" as the driver
// draws them (both: alternating by index), fill rules it has, curves only when it draws them,
// every control point on its grid. `only` restricts the families (names of kPathFamilies).
// nullopt when no family can be drawn by the driver.
// rule: FUZZ.PATH.GENERATE
[[nodiscard]] std::optional<PathCase> generate_path_case(std::uint64_t seed, std::uint64_t index,
                                                         const driver::DriverInfo& info,
                                                         const std::vector<std::string>& only = {});

// The classes of a pixel whose value differs from the exact one beyond what is legal
// (FUZZ.PATH.CLASSIFY), in the order they are tried.
// rule: FUZZ.PATH.CLASSIFY
enum class DiffClass {
  kBoundaryTie,     // aliased: the pixel centre on the boundary, decided by another convention
  kConflation,      // several windings in one pixel: the signed-area sum explains it
  kWindingOverflow, // a winding number of 8 or more, wrapped in 4 bits, explains it
  kFillRule,        // the exact coverage under the other fill rule explains it
  kGridSnapping,    // the exact answer on the path snapped to 26.6 or 1/16 px explains it
  kFlattening,      // next to a curve: its flattening explains it
  kDropout,         // aliased: a pixel the boundary passes through added (dropout control)
  kOther,
};
[[nodiscard]] std::string_view to_string(DiffClass c); // "boundary tie", "conflation", ...
inline constexpr std::size_t kDiffClassCount = 8;

// One pixel that differs beyond what is legal.
struct PixelDiff {
  std::uint32_t prim = 0;
  std::int32_t x = 0, y = 0;
  int expected = 0; // aliased: 0/1; antialiased: the exact area's 8-bit alpha
  int actual = 0;   // the library's
  DiffClass klass = DiffClass::kOther;
  std::string why; // the model that explained it, e.g. "windings {0: 1/2, 1: 1/4, 2: 1/4}"
};

// How the comparison judges alpha (FUZZ.PATH.COMPARE).
struct PathCompareOptions {
  // A library's alpha A is legal when |A - round(255 a)| <= alpha_tolerance for the exact area a:
  // 8-bit quantisation (1: rounding or truncation) plus the library's stated error.
  int alpha_tolerance = 1;
  // Legal mode: an aliased pixel whose centre is on the boundary may be decided by any of the
  // four conventions of PATH.SAMPLE.TIE (counted, not a difference); exact mode: the scene's.
  bool legal = true;
};

struct PathComparison {
  bool match = true;
  bool antialiased = false;
  std::uint64_t pixels = 0;     // pixels compared (the target's, per path)
  std::uint64_t legal_ties = 0; // aliased pixels that differ only by the boundary convention
  // Aliased: the pixels whose centre the four conventions of PATH.SAMPLE.TIE decide differently,
  // and the conventions (bit k: FillConvention k) that give the library's answer on all of them.
  std::uint64_t tie_pixels = 0;
  std::uint8_t conventions = 0xF;
  std::uint64_t within = 0;     // antialiased pixels that differ within the tolerance
  int max_alpha_error = 0;      // the largest |A - exact alpha| seen, legal or not
  std::vector<PixelDiff> diffs; // every pixel beyond what is legal
  std::array<std::uint64_t, kDiffClassCount> by_class{};
  // Per primitive, the exact and the library's raster (w * h, row by row: 0/1 or alpha).
  std::vector<std::vector<std::uint8_t>> expected, actual;
  // The case's class: the most frequent class among diffs (ties: the earlier class).
  [[nodiscard]] DiffClass main_class() const;
};

// Compares a library's fragments (DRIVER.PATH.LIBRARY) for a scene of path primitives with the
// exact coverage, classifying every difference beyond what is legal. nullopt and *error when the
// kernel rejects the scene.
// rule: FUZZ.PATH.COMPARE, FUZZ.PATH.CLASSIFY
[[nodiscard]] std::optional<PathComparison> compare_paths(const Scene& scene,
                                                          const std::vector<Fragment>& actual,
                                                          const PathCompareOptions& options,
                                                          std::string* error);

// Returns a minimal scene for which still_differs() holds, from `scene` (for which it holds):
// fewest contours, then fewest segments, curves made lines or quadratics, then simplest
// coordinates (integers, halves, a grid step toward the path's first point), the path moved
// toward the origin, the smallest target holding it. `grid` is the raw step every coordinate
// must stay a multiple of (the library's grid_raw). Deterministic.
// rule: FUZZ.PATH.SHRINK
[[nodiscard]] Scene shrink_path(const Scene& scene, std::int32_t grid,
                                const std::function<bool(const Scene&)>& still_differs);

// Campaign settings (rastrules fuzz2d).
struct PathSettings {
  std::string driver_name;
  std::uint64_t seed = 1;
  std::uint64_t cases = 100;
  std::string out_dir; // empty: write nothing
  std::vector<std::string> families;
  PathCompareOptions compare;
  std::uint64_t max_findings = 8; // findings shrunk and written per class
};

struct PathFinding {
  std::uint64_t case_index = 0;
  std::string family;
  DiffClass klass = DiffClass::kOther;
  Scene original, shrunk;
  PathComparison comparison; // of the shrunk scene
  std::string scene_file, shrunk_file, picture_file;
};

struct PathSummary {
  std::uint64_t cases = 0, skipped = 0, mismatches = 0;
  std::uint64_t pixels = 0, legal_ties = 0, within = 0;
  std::uint64_t tie_pixels = 0;   // aliased pixels the conventions decide differently
  std::uint8_t conventions = 0xF; // the conventions consistent with every one of them
  int max_alpha_error = 0;
  std::array<std::uint64_t, kDiffClassCount> cases_by_class{};  // by the case's main class
  std::array<std::uint64_t, kDiffClassCount> pixels_by_class{}; // every differing pixel
  std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> families; // cases, mismatches
  std::vector<PathFinding> findings; // shrunk, at most max_findings a class
  double seconds = 0;                // the whole campaign
  double driver_seconds = 0;         // in the library's draw()
  double reference_seconds = 0;      // in the exact kernel, the same scenes
  std::string error;                 // non-empty: stopped on a driver error
  bool interrupted = false;          // SIGINT or SIGTERM: stopped between cases
};

// Runs a campaign against one library and writes DIR/report.json, the findings' scenes and
// pictures when settings.out_dir is set.
// rule: FUZZ.PATH.GENERATE, FUZZ.PATH.SHRINK, FUZZ.PATH.REPORT
[[nodiscard]] PathSummary run_path_fuzz(driver::Driver& driver, const PathSettings& settings);

// Prints the summary: cases, differences by class, the speed against the exact kernel.
// rule: FUZZ.PATH.REPORT
void print_path_summary(std::FILE* out, const PathSettings& settings,
                        const driver::DriverInfo& info, const PathSummary& s);

// Writes expected | actual | difference of one path primitive, magnified, as a PNG.
// rule: FUZZ.PATH.REPORT
[[nodiscard]] std::optional<std::string>
write_path_picture(const std::string& file, const Scene& scene, const PathComparison& c);

} // namespace rastrules::fuzzer::paths

namespace rastrules::fuzzer::paths {

// What `rastrules probe` finds out about a 2D library from dedicated path scenes
// (FUZZ.PATH.PROBE). Every field is measured, not taken from the driver's declaration.
struct PathProbeReport {
  // Aliased: whether a pixel centre exactly on a left, right, top or bottom edge of an axis-
  // aligned rectangle is covered, for both orientations of the contour (cw, ccw), and the name
  // of the convention when both agree and one of PATH.SAMPLE.TIE's four fits.
  std::array<bool, 4> on_edge_cw{}, on_edge_ccw{}; // left, right, top, bottom
  std::string convention;
  // Aliased: the largest distance e (1/256 px) at which a vertical edge moved off a pixel centre
  // still decides the centre as an edge exactly on it does (0: none, the library resolves
  // 1/256 px), and the grid that implies.
  std::int32_t snap_extent = 0;
  std::string grid;
  // Antialiased: the distinct alphas of pixel coverage as a vertical (horizontal) edge moves
  // across the pixel in 65 steps of 1/64 px, and the method they imply.
  int levels_x = 0, levels_y = 0;
  int max_edge_error = 0; // the largest |alpha - exact alpha| on those edges
  std::string aa_method;
  std::string quantisation; // how an exact area a becomes alpha, among the usual formulas
  int twice_evenodd = -1;   // alpha of a half pixel drawn twice under even-odd (exact 0)
  int quadratic = -1;       // alpha between a quadratic and its chord (exact 85), -1: no curves
  std::string error;        // non-empty: a draw failed
};

// Probes a 2D library driver (info().paths.any()): a handful of scenes, each holding many paths.
// rule: FUZZ.PATH.PROBE
[[nodiscard]] PathProbeReport probe_path_library(driver::Driver& driver);

} // namespace rastrules::fuzzer::paths
