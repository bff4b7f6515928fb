// SPDX-License-Identifier: MIT
// rastrules fuzz2d --driver NAME: the 2D campaign against a 2D library (FUZZ.PATH.*).
// Implements: FUZZ.PATH.REPORT (the command line)

#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "cli.hpp"
#include "fuzz_options.hpp"
#include "parser.hpp"
#include "rastrules/fuzzer/paths.hpp"
#include "rastrules/io/interrupt.hpp"

namespace rastrules::cli {

// rule: FUZZ.PATH.GENERATE, FUZZ.PATH.COMPARE, FUZZ.PATH.REPORT
int run_fuzz2d(const Args& args) {
  CommandLine cl("fuzz2d",
                 "Draw generated paths with a 2D library and compare its raster with the exact "
                 "coverage (FUZZ.PATH.*): boundary ties and alpha within the tolerance are legal, "
                 "every other difference is classified (conflation, winding overflow, curve "
                 "flattening, grid snapping, boundary tie, other) and the first findings of each "
                 "class are shrunk, with pictures, into --out DIR.");
  std::optional<std::string> driver, out, cases, seed, tolerance, families, max_findings;
  bool exact = false;
  cl.value("--driver", driver, "NAME",
           "the 2D library: freetype, cairo, agg, skia, tiny-skia, imprecise-path:BUG (required)",
           "--driver needs a value");
  cl.value("--cases", cases, "N", "the number of generated paths (default 100)",
           "--cases needs a value");
  cl.value("--seed", seed, "S", "the generator's seed (default 1)", "--seed needs a value");
  cl.value("--out", out, "DIR", "write report.json, the findings' scenes and pictures",
           "--out needs a value");
  cl.value("--alpha-tolerance", tolerance, "N",
           "largest legal |alpha - exact alpha| in 1/255 (default 1)",
           "--alpha-tolerance needs a value");
  cl.value("--families", families, "A,B", "only these path families (FUZZ.PATH.GENERATE)",
           "--families needs a value");
  cl.value("--max-findings", max_findings, "N",
           "findings shrunk and written per class (default 8; 0: none)",
           "--max-findings needs a value");
  cl.flag("--exact", exact, "aliased boundary ties are differences too (default: legal)");
  if (const auto stop = cl.parse(args, "fuzz2d: "))
    return *stop;
  fuzzer::paths::PathSettings settings;
  settings.driver_name = driver.value_or("");
  if (settings.driver_name.empty())
    return usage_error("--driver is required");
  settings.compare.legal = !exact;
  if (out)
    settings.out_dir = *out;
  if (cases) {
    const auto n = parse_int(*cases, 1, 100000000);
    if (!n)
      return usage_error("--cases: must be an integer in [1, 100000000], got " +
                         shown_value(*cases));
    settings.cases = static_cast<std::uint64_t>(*n);
  }
  if (seed) {
    const auto n = parse_int(*seed, 0, INT64_MAX);
    if (!n)
      return usage_error("--seed: must be an integer >= 0, got " + shown_value(*seed));
    settings.seed = static_cast<std::uint64_t>(*n);
  }
  if (tolerance) {
    const auto n = parse_int(*tolerance, 0, 255);
    if (!n)
      return usage_error("--alpha-tolerance: must be an integer in [0, 255], got " +
                         shown_value(*tolerance));
    settings.compare.alpha_tolerance = static_cast<int>(*n);
  }
  if (max_findings) {
    const auto n = parse_int(*max_findings, 0, 1000000);
    if (!n)
      return usage_error("--max-findings: must be an integer in [0, 1000000], got " +
                         shown_value(*max_findings));
    settings.max_findings = static_cast<std::uint64_t>(*n);
  }
  if (families) {
    std::stringstream in(*families);
    for (std::string f; std::getline(in, f, ',');) {
      bool known = false;
      for (const std::string_view k : fuzzer::paths::kPathFamilies)
        known = known || k == f;
      if (!known) {
        std::string names;
        for (const std::string_view k : fuzzer::paths::kPathFamilies)
          names += (names.empty() ? "" : ", ") + std::string(k);
        return usage_error("--families: unknown family " + shown_value(f) + " (" + names + ")");
      }
      settings.families.push_back(f);
    }
  }
  auto d = open_driver_or_report(settings.driver_name);
  if (!d)
    return kExitBadInput;
  if (!d->info().paths.any())
    return error("fuzz2d: driver '" + settings.driver_name + "' draws no paths");
  const fuzzer::paths::PathSummary s = fuzzer::paths::run_path_fuzz(*d, settings);
  fuzzer::paths::print_path_summary(stdout, settings, d->info(), s);
  // rule: SCENE.INPUT.ERRORS, FUZZ.PATH.REPORT
  if (s.interrupted || io::interrupted()) {
    std::printf("result      interrupted after %llu case(s)\n",
                static_cast<unsigned long long>(s.cases));
    std::fflush(stdout);
    error("interrupted");
    return io::kExitInterrupted;
  }
  if (!s.error.empty())
    return kExitBadInput;
  return s.mismatches > 0 ? kExitDifference : kExitOk;
}

} // namespace rastrules::cli
