// SPDX-License-Identifier: MIT
// The ladder's report: the Markdown table and the JSON document (BENCH.REPORT).
// Implements: BENCH.REPORT, BENCH.TARGETS (reported, never asserted), BENCH.LAVAPIPE (figures)

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string range_text(const RungResult& r) {
  if (!has_coverage(r.rung))
    return "n/a";
  if (!r.range)
    return "none";
  return std::to_string(*r.range) + " px";
}

} // namespace

// rule: BENCH.REPORT
std::string to_markdown(const LadderReport& r) {
  std::ostringstream o;
  o << "Precision ladder, " << r.date << ", " << r.cpu << ", ISA " << r.isa
    << " (batch counter rows: " << r.batch_lanes << " lanes; limit rung: " << r.limit_isa << ", "
    << r.limit_lanes << " lanes), rungs on 1 thread, `reference-fast x" << r.threads << "` on "
    << r.threads << ", " << (r.config.quick ? "quick" : "full") << " mode, seed " << r.config.seed
    << ".\n\n";
  o << "| rung |";
  for (const auto& s : r.scenes)
    o << " " << s << " Mdec/s (x ref) |";
  o << " error fraction | watertight violations | exact range |\n|---|";
  for (std::size_t i = 0; i < r.scenes.size(); ++i)
    o << "---:|";
  o << "---:|---:|---:|\n";
  for (const RungResult& rr : r.rungs) {
    o << "| " << to_string(rr.rung) << " |";
    for (const FamilyResult& f : rr.families)
      o << " " << fmt("%.4g", f.decisions_per_second / 1e6) << " ("
        << fmt("%.3g", f.ratio_to_reference) << ") |";
    if (has_coverage(rr.rung))
      o << " " << (rr.total_errors == 0 ? std::string("0") : fmt("%.3g", rr.error_fraction()))
        << " | " << rr.total_watertight << " | " << range_text(rr) << " |\n";
    else
      o << " n/a | n/a | n/a |\n";
    if (rr.rung == Rung::kReferenceFast && !r.fast_threaded.empty()) {
      o << "| reference-fast x" << r.threads << " |";
      for (const FamilyResult& f : r.fast_threaded)
        o << " " << fmt("%.4g", f.decisions_per_second / 1e6) << " ("
          << fmt("%.3g", f.ratio_to_reference) << ") |";
      o << " = reference-fast | = | = |\n";
    }
  }
  o << "\nDecisions: pixel centres of each triangle's bounding box (clipped to the target); "
       "Mdec/s: millions of decisions per second, median of repeats (at least "
    << fmt("%g", r.config.min_seconds)
    << " s per rung and scene), ratio to `reference` in the same run. Error: decisions that "
       "differ from `exact` over all decisions of these scenes. Watertight: pixels of the "
       "meshes' rectangles drawn zero or several times. Exact range: largest translation t of "
       "the sweep ("
    << r.sweep_note
    << ") up to which the rung has no error, no watertightness and no "
       "translation violation. `reference-fast x"
    << r.threads
    << "`: the same batch counter with the "
       "scene's triangles split into "
    << r.threads << " chunks on a pool of " << r.threads
    << " threads created before the timed repeats (its answers are reference-fast's). "
       "`reference-fast` is timed through the kernel's batch counter (snapping, setup and "
       "coverage; triangles up to 64 px a side eight at a time in 32-bit lanes). The plot shows "
       "the single-thread rungs; "
       "`limit` has no error figure (no tie rule) and is drawn at error 0 only to show its "
       "speed.\n";
  o << "\nTriangles per second (small mesh):";
  for (const RungResult& rr : r.rungs)
    for (const FamilyResult& f : rr.families)
      if (f.scene == "small")
        o << " " << to_string(rr.rung) << " " << fmt("%.3g", f.triangles_per_second) << ";";
  for (const FamilyResult& f : r.fast_threaded)
    if (f.scene == "small")
      o << " reference-fast x" << r.threads << " " << fmt("%.3g", f.triangles_per_second) << ";";
  // rule: BENCH.LAVAPIPE
  const std::string lp_threads =
      (r.lavapipe.threads > 0 ? std::to_string(r.lavapipe.threads) : std::string("?")) +
      " rasterizer threads: " + r.lavapipe.threads_source;
  o << "\n\nLavapipe (small mesh, " << r.lavapipe.triangles << " triangles): ";
  if (r.lavapipe.available) {
    const double lav = r.lavapipe.seconds > 0
                           ? static_cast<double>(r.lavapipe.triangles) / r.lavapipe.seconds
                           : 0.0;
    o << fmt("%.3g", lav) << " triangles/s (" << r.lavapipe.device << ", median of "
      << r.lavapipe.repeats << " draws, " << fmt("%.4g", r.lavapipe.seconds * 1e3)
      << " ms per draw, " << lp_threads << "); occlusion query " << r.lavapipe.samples_passed
      << " samples, reference " << r.reference_small_covered
      << " pixels. Timed: " << r.lavapipe.includes
      << (!r.lavapipe.includes.empty() && r.lavapipe.includes.back() == '.' ? "" : ".")
      << " rastrules' figures count coverage only (snapping, setup, traversal).\n";
  } else {
    o << "not available (" << r.lavapipe.why_not << "); no ratio (it would have used " << lp_threads
      << ").\n";
  }
  o << "\nTargets (BENCH.TARGETS, reported, never asserted):\n\n";
  for (const TargetCheck& t : check_targets(r))
    o << "- " << t.name << ": " << t.measured << " — "
      << (t.met ? (*t.met ? "met" : "NOT met") : "not measured") << "\n";
  return o.str();
}

// rule: BENCH.REPORT
std::string to_json(const LadderReport& r) {
  using nlohmann::json;
  json j;
  j["date"] = r.date;
  j["cpu"] = r.cpu;
  j["isa"] = r.isa;
  j["limit_isa"] = r.limit_isa;
  j["batch_lanes"] = r.batch_lanes;
  j["limit_lanes"] = r.limit_lanes;
  j["threads"] = r.threads;
  j["quick"] = r.config.quick;
  j["seed"] = r.config.seed;
  j["min_seconds"] = r.config.min_seconds;
  j["scenes"] = r.scenes;
  j["sweep_t"] = r.sweep_t;
  j["sweep_note"] = r.sweep_note;
  j["seconds_total"] = r.seconds_total;
  json rungs = json::array();
  for (const RungResult& rr : r.rungs) {
    json x;
    x["rung"] = std::string(to_string(rr.rung));
    json fams = json::array();
    for (const FamilyResult& f : rr.families) {
      json y;
      y["scene"] = f.scene;
      y["triangles"] = f.triangles;
      y["decisions"] = f.decisions;
      y["covered"] = f.covered;
      y["repeats"] = f.repeats;
      y["seconds_median"] = f.seconds;
      y["decisions_per_second"] = f.decisions_per_second;
      y["triangles_per_second"] = f.triangles_per_second;
      y["ratio_to_reference"] = f.ratio_to_reference;
      y["errors"] = f.errors ? json(*f.errors) : json(nullptr);
      y["watertight_violations"] = f.watertight ? json(*f.watertight) : json(nullptr);
      fams.push_back(y);
    }
    x["scenes"] = fams;
    if (has_coverage(rr.rung)) {
      x["decisions"] = rr.total_decisions;
      x["errors"] = rr.total_errors;
      x["error_fraction"] = rr.error_fraction();
      x["watertight_violations"] = rr.total_watertight;
      json sw = json::array();
      for (const SweepPoint& p : rr.sweep)
        sw.push_back({{"t", p.t},
                      {"errors", p.errors},
                      {"watertight_violations", p.watertight},
                      {"translation_violations", p.translation}});
      x["sweep"] = sw;
      x["exact_range"] = rr.range ? json(*rr.range) : json(nullptr);
    } else {
      x["errors"] = nullptr;
      x["exact_range"] = nullptr;
    }
    rungs.push_back(x);
  }
  j["rungs"] = rungs;
  json threaded = json::array();
  for (const FamilyResult& f : r.fast_threaded)
    threaded.push_back({{"scene", f.scene},
                        {"threads", r.threads},
                        {"decisions", f.decisions},
                        {"covered", f.covered},
                        {"repeats", f.repeats},
                        {"seconds_median", f.seconds},
                        {"decisions_per_second", f.decisions_per_second},
                        {"triangles_per_second", f.triangles_per_second},
                        {"ratio_to_reference", f.ratio_to_reference}});
  j["reference_fast_threaded"] = threaded;
  json lav;
  lav["available"] = r.lavapipe.available;
  lav["why_not"] = r.lavapipe.why_not;
  lav["device"] = r.lavapipe.device;
  lav["includes"] = r.lavapipe.includes;
  lav["repeats"] = r.lavapipe.repeats;
  lav["seconds_median"] = r.lavapipe.seconds;
  lav["samples_passed"] = r.lavapipe.samples_passed;
  lav["triangles"] = r.lavapipe.triangles;
  lav["reference_covered"] = r.reference_small_covered;
  lav["threads"] = r.lavapipe.threads;
  lav["threads_source"] = r.lavapipe.threads_source;
  if (r.lavapipe.available && r.lavapipe.seconds > 0)
    lav["triangles_per_second"] = static_cast<double>(r.lavapipe.triangles) / r.lavapipe.seconds;
  j["lavapipe"] = lav;
  json targets = json::array();
  for (const TargetCheck& t : check_targets(r))
    targets.push_back({{"target", t.name},
                       {"measured", t.measured},
                       {"met", t.met ? json(*t.met) : json(nullptr)}});
  j["targets"] = targets;
  return j.dump(2) + "\n";
}

} // namespace rastrules::bench
