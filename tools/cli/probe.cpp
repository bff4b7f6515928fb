// SPDX-License-Identifier: MIT
// rastrules probe --driver NAME: report the driver's conventions.
// Implements: FUZZ.PROBE (the command line)

#include <cstdio>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "fuzz_options.hpp"
#include "parser.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/fuzzer/paths.hpp"
#include "rastrules/io/interrupt.hpp"

namespace rastrules::cli {

namespace {

// rule: FUZZ.PROBE
// The report as one JSON document (probe --json).
std::string probe_json(const std::string& name, const driver::DriverInfo& info,
                       const fuzzer::ProbeReport& r) {
  nlohmann::ordered_json j;
  j["driver"] = name;
  j["description"] = info.description;
  j["fill"] = {{"convention", r.fill},
               {"top", r.top},
               {"bottom", r.bottom},
               {"left", r.left},
               {"right", r.right}};
  j["subpixel_bits"] = r.subpixel_bits >= 0 ? nlohmann::ordered_json(r.subpixel_bits) : nullptr;
  j["reported_subpixel_bits"] =
      info.subpixel_bits >= 0 ? nlohmann::ordered_json(info.subpixel_bits) : nullptr;
  j["snapping"] = {{"rounding", r.rounding}, {"threshold_4096", r.threshold_4096}};
  j["line_mode"] = r.line_mode;
  j["point_rule"] = r.point_rule;
  nlohmann::ordered_json samples = nlohmann::ordered_json::array();
  for (const SampleOffset& o : r.samples_4x)
    samples.push_back({o.x, o.y});
  j["samples_4x"] = samples;
  j["samples_note"] = r.samples_note;
  return j.dump(2) + "\n";
}

// rule: FUZZ.PATH.PROBE
// A 2D library's report: text, or one JSON document.
int print_path_probe(const std::string& name, const driver::DriverInfo& info, bool as_json,
                     const fuzzer::paths::PathProbeReport& r) {
  auto edges = [](const std::array<bool, 4>& e) {
    return std::string("left ") + (e[0] ? "in" : "out") + ", right " + (e[1] ? "in" : "out") +
           ", top " + (e[2] ? "in" : "out") + ", bottom " + (e[3] ? "in" : "out");
  };
  if (as_json) {
    nlohmann::ordered_json j;
    j["driver"] = name;
    j["description"] = info.description;
    if (info.paths.samples) {
      j["convention"] = r.convention;
      j["on_edge_cw"] = r.on_edge_cw;
      j["on_edge_ccw"] = r.on_edge_ccw;
      j["snap_extent_256"] = r.snap_extent;
      j["grid"] = r.grid;
    }
    if (info.paths.area) {
      j["levels_x"] = r.levels_x;
      j["levels_y"] = r.levels_y;
      j["max_edge_error"] = r.max_edge_error;
      j["aa_method"] = r.aa_method;
      j["quantisation"] = r.quantisation;
      j["twice_evenodd"] = r.twice_evenodd;
      j["quadratic"] = r.quadratic;
    }
    std::fputs((j.dump(2) + "\n").c_str(), stdout);
    return kExitOk;
  }
  std::printf("driver            %s (%s)\n", name.c_str(), info.description.c_str());
  std::printf("declared          grid %s; aliased: %s; antialiased: %s\n", info.paths.grid.c_str(),
              info.paths.aliased_method.empty() ? "no" : info.paths.aliased_method.c_str(),
              info.paths.antialiased_method.empty() ? "no" : info.paths.antialiased_method.c_str());
  if (info.paths.samples) {
    std::printf("boundary          %s (centres on edges, cw: %s; ccw: %s)\n", r.convention.c_str(),
                edges(r.on_edge_cw).c_str(), edges(r.on_edge_ccw).c_str());
    std::printf("grid              %s\n", r.grid.c_str());
  }
  if (info.paths.area) {
    std::printf("antialiasing      %s; %d and %d levels, largest error %d/255 on edges\n",
                r.aa_method.c_str(), r.levels_x, r.levels_y, r.max_edge_error);
    std::printf("quantisation      %s\n", r.quantisation.c_str());
    std::printf("conflation        a half pixel drawn twice, even-odd: alpha %d (exact 0)%s\n",
                r.twice_evenodd, r.twice_evenodd > 1 ? ": signed areas accumulated" : "");
    if (r.quadratic >= 0)
      std::printf("curves            a quadratic's segment of area 1/3: alpha %d (exact 85)\n",
                  r.quadratic);
  }
  return kExitOk;
}

} // namespace

int run_probe(const Args& args) {
  CommandLine cl("probe", "Report the driver's fill convention, subpixel bits and snapping "
                          "rounding, line mode, point rule and 4x sample positions, found with "
                          "probe scenes (FUZZ.PROBE).");
  std::optional<std::string> driver;
  bool as_json = false;
  cl.value("--driver", driver, "NAME", "the driver (required; as for fuzz)",
           "--driver needs a value");
  cl.flag("--json", as_json, "one JSON document instead of the text");
  if (const auto stop = cl.parse(args, "probe: "))
    return *stop;
  const std::string name = driver.value_or("");
  if (name.empty())
    return usage_error("--driver is required");
  auto d = open_driver_or_report(name);
  if (!d)
    return kExitBadInput;
  if (!d->info().triangles && d->info().paths.any()) {
    // rule: FUZZ.PATH.PROBE
    const fuzzer::paths::PathProbeReport pr = fuzzer::paths::probe_path_library(*d);
    if (!pr.error.empty())
      return error("probe: " + pr.error);
    return print_path_probe(name, d->info(), as_json, pr);
  }
  const fuzzer::ProbeReport r = fuzzer::probe(*d);
  if (io::interrupted()) { // rule: SCENE.INPUT.ERRORS
    error("interrupted");
    return io::kExitInterrupted;
  }
  if (!r.error.empty())
    return error("probe: " + r.error);
  if (as_json) {
    std::fputs(probe_json(name, d->info(), r).c_str(), stdout);
    return kExitOk;
  }
  const auto& info = d->info();
  std::printf("driver            %s (%s)\n", name.c_str(), info.description.c_str());
  std::printf(
      "fill convention   %s (on-edge samples inside: top %s, bottom %s, left %s, right %s)\n",
      r.fill.c_str(), r.top ? "yes" : "no", r.bottom ? "yes" : "no", r.left ? "yes" : "no",
      r.right ? "yes" : "no");
  if (r.subpixel_bits >= 0) {
    std::printf("subpixel bits     %d (reported by the driver: %s)\n", r.subpixel_bits,
                info.subpixel_bits >= 0 ? std::to_string(info.subpixel_bits).c_str() : "unknown");
  } else {
    std::printf("subpixel bits     not determined\n");
  }
  std::printf("snapping          %s (an edge leaves the pixel centre %lld/4096 px away)\n",
              r.rounding.c_str(), static_cast<long long>(r.threshold_4096));
  std::printf("line mode         %s\n", r.line_mode.c_str());
  std::printf("point rule        %s\n", r.point_rule.c_str());
  if (r.samples_4x.empty()) {
    std::printf("4x samples        %s\n", r.samples_note.c_str());
  } else {
    std::string list;
    for (const SampleOffset& o : r.samples_4x) {
      list += (list.empty() ? "" : " ") + std::string("(") + std::to_string(o.x) + "," +
              std::to_string(o.y) + ")";
    }
    std::printf("4x samples        %s in 1/16 px from the centre: %s\n", list.c_str(),
                r.samples_note.c_str());
  }
  return kExitOk;
}

} // namespace rastrules::cli
