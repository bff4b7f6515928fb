// SPDX-License-Identifier: MIT
// rastrules fuzz and the option parsing shared with check and probe.
// Implements: FUZZ.GENERATE, FUZZ.REPORT (the command line)

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cli.hpp"
#include "fuzz_options.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/output_file.hpp"

namespace rastrules::cli {

namespace {

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
                                              bool allow_campaign) {
  FuzzOptions o;
  o.settings.progress = ::isatty(2) != 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool campaign_option = allow_campaign && (a == "--cases" || a == "--seed");
    const bool shard_option = allow_campaign && a == "--shard";
    const bool results_option = a == "--baseline" || a == "--junit" || a == "--summary-json";
    const bool takes_value = a == "--driver" || a == "--profile" || a == "--mode" || a == "--out" ||
                             campaign_option || shard_option || results_option;
    std::string v;
    if (takes_value) {
      if (i + 1 >= args.size()) {
        usage_error(a + " needs a value");
        return std::nullopt;
      }
      v = args[++i];
    }
    if (a == "--driver") {
      o.settings.driver_name = v;
    } else if (a == "--profile") {
      if (!set_choice(a, v, fuzzer::parse_profile(v), "d3d11, vulkan, opengl", o.settings.profile))
        return std::nullopt;
    } else if (a == "--mode") {
      if (!set_choice(a, v, fuzzer::parse_mode(v), "exact, legal", o.settings.mode))
        return std::nullopt;
    } else if (a == "--out") {
      o.settings.out_dir = v;
    } else if (campaign_option) {
      auto n = parse_int(v, a == "--cases" ? 1 : 0, a == "--cases" ? 100000000 : INT64_MAX);
      if (!n) {
        usage_error(a + ": must be an integer" + (a == "--cases" ? " in [1, 100000000]" : " >= 0") +
                    ", got " + shown_value(v));
        return std::nullopt;
      }
      (a == "--cases" ? o.settings.cases : o.settings.seed) = static_cast<std::uint64_t>(*n);
    } else if (shard_option) {
      // rule: FUZZ.SHARD
      const auto slash = v.find('/');
      const auto k =
          slash == std::string::npos ? std::nullopt : parse_int(v.substr(0, slash), 0, 1000000);
      const auto n =
          slash == std::string::npos ? std::nullopt : parse_int(v.substr(slash + 1), 1, 1000000);
      if (!k || !n || *k >= *n) {
        usage_error("--shard: must be K/N with 0 <= K < N <= 1000000, got " + shown_value(v));
        return std::nullopt;
      }
      o.settings.shard_index = static_cast<std::uint64_t>(*k);
      o.settings.shard_count = static_cast<std::uint64_t>(*n);
    } else if (results_option) {
      (a == "--baseline" ? o.baseline_path : (a == "--junit" ? o.junit_path : o.summary_path)) = v;
    } else if (a == "--no-progress") {
      o.settings.progress = false;
    } else if (want_scene && o.scene_path.empty() && (a == "-" || a.rfind("--", 0) != 0)) {
      o.scene_path = a;
    } else {
      usage_error("unknown option " + shown_value(a));
      return std::nullopt;
    }
  }
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
  auto o = parse_fuzz_options(args, false, true);
  if (!o)
    return kExitBadInput;
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
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--out" || a == "--baseline" || a == "--junit" || a == "--summary-json") {
      if (i + 1 >= args.size())
        return usage_error(a + " needs a value");
      const std::string& v = args[++i];
      (a == "--out" ? o.settings.out_dir
                    : (a == "--baseline" ? o.baseline_path
                                         : (a == "--junit" ? o.junit_path : o.summary_path))) = v;
    } else if (a.rfind("--", 0) == 0) {
      return usage_error("unknown option " + shown_value(a));
    } else {
      dirs.push_back(a);
    }
  }
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
