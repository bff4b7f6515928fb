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
