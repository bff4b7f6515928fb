// SPDX-License-Identifier: MIT
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, FAST.THREADS.DETERMINISTIC

#include "fast_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include "count.hpp"
#include "rastrules/parallel.hpp"
#include "rastrules/raster/fast_batch.hpp"

namespace rastrules::cli {
namespace {

// Pixels of the work bound (load_fast_form's) a unit holds. Consecutive triangles share a unit
// up to kGroupBudget: their bound overestimates a small triangle's fragments tenfold (36
// against 2.5 for 2-3 px legs), and units of 56 such triangles (a budget of 2048) spent a third
// of two threads' time handing units over (1.16x one thread on 10^6 small triangles; 1.6x with
// 16384). A triangle whose bound passes it is cut into bands of at most kBandBudget pixels
// (about kBandBudget fragments: a band's rows are mostly covered), so that the text a large
// triangle's units hold stays small. A fragment's JSON line takes at most kMostJsonLine bytes
// (prim of 10 digits, x and y of 5): a unit's string reserves its bound's worth once (never
// reallocated: a string grown by doubling on two threads' heaps held twice its bytes; untouched
// reserved pages are not resident). Binary units hold 16 bytes a run.
constexpr double kGroupBudget = 16384;
constexpr double kJsonBandBudget = 2048;
constexpr double kBinaryBandBudget = 65536;
constexpr std::size_t kMostJsonLine = 60;

// A run as the units of a binary list hold it (16 bytes, the host's byte order: it never
// leaves the process); tri is the run's primitive (FragmentBinaryWriter::add_runs with base 0).
struct RunRecord {
  std::uint32_t tri;
  std::int32_t y, x;
  std::uint32_t n;
};

// A unit's runs in brief, written at the start of its bytes (a summary kept per unit took
// more memory than the window's bytes on large triangles): the batch unit's status and count,
// the fragments sent, the first and last (prim, y, x), and whether each run came after the
// previous one.
struct UnitHead {
  raster::BatchStatus status = raster::BatchStatus::kOk;
  bool in_order = true;
  std::uint64_t covered = 0; // from the batch unit
  std::uint64_t count = 0;   // sent as runs
  std::uint32_t first_prim = 0, last_prim = 0;
  std::int32_t first_y = 0, first_x = 0, last_y = 0, last_x = 0;
};

// Where a unit's runs go: its bytes after the head (JSON text or RunRecords), and its head.
struct UnitSink {
  std::string* bytes;
  std::uint32_t base; // the index of the unit's first triangle in the list
  bool json;
  io::RunText text;
  UnitHead head;
};

void unit_run(void* context, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
  auto& s = *static_cast<UnitSink*>(context);
  const std::uint32_t prim = s.base + tri;
  const auto k = static_cast<std::uint32_t>(n);
  UnitHead& h = s.head;
  if (h.count == 0) {
    h.first_prim = prim;
    h.first_y = y;
    h.first_x = x;
  } else if (std::tuple(prim, y, x) <= std::tuple(h.last_prim, h.last_y, h.last_x)) {
    h.in_order = false;
  }
  h.last_prim = prim;
  h.last_y = y;
  h.last_x = static_cast<std::int32_t>(std::int64_t{x} + n - 1);
  h.count += k;
  if (s.json) {
    s.text.append(*s.bytes, prim, y, x, k, false);
  } else {
    const RunRecord r{prim, y, x, k};
    s.bytes->append(reinterpret_cast<const char*>(&r), sizeof r);
  }
}

// Adds a run to whichever writer there is; false when it is out of order.
bool add_run(io::FragmentWriter* json, io::FragmentBinaryWriter* binary, std::uint32_t prim,
             std::int32_t y, std::int32_t x, std::uint32_t n) {
  return binary ? binary->add_run(prim, y, x, n) == io::FragmentBinaryWriter::Added::kOk
                : json->add_run(prim, y, x, n);
}

} // namespace

// rule: FAST.THREADS.DETERMINISTIC
std::vector<RunUnit> plan_run_units(std::span<const float> xy, std::int32_t width,
                                    std::int32_t height, double group_budget, double band_budget) {
  std::vector<RunUnit> units;
  const auto n = static_cast<std::uint32_t>(xy.size() / 6);
  RunUnit open; // triangles [open.first, open.last) so far
  const auto close = [&] {
    if (open.last > open.first)
      units.push_back(open);
    open = RunUnit{open.last, open.last};
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    // load_fast_form's bound (every coordinate is finite: it checked them).
    const TriangleBound b = *triangle_bound(&xy[std::size_t{i} * 6], width, height);
    const double work = b.work();
    if (work <= group_budget) {
      if (open.bound + work > group_budget || open.last - open.first >= kMaxRunUnitTriangles)
        close();
      open.last = i + 1;
      open.bound += work;
      continue;
    }
    close();
    const auto y0 =
        static_cast<std::int32_t>(std::clamp<double>(std::floor(b.lo_y) - 1, 0, height - 1));
    const auto y1 =
        static_cast<std::int32_t>(std::clamp<double>(std::ceil(b.hi_y) + 1, 0, height - 1));
    const auto band = static_cast<std::int32_t>(std::max(1.0, std::floor(band_budget / b.cols)));
    for (std::int32_t y = y0; y <= y1; y += band) {
      const auto last =
          static_cast<std::int32_t>(std::min<std::int64_t>(std::int64_t{y} + band - 1, y1));
      units.push_back(RunUnit{i, i + 1, true, y, last, b.cols * (last - y + 1)});
    }
    open = RunUnit{i + 1, i + 1};
  }
  close();
  return units;
}

// rule: FAST.BATCH.EQUALS.PLAIN, FAST.THREADS.DETERMINISTIC
std::optional<std::uint64_t> count_fast_list(std::span<const float> xy, std::int32_t width,
                                             std::int32_t height, const RasterState& state, Isa isa,
                                             unsigned threads) {
  const std::size_t n = xy.size() / 6;
  const std::size_t parts = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(n, 1));
  std::vector<raster::FastBatchResult> counted(parts);
  run_units(parts, threads, [&](std::size_t k) {
    const std::size_t first = n * k / parts, last = n * (k + 1) / parts;
    counted[k] = raster::fast_count_batch(xy.subspan(6 * first, 6 * (last - first)), width, height,
                                          state, isa);
  });
  std::uint64_t covered = 0;
  for (const raster::FastBatchResult& r : counted) {
    if (r.status != raster::BatchStatus::kOk)
      return std::nullopt;
    covered += r.covered;
  }
  return covered;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, FAST.THREADS.DETERMINISTIC
FastListResult write_fast_list(std::span<const float> xy, std::int32_t width, std::int32_t height,
                               const RasterState& state, Isa isa, unsigned threads,
                               std::uint64_t max_fragments, io::FragmentWriter* json,
                               io::FragmentBinaryWriter* binary, std::uint32_t first_prim) {
  // Thrown where the list stops (declined); never seen outside.
  struct Stop {};
  FastListResult out;
  if (threads <= 1) {
    // Straight from the runs to the writer.
    struct Sink {
      io::FragmentWriter* json;
      io::FragmentBinaryWriter* binary;
      std::uint64_t max;
      std::uint32_t first_prim;
      std::uint64_t count = 0;
      bool in_order = true;
    } sink{json, binary, max_fragments, first_prim};
    const raster::RunSink runs{
        &sink,
        [](void* c, std::uint32_t tri, std::int32_t y, std::int32_t x, std::int32_t n) {
          auto& s = *static_cast<Sink*>(c);
          const auto k = static_cast<std::uint32_t>(n);
          s.count += k;
          if (s.count > s.max)
            throw Stop{}; // unwinds the batch unit: it holds its buffers in RAII owners
          s.in_order = add_run(s.json, s.binary, s.first_prim + tri, y, x, k) && s.in_order;
        },
        // The small triangles' runs of a chunk at once: the limit checked once for all of them
        // (a list that passes it is declined whatever it wrote), the runs written by the binary
        // writer's add_runs in one call, or each run in a loop (FragmentWriter::add_run).
        [](void* c, const raster::BatchRun* r, std::size_t n) {
          auto& s = *static_cast<Sink*>(c);
          std::uint64_t k = 0;
          for (std::size_t i = 0; i < n; ++i)
            k += static_cast<std::uint32_t>(r[i].n);
          s.count += k;
          if (s.count > s.max)
            throw Stop{};
          if (s.binary) {
            s.in_order =
                s.binary->add_runs(r, n, s.first_prim) == io::FragmentBinaryWriter::Added::kOk &&
                s.in_order;
            return;
          }
          for (std::size_t i = 0; i < n; ++i)
            s.in_order = s.json->add_run(s.first_prim + r[i].tri, r[i].y, r[i].x,
                                         static_cast<std::uint32_t>(r[i].n)) &&
                         s.in_order;
        }};
    try {
      const raster::FastBatchResult r =
          raster::fast_runs_batch(xy, width, height, state, isa, runs);
      out.declined = r.status != raster::BatchStatus::kOk;
      out.ok = out.declined || r.covered == sink.count;
    } catch (const Stop&) {
      out.declined = true;
    }
    out.covered = sink.count;
    out.in_order = sink.in_order;
    return out;
  }
  const std::vector<RunUnit> units =
      plan_run_units(xy, width, height, kGroupBudget, json ? kJsonBandBudget : kBinaryBandBudget);
  const auto produce = [&](std::size_t i, std::string& bytes) {
    const RunUnit& u = units[i];
    if (json)
      bytes.reserve(sizeof(UnitHead) + static_cast<std::size_t>(u.bound) * kMostJsonLine);
    bytes.resize(sizeof(UnitHead)); // written last
    UnitSink sink{&bytes, first_prim + (u.band ? 0 : u.first), json != nullptr, {}, {}};
    const raster::RunSink runs{&sink, unit_run};
    const raster::FastBatchResult r =
        u.band ? raster::fast_runs_rows(xy, u.first, width, height, state, isa, u.y_first, u.y_last,
                                        runs)
               : raster::fast_runs_batch(
                     xy.subspan(std::size_t{u.first} * 6, std::size_t{u.last - u.first} * 6), width,
                     height, state, isa, runs);
    sink.head.status = r.status;
    sink.head.covered = r.covered;
    std::memcpy(bytes.data(), &sink.head, sizeof sink.head);
  };
  const auto consume = [&](std::size_t, std::string& bytes) {
    UnitHead h;
    std::memcpy(&h, bytes.data(), sizeof h);
    const std::string_view body = std::string_view(bytes).substr(sizeof h);
    if (h.status != raster::BatchStatus::kOk || h.count > max_fragments - out.covered)
      throw Stop{};
    if (h.covered != h.count)
      out.ok = false;
    out.covered += h.count;
    if (json) {
      BatchSummary b;
      b.count = h.count;
      b.first = Fragment(h.first_prim, h.first_x, h.first_y, 1);
      b.last = Fragment(h.last_prim, h.last_x, h.last_y, 1);
      b.in_order = h.in_order;
      out.in_order = json->add_without_text(b) && out.in_order;
      json->add_encoded_text(body);
      return;
    }
    // The unit's runs to the writer's add_runs a block at a time (copied out of the bytes).
    RunRecord block[256];
    for (std::size_t at = 0; at < body.size();) {
      const std::size_t k = std::min(std::size(block), (body.size() - at) / sizeof(RunRecord));
      if (k == 0)
        break;
      std::memcpy(block, body.data() + at, k * sizeof(RunRecord));
      out.in_order =
          binary->add_runs(block, k, 0) == io::FragmentBinaryWriter::Added::kOk && out.in_order;
      at += k * sizeof(RunRecord);
    }
  };
  try {
    produce_ordered(units.size(), threads, std::size_t{threads} + 1, produce, consume);
  } catch (const Stop&) {
    out.declined = true;
  }
  return out;
}

} // namespace rastrules::cli
