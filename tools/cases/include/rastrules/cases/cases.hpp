// SPDX-License-Identifier: MIT
// The hard-case catalog (spec/cases/, PIPE.CATALOG): pipeline scenes, each with a sidecar
// NAME.expect.json that names the rules it exercises and what its result must be. check_case()
// renders a case with every optimization and with none, and checks
//   - the two results are identical (PIPE.OPT.*);
//   - every value is finite, every barycentric triple sums to its area, every stored depth lies
//     in the viewport's range (PIPE.BARY.SUM, PIPE.INTERP.HORIZON, PIPE.DEPTH.CLAMP);
//   - every attribute and depth agrees with the exact oracle within its stated bound
//     (PIPE.INTERP.BOUND, PIPE.DEPTH.BOUND; oracle/, exact rationals);
//   - the sidecar's expectations (counts, parts, passed samples, depth values, ranges).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rastrules::cases {

struct CaseReport {
  std::string name;                  // the scene file's stem
  std::vector<std::string> rules;    // from the sidecar
  std::string what;                  // from the sidecar
  std::vector<std::string> failures; // empty: the case holds
  std::size_t fragments = 0;
  std::size_t oracle_checks = 0; // attribute and depth values compared with the oracle
  [[nodiscard]] bool ok() const { return failures.empty(); }
};

// Checks one case: scene is NAME.json, its sidecar NAME.expect.json beside it. A missing or
// malformed sidecar, or a scene that does not read, is a failure of the case (named).
[[nodiscard]] CaseReport check_case(const std::filesystem::path& scene);

// The scene files of a catalog directory (every *.json that is not *.expect.json), sorted.
[[nodiscard]] std::vector<std::filesystem::path> catalog(const std::filesystem::path& dir);

// One line per case: "OK   name  (N fragments, M oracle checks)  rules" or "FAIL name: ...".
[[nodiscard]] std::string format_report(const std::vector<CaseReport>& reports);

} // namespace rastrules::cases
