// SPDX-License-Identifier: MIT
// rastrules fuzz and the option parsing shared with check and probe.
// Implements: FUZZ.GENERATE, FUZZ.REPORT (the command line)

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "fuzz_options.hpp"
#include "parser.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/output_file.hpp"

namespace rastrules::cli {

namespace {

// The options of a campaign's results that fuzz, check and fuzz-merge share: --baseline
// (FUZZ.BASELINE), --junit and --summary-json (FUZZ.RESULTS).
struct ResultOptions {
  std::optional<std::string> baseline, junit, summary;

  void declare(CommandLine& cl) {
    cl.value("--baseline", baseline, "KNOWN.json",
             "known findings: only groups the file does not list fail (FUZZ.BASELINE)",
             "--baseline needs a value");
    cl.value("--junit", junit, "FILE.xml", "write the results as JUnit XML (FUZZ.RESULTS)",
             "--junit needs a value");
    cl.value("--summary-json", summary, "FILE.json", "write a JSON summary (FUZZ.RESULTS)",
             "--summary-json needs a value");
  }
  void store(FuzzOptions& o) const {
    o.baseline_path = baseline.value_or("");
    o.junit_path = junit.value_or("");
    o.summary_path = summary.value_or("");
  }
};

// Sets `out` to `parsed`, the value of `option` ("--profile") read from `value`; when there is
// none, prints the usage error "OPTION: unknown NAME "VALUE" (CHOICES)" and returns false.
template <class T>
bool set_choice(const std::string& option, const std::string& value, std::optional<T> parsed,
                std::string_view choices, T& out) {
  if (!parsed) {
    usage_error(option + ": unknown " + option.substr(2) + " " + shown_value(value) + " (" +
                std::string(choices) + ")");
    return false;
  }
  out = *parsed;
  return true;
}

} // namespace

std::optional<FuzzOptions> parse_fuzz_options(const Args& args, bool want_scene,
                                              bool allow_campaign, int& status) {
  status = kExitBadInput;
  FuzzOptions o;
  o.settings.progress = ::isatty(2) != 0;
  const std::string command = want_scene ? "check" : "fuzz";
  CommandLine cl(command,
                 want_scene ? "Compare one scene, used as it is, drawn by the driver with the "
                              "reference: the same comparison and outputs as a campaign's case."
                            : "Draw N generated scenes with the driver and compare each with the "
                              "reference; every mismatch is shrunk to a minimal scene and, with "
                              "--out, written as DIR/case-N.scene.json (original), case-N.min.json "
                              "(shrunk), case-N.png (expected | actual | difference) and "
                              "case-N.json, with DIR/report.json for the campaign (spec/driver.md "
                              "FUZZ.*). Mismatches are grouped by the rule that decided them and "
                              "their class.");
  std::vector<std::string> scenes;
  std::optional<std::string> driver, profile, mode, out, cases, seed, shard, families;
  ResultOptions results;
  bool no_progress = false;
  bool values = false;
  if (want_scene)
    cl.scene_files(scenes);
  cl.value("--driver", driver, "NAME",
           "the driver (required): reference, imprecise[:float-edges|:fill-bottom-right|"
           ":4-bit-subpixel|:screen-space|:provoking-vertex|:d24-truncate], lavapipe and opengl "
           "(when built), external:COMMAND "
           "(DRIVER.EXTERNAL.PROTOCOL)",
           "--driver needs a value");
  cl.value("--profile", profile, "d3d11|vulkan|opengl", "the rules compared (default d3d11)",
           "--profile needs a value");
  cl.value("--mode", mode, "exact|legal",
           "exact: the profile's rules; legal: what the API allows (default exact)",
           "--mode needs a value");
  if (allow_campaign) {
    cl.value("--cases", cases, "N", "the number of generated scenes (default 100)",
             "--cases needs a value");
    cl.value("--seed", seed, "S", "the generator's seed (default 1)", "--seed needs a value");
    cl.value("--shard", shard, "K/N", "run the cases i with i mod N = K (FUZZ.SHARD)",
             "--shard needs a value");
    cl.value("--families", families, "F,F,...",
             "generate only these scene families: random, shared-edge, fan, grid, sliver, "
             "points, lines (FUZZ.FAMILIES)",
             "--families needs a value");
    cl.flag("--values", values,
            "the values campaign: pipeline scenes whose depth and attribute values are compared "
            "(families perspective, clipped, strips, depth, horizon, bias; FUZZ.VALUES.GENERATE)");
  }
  cl.value("--out", out, "DIR", "write the findings and report.json into DIR",
           "--out needs a value");
  results.declare(cl);
  cl.flag("--no-progress", no_progress, "no progress bar on standard error");
  if (const auto stop = cl.parse(args, command + ": ")) {
    status = *stop; // 0 after --help
    return std::nullopt;
  }
  if (driver)
    o.settings.driver_name = *driver;
  if (profile && !set_choice(std::string("--profile"), *profile, fuzzer::parse_profile(*profile),
                             "d3d11, vulkan, opengl", o.settings.profile))
    return std::nullopt;
  if (mode && !set_choice(std::string("--mode"), *mode, fuzzer::parse_mode(*mode), "exact, legal",
                          o.settings.mode))
    return std::nullopt;
  if (out)
    o.settings.out_dir = *out;
  for (const auto& [name, v] : {std::pair{"--cases", &cases}, std::pair{"--seed", &seed}}) {
    if (!*v)
      continue;
    const bool is_cases = std::string_view(name) == "--cases";
    auto n = parse_int(**v, is_cases ? 1 : 0, is_cases ? 100000000 : INT64_MAX);
    if (!n) {
      usage_error(std::string(name) + ": must be an integer" +
                  (is_cases ? " in [1, 100000000]" : " >= 0") + ", got " + shown_value(*v));
      return std::nullopt;
    }
    (is_cases ? o.settings.cases : o.settings.seed) = static_cast<std::uint64_t>(*n);
  }
  if (shard) {
    // rule: FUZZ.SHARD
    const auto slash = shard->find('/');
    const auto k =
        slash == std::string::npos ? std::nullopt : parse_int(shard->substr(0, slash), 0, 1000000);
    const auto n =
        slash == std::string::npos ? std::nullopt : parse_int(shard->substr(slash + 1), 1, 1000000);
    if (!k || !n || *k >= *n) {
      usage_error("--shard: must be K/N with 0 <= K < N <= 1000000, got " + shown_value(shard));
      return std::nullopt;
    }
    o.settings.shard_index = static_cast<std::uint64_t>(*k);
    o.settings.shard_count = static_cast<std::uint64_t>(*n);
  }
  o.settings.values = values; // rule: FUZZ.VALUES.GENERATE
  if (families) {
    // rule: FUZZ.FAMILIES
    std::string_view rest = *families;
    while (true) {
      const std::size_t comma = rest.find(',');
      const std::string name(rest.substr(0, comma));
      const bool known =
          values ? std::find(fuzzer::kValueFamilies.begin(), fuzzer::kValueFamilies.end(), name) !=
                       fuzzer::kValueFamilies.end()
                 : std::find(fuzzer::kFamilies.begin(), fuzzer::kFamilies.end(), name) !=
                       fuzzer::kFamilies.end();
      if (!known) {
        usage_error("--families: unknown family " + shown_value(name) +
                    (values ? " (known with --values: perspective, clipped, strips, depth)"
                            : " (known: random, shared-edge, fan, grid, sliver, points, lines)"));
        return std::nullopt;
      }
      if (std::find(o.settings.families.begin(), o.settings.families.end(), name) ==
          o.settings.families.end())
        o.settings.families.push_back(name);
      if (comma == std::string_view::npos)
        break;
      rest.remove_prefix(comma + 1);
    }
  }
  results.store(o);
  // rule: SCENE.INPUT.ERRORS
  // -q: no progress bar; -v: the progress bar even when standard error is no terminal.
  if (no_progress || verbosity() == Verbosity::kQuiet)
    o.settings.progress = false;
  else if (verbosity() == Verbosity::kVerbose)
    o.settings.progress = true;
  if (want_scene && scenes.size() > 1) {
    usage_error(command + ": more than one scene file");
    return std::nullopt;
  }
  if (want_scene && !scenes.empty())
    o.scene_path = scenes.front();
  if (o.settings.driver_name.empty()) {
    usage_error("--driver is required");
    return std::nullopt;
  }
  if (want_scene && o.scene_path.empty()) {
    usage_error("missing SCENE.json");
    return std::nullopt;
  }
  if (!o.baseline_path.empty()) {
    std::string err;
    o.baseline = fuzzer::read_baseline(o.baseline_path, &err);
    if (!o.baseline) {
      error("--baseline: " + err);
      return std::nullopt;
    }
  }
  return o;
}

std::unique_ptr<driver::Driver> open_driver_or_report(const std::string& name) {
  std::string err;
  auto d = driver::open_driver(name, &err);
  if (!d)
    error("--driver: " + err);
  return d;
}

int finish_campaign(const FuzzOptions& o, const driver::Driver& d, fuzzer::Summary& s) {
  return finish_campaign(o, d.info().description, s, d.info().capabilities);
}

int finish_campaign(const FuzzOptions& o, const std::string& description, fuzzer::Summary& s,
                    const std::string& capabilities) {
  // rule: FUZZ.BASELINE
  std::uint64_t unknown = 0;
  if (o.baseline)
    unknown = fuzzer::apply_baseline(*o.baseline, s);
  const fuzzer::Baseline* baseline = o.baseline ? &*o.baseline : nullptr;
  // rule: FUZZ.RESULTS
  // The machine-readable results are written whatever the outcome, an interrupt included.
  std::string results_error;
  if (!o.junit_path.empty()) {
    if (auto e = io::write_text(o.junit_path, fuzzer::junit_xml(o.settings, s, baseline)))
      results_error = "--junit: " + *e;
  }
  if (!o.summary_path.empty() && results_error.empty()) {
    if (auto e = io::write_text(o.summary_path,
                                fuzzer::summary_json(o.settings, description, s, baseline)))
      results_error = "--summary-json: " + *e;
  }
  // rule: SCENE.INPUT.ERRORS, FUZZ.REPORT
  if (s.interrupted || io::interrupted()) {
    fuzzer::print_summary(stdout, o.settings, description, s, capabilities);
    std::printf("result      interrupted after %llu case(s)\n",
                static_cast<unsigned long long>(s.cases));
    std::fflush(stdout);
    error("interrupted");
    return io::kExitInterrupted;
  }
  if (!s.error.empty() && s.cases == 0)
    return error(s.error);
  fuzzer::print_summary(stdout, o.settings, description, s, capabilities);
  std::fflush(stdout);
  if (!s.error.empty())
    return error(s.error);
  if (!results_error.empty())
    return error(results_error);
  if (baseline != nullptr && s.mismatches != 0) {
    std::printf("result      %llu difference(s) in %zu group(s), %llu not in the baseline %s\n",
                static_cast<unsigned long long>(s.mismatches), s.groups.size(),
                static_cast<unsigned long long>(unknown), baseline->path.c_str());
    return unknown != 0 ? kExitDifference : kExitOk;
  }
  if (s.mismatches != 0) {
    std::printf("result      %llu difference(s) found\n",
                static_cast<unsigned long long>(s.mismatches));
    return kExitDifference;
  }
  std::printf("result      no difference\n");
  return kExitOk;
}

int run_fuzz(const Args& args) {
  int status = kExitBadInput;
  auto o = parse_fuzz_options(args, false, true, status);
  if (!o)
    return status;
  auto d = open_driver_or_report(o->settings.driver_name);
  if (!d)
    return kExitBadInput;
  fuzzer::Summary s = fuzzer::run_fuzz(*d, o->settings);
  return finish_campaign(*o, *d, s);
}

// rule: FUZZ.MERGE
int run_fuzz_merge(const Args& args) {
  FuzzOptions o;
  std::vector<std::string> dirs;
  std::optional<std::string> out;
  ResultOptions results;
  CommandLine cl("fuzz-merge", "Join the --out DIRs of the N shards of a campaign into that "
                               "campaign (FUZZ.MERGE): the summary, groups, exit status and "
                               "outputs of fuzz.");
  cl.positionals("DIR", dirs, "the --out folder of each shard");
  cl.value("--out", out, "DIR", "write the merged report into DIR", "--out needs a value");
  results.declare(cl);
  if (const auto stop = cl.parse(args, "fuzz-merge: "))
    return *stop;
  o.settings.out_dir = out.value_or("");
  results.store(o);
  if (dirs.empty())
    return usage_error("missing shard DIR");
  if (!o.baseline_path.empty()) {
    std::string err;
    o.baseline = fuzzer::read_baseline(o.baseline_path, &err);
    if (!o.baseline)
      return error("--baseline: " + err);
  }
  std::string description, err;
  auto s = fuzzer::merge_reports(dirs, &o.settings, &description, &err);
  if (!s)
    return error(err);
  if (!o.settings.out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.settings.out_dir, ec);
    if (ec)
      return error(o.settings.out_dir + ": cannot create: " + ec.message());
    if (auto e = fuzzer::write_report(o.settings, description, *s))
      return error(*e);
  }
  return finish_campaign(o, description, *s);
}

} // namespace rastrules::cli
