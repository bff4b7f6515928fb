// SPDX-License-Identifier: MIT
// The precision ladder (spec/bench.md BENCH.*): the same scenes rasterized by comparators of
// increasing precision, the kernel and the exact oracle, with what each costs in time and what
// it gets wrong. Rungs other than `reference`, `reference-fast` and `exact` are comparators,
// not the product: they live here, never in kernel/.
// Implements: BENCH.LADDER.RUNGS, BENCH.LADDER.SCENES, BENCH.METRIC.THROUGHPUT,
//             BENCH.METRIC.ERROR, BENCH.METRIC.WATERTIGHT, BENCH.METRIC.TRANSLATION, BENCH.REPORT

#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rastrules/name_table.hpp"

namespace rastrules::bench {

// rule: BENCH.LADDER.RUNGS
enum class Rung {
  kFloat,
  kFloatSimd,
  kDouble,
  kScanline,
  kFixed4I32,
  kReference,
  kReferenceFast,
  kFixed16I128,
  kExact,
  kLimit,
};
} // namespace rastrules::bench

namespace rastrules {
template <> struct Names<bench::Rung> {
  static constexpr auto table =
      in_enum_order<bench::Rung>({"float", "float-simd", "double", "scanline", "fixed4-i32",
                                  "reference", "reference-fast", "fixed16-i128", "exact", "limit"});
};
} // namespace rastrules

namespace rastrules::bench {
using rastrules::to_string; // "float", "double", ..., "limit"
[[nodiscard]] std::optional<Rung> parse_rung(std::string_view name);
// Every rung in ladder order (float .. exact, then limit).
[[nodiscard]] const std::vector<Rung>& all_rungs();
// Whether the rung yields coverage (every rung but `limit`, which only counts).
[[nodiscard]] bool has_coverage(Rung r);

using FloatTriangle = std::array<std::array<float, 2>, 3>;

// A scene of the ladder: triangles in window coordinates (pixels, float32) in a target of
// width x height. A mesh covers the rectangle [rect_x0, rect_x1) x [rect_y0, rect_y1) exactly
// (BENCH.METRIC.WATERTIGHT: the pixel centres in it are the ones a correct rule draws once).
// rule: BENCH.LADDER.SCENES
struct LadderScene {
  std::string name; // "small", "medium", "large", "hard", "translate"
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<FloatTriangle> triangles;
  // The same coordinates, six floats a triangle, as the kernel's batch counter reads them
  // (raster::fast_count_batch); flatten() fills it. Kept in the scene so that the timed
  // reference-fast rung does not time a copy.
  std::vector<float> xy;
  bool is_mesh = false;
  double rect_x0 = 0, rect_y0 = 0, rect_x1 = 0, rect_y1 = 0;
};

// The triangles' coordinates, six floats a triangle; flatten(s) sets s.xy to them.
[[nodiscard]] std::vector<float> flat_coordinates(const std::vector<FloatTriangle>& triangles);
void flatten(LadderScene& s);

// A seeded mesh: (cols + 1) x (rows + 1) grid vertices `cell` pixels apart starting at
// (x0, y0), interior vertices jittered by up to `jitter` * cell on the 1/256 grid, boundary
// vertices moved only along the rectangle's side (corners fixed), each cell split into two
// triangles along a diagonal chosen by the seed. All triangles run clockwise.
// rule: BENCH.LADDER.SCENES
[[nodiscard]] LadderScene make_mesh(std::string name, std::uint64_t seed, std::int32_t cols,
                                    std::int32_t rows, double cell, double jitter, double x0,
                                    double y0, std::int32_t width, std::int32_t height);
// The tie-heavy mesh: vertices on pixel centres (diagonals through pixel centres), rows of
// slivers 1/256, 3/256 and 1/16 px tall, all on the 1/256 grid.
[[nodiscard]] LadderScene make_hard_mesh(std::int32_t cols, std::int32_t rows, std::int32_t cell);
// The scene moved by (t, t) pixels in a target of width x height.
[[nodiscard]] LadderScene translated(const LadderScene& s, std::int32_t t, std::int32_t width,
                                     std::int32_t height);

// Covered (triangle, pixel) pairs as keys: triangle << 32 | y << 16 | x, ascending.
using Coverage = std::vector<std::uint64_t>;
[[nodiscard]] constexpr std::uint64_t coverage_key(std::uint32_t tri, std::int32_t x,
                                                   std::int32_t y) {
  return (std::uint64_t{tri} << 32) | (static_cast<std::uint64_t>(y) << 16) |
         static_cast<std::uint64_t>(x);
}

// Runs a rung over the scene: returns the number of covered (triangle, pixel) pairs, and with
// out != nullptr also appends them (not for kLimit). Timed code and checked code are the same.
// rule: BENCH.LADDER.RUNGS
std::uint64_t run_rung(Rung r, const LadderScene& s, Coverage* out);

// The decisions of a scene: pixels of each triangle's bounding box (of the vertices snapped to
// 1/256 px, as the reference sees them) clipped to the target.
// rule: BENCH.METRIC.THROUGHPUT
[[nodiscard]] std::uint64_t count_decisions(const LadderScene& s);

// The number of keys in exactly one of a and b (both ascending).
// rule: BENCH.METRIC.ERROR
[[nodiscard]] std::uint64_t symmetric_difference(const Coverage& a, const Coverage& b);

// Pixels of the mesh's rectangle drawn zero times or twice or more. Preconditions: s.is_mesh.
// rule: BENCH.METRIC.WATERTIGHT
[[nodiscard]] std::uint64_t watertight_violations(const LadderScene& s, const Coverage& c);

// The coverage shifted by (-t, -t) (keys whose pixel would leave the 16-bit range are kept out).
// rule: BENCH.METRIC.TRANSLATION
[[nodiscard]] Coverage shifted_back(const Coverage& c, std::int32_t t);

// One point of the translation sweep for one rung.
struct SweepPoint {
  std::int64_t t = 0;
  std::uint64_t errors = 0;      // vs exact at t
  std::uint64_t watertight = 0;  // on the translated mesh
  std::uint64_t translation = 0; // vs its own result at t = 0, shifted
};
// The largest t of the sweep (ascending t, t = 0 first) with no error, watertightness or
// translation violation at every t' <= t; nullopt when already t = 0 fails.
// rule: BENCH.METRIC.TRANSLATION
[[nodiscard]] std::optional<std::int64_t> exact_range(const std::vector<SweepPoint>& sweep);

// The median of the values (the mean of the middle two for an even count). Preconditions: not
// empty.
[[nodiscard]] double median(std::vector<double> v);

// Per rung and scene family.
struct FamilyResult {
  std::string scene;
  std::uint64_t triangles = 0;
  std::uint64_t decisions = 0;
  std::uint64_t covered = 0;
  int repeats = 0;
  double seconds = 0; // median of repeats
  double decisions_per_second = 0;
  double triangles_per_second = 0;
  double ratio_to_reference = 0;           // decisions per second / the reference's
  std::optional<std::uint64_t> errors;     // vs exact (nullopt for limit)
  std::optional<std::uint64_t> watertight; // nullopt for limit
};

struct RungResult {
  Rung rung = Rung::kReference;
  std::vector<FamilyResult> families; // in the order of LadderConfig's scenes
  std::vector<SweepPoint> sweep;      // empty for limit
  std::optional<std::int64_t> range;  // exact range
  std::uint64_t total_decisions = 0;  // over the timed families
  std::uint64_t total_errors = 0;
  std::uint64_t total_watertight = 0;
  [[nodiscard]] double error_fraction() const {
    return total_decisions == 0
               ? 0.0
               : static_cast<double>(total_errors) / static_cast<double>(total_decisions);
  }
  // decisions per second relative to the reference on the "medium" scene (1 for reference)
  [[nodiscard]] double medium_ratio() const;
};

// What lavapipe did on the small mesh (BENCH.LAVAPIPE), filled in by the caller.
struct LavapipeFigure {
  bool available = false;
  std::string why_not;
  std::string device;
  std::string includes;
  int repeats = 0;
  double seconds = 0;
  std::uint64_t samples_passed = 0;
  std::uint64_t triangles = 0;
  unsigned threads = 0;       // lavapipe's rasterizer threads (0: unknown)
  std::string threads_source; // where that figure comes from
};

// Returns lavapipe's rasterizer thread count and where it comes from: LP_NUM_THREADS when set
// (an integer in [0, 256]; 0 means llvmpipe rasterizes on the calling thread, counted as 1),
// else the number of online processors, llvmpipe's default (BENCH.LAVAPIPE).
// rule: BENCH.LAVAPIPE
[[nodiscard]] std::pair<unsigned, std::string> lavapipe_threads();

struct LadderConfig {
  bool quick = false;
  std::uint64_t seed = 1;
  double min_seconds = 0.2; // per rung and scene, repeated until reached (quick: 0.02)
  unsigned threads = 1;     // threads of the `reference-fast xN` figure (BENCH.METRIC.THROUGHPUT)
};

// reference-fast on `threads` threads kept between calls (a persistent pool of standard-library
// threads, created once, like a driver's): each call splits the scene's triangles into 16
// contiguous chunks a thread, which the calling thread and the workers claim from one counter
// (so a worker the system does not schedule holds nothing up), counts each with the kernel's
// batch counter and adds the chunk counts in chunk order. Equal to run_rung(kReferenceFast, s,
// nullptr) for every thread count. A thread that cannot be created leaves fewer workers.
// rule: BENCH.METRIC.THROUGHPUT
class FastPool {
public:
  explicit FastPool(unsigned threads);
  ~FastPool();
  FastPool(const FastPool&) = delete;
  FastPool& operator=(const FastPool&) = delete;
  [[nodiscard]] unsigned threads() const;
  [[nodiscard]] std::uint64_t count(const LadderScene& s);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One FastPool(threads).count(s): threads created for this call only.
// rule: BENCH.METRIC.THROUGHPUT
[[nodiscard]] std::uint64_t run_reference_fast_threaded(const LadderScene& s, unsigned threads);

struct LadderReport {
  LadderConfig config;
  std::string date;      // UTC, ISO 8601
  std::string cpu;       // /proc/cpuinfo model name
  std::string isa;       // best_isa() of this processor
  std::string limit_isa; // what the limit rung ran
  int batch_lanes = 1;   // pixels a chunk of the batch counter's row loop (16, 8 or 1)
  int limit_lanes = 1;   // pixels a chunk of the limit rung's loop
  unsigned threads = 1;
  std::vector<std::string> scenes; // timed families
  std::vector<std::int64_t> sweep_t;
  std::string sweep_note;
  std::uint64_t reference_small_covered = 0;
  std::vector<RungResult> rungs;
  // reference-fast on config.threads threads, per timed scene (empty when the fast traversal is
  // not built); its errors, watertightness and exact range are reference-fast's.
  std::vector<FamilyResult> fast_threaded;
  LavapipeFigure lavapipe;
  double seconds_total = 0;
  [[nodiscard]] const RungResult* find(Rung r) const;
};

// The scenes of a configuration: timed families then the translation base mesh.
struct LadderScenes {
  std::vector<LadderScene> timed;  // small, medium, large, hard
  LadderScene translate_base;      // at t = 0 in the sweep's target
  std::vector<std::int32_t> sweep; // 0, 1, 2, 4, ..., top
};
[[nodiscard]] LadderScenes make_scenes(const LadderConfig& c);

// Runs the whole ladder. lavapipe(scene) times the small mesh with lavapipe (may be empty: the
// report then says lavapipe was not run). progress (may be empty) receives one line per step.
using LavapipeTimer = std::function<LavapipeFigure(const LadderScene&)>;
[[nodiscard]] LadderReport run_ladder(const LadderConfig& c, const LavapipeTimer& lavapipe,
                                      const std::function<void(const std::string&)>& progress);

// One line per speed target of BENCH.TARGETS: whether this run met it.
struct TargetCheck {
  std::string name;
  std::string measured;
  std::optional<bool> met; // nullopt: could not be measured
};
// rule: BENCH.TARGETS
[[nodiscard]] std::vector<TargetCheck> check_targets(const LadderReport& r);

// rule: BENCH.REPORT
[[nodiscard]] std::string to_markdown(const LadderReport& r);
[[nodiscard]] std::string to_json(const LadderReport& r);

// The plot (BENCH.REPORT): RGB rows, top first, 3 bytes per pixel.
struct Plot {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
  [[nodiscard]] std::array<std::uint8_t, 3> at(int x, int y) const;
};
[[nodiscard]] Plot make_plot(const LadderReport& r);

} // namespace rastrules::bench
