// SPDX-License-Identifier: MIT
// Options shared by rastrules fuzz, check and probe.

#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cli.hpp"
#include "rastrules/driver/driver.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::cli {

struct FuzzOptions {
  fuzzer::Settings settings;
  std::string scene_path;    // check only
  std::string baseline_path; // --baseline FILE (FUZZ.BASELINE)
  std::string junit_path;    // --junit FILE (FUZZ.RESULTS)
  std::string summary_path;  // --summary-json FILE (FUZZ.RESULTS)
  std::optional<fuzzer::Baseline> baseline;
};

// Parses --driver, --profile, --mode, --out, --no-progress, -q/-v, --baseline, --junit,
// --summary-json, and --cases/--seed/--shard when allow_campaign, and one scene path when
// want_scene (CLI11, parser.hpp); reads the baseline. Returns nullopt with `status` the exit
// status when the command stops here: 0 after --help, kExitBadInput after a usage error or a
// bad baseline (printed).
std::optional<FuzzOptions> parse_fuzz_options(const Args& args, bool want_scene,
                                              bool allow_campaign, int& status);

// Opens the driver, or prints "rastrules: error: --driver: REASON" and returns nullptr.
std::unique_ptr<driver::Driver> open_driver_or_report(const std::string& name);

// Prints the summary, writes --junit and --summary-json; returns 0 (no difference, or only
// differences the baseline knows), 1 (differences) or 2 (the campaign stopped on an error).
int finish_campaign(const FuzzOptions& o, const driver::Driver& d, fuzzer::Summary& s);
// capabilities: DriverInfo::capabilities of the driver, printed under it (empty: nothing).
int finish_campaign(const FuzzOptions& o, const std::string& description, fuzzer::Summary& s,
                    const std::string& capabilities = {});

} // namespace rastrules::cli
