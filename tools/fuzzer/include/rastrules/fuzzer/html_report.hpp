// SPDX-License-Identifier: MIT
// The campaign's page for people: DIR/index.html beside report.json (spec/driver.md
// FUZZ.REPORT.HTML).
// Implements: FUZZ.REPORT.HTML

#pragma once

#include <optional>
#include <string>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {

// Writes settings.out_dir/index.html for a finished campaign: the summary table, the unique
// findings counted by rule and class, and per unique finding its picture (expected | actual |
// difference) with a caption and the legend, its minimal scene inline, links to its files and
// the explanation of its differing pixels (at most kExplainedPixels of them). Every string
// from input is escaped; pictures and files are linked by relative paths. Returns an error or
// nullopt. Nothing is written when settings.out_dir is empty.
// rule: FUZZ.REPORT.HTML
inline constexpr std::size_t kExplainedPixels = 4;
[[nodiscard]] std::optional<std::string> write_html_report(const Settings& settings,
                                                           const std::string& driver_description,
                                                           const Summary& summary);

} // namespace rastrules::fuzzer
