// SPDX-License-Identifier: MIT
// Machine-readable results of a campaign for CI: JUnit XML and the JSON summary.
// Implements: FUZZ.RESULTS

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "json_file.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/html.hpp"

namespace rastrules::fuzzer {
namespace {

using nlohmann::json;

// Text as XML character data or an attribute value: the pages' escaper (io::html_escape), whose
// output is also valid XML 1.0 (the five markup characters escaped, invalid UTF-8 and the
// control characters XML forbids replaced by U+FFFD).
std::string xml(std::string_view text) {
  return io::html_escape(text);
}

std::string u(std::uint64_t n) {
  return std::to_string(n);
}

bool failing(const Group& g, const Baseline* baseline) {
  return baseline == nullptr || !g.known;
}

std::string suite_name(const Settings& st) {
  std::string name = "rastrules fuzz " + st.driver_name + " " + std::string(to_string(st.profile)) +
                     " " + std::string(to_string(st.mode)) + " seed " + u(st.seed);
  if (st.shard_count > 1)
    name += " shard " + u(st.shard_index) + "/" + u(st.shard_count);
  return name;
}

} // namespace

// rule: FUZZ.RESULTS
std::string junit_xml(const Settings& st, const Summary& s, const Baseline* baseline) {
  std::string cases;
  std::uint64_t tests = 0, failures = 0, errors = 0, skipped = 0;
  // One test case per finding group: a failure when the baseline does not know it.
  for (const Group& g : s.groups) {
    ++tests;
    cases += "    <testcase classname=\"findings\" name=\"" + xml(g.key.rule + ", " + g.key.klass) +
             "\" time=\"0\">\n";
    const std::string what = u(g.count) + " case(s), " + u(g.scenes) +
                             " shrunk scene(s), first case " + u(g.example_case);
    if (failing(g, baseline)) {
      ++failures;
      cases += "      <failure type=\"" + std::string(baseline ? "new finding" : "finding") +
               "\" message=\"" + xml(g.key.rule + ", " + g.key.klass + ": " + what) + "\">" +
               xml("minimal scene (rastrules check SCENE --driver " + st.driver_name + "):\n" +
                   g.example) +
               "</failure>\n";
    } else {
      cases += "      <system-out>" +
               xml("known" + (g.known_as.empty() ? "" : " as " + g.known_as) + ": " + what) +
               "</system-out>\n";
    }
    cases += "    </testcase>\n";
  }
  // One per scene family: a failure when one of its cases is in a failing group.
  for (const auto& [family, n] : s.families) {
    ++tests;
    cases += "    <testcase classname=\"families\" name=\"" + xml(family) + "\" time=\"0\">\n";
    std::uint64_t bad = 0;
    for (const Finding& f : s.findings) {
      if (f.family != family)
        continue;
      for (const Group& g : s.groups) {
        if (g.key == f.group && failing(g, baseline))
          ++bad;
      }
    }
    const std::string what = u(n.cases) + " case(s), " + u(n.mismatches) + " mismatch(es)";
    if (bad != 0) {
      ++failures;
      cases += "      <failure type=\"" + std::string(baseline ? "new finding" : "finding") +
               "\" message=\"" + xml(what + ", " + u(bad) + " not in the baseline") +
               "\"></failure>\n";
    } else {
      cases += "      <system-out>" + xml(what) + "</system-out>\n";
    }
    cases += "    </testcase>\n";
  }
  for (const auto& [family, why] : s.families_not_generated) {
    ++tests;
    ++skipped;
    cases += "    <testcase classname=\"families\" name=\"" + xml(family) +
             "\" time=\"0\">\n      <skipped message=\"" + xml(why) + "\"/>\n    </testcase>\n";
  }
  if (s.skipped != 0) {
    ++tests;
    ++skipped;
    cases += "    <testcase classname=\"campaign\" name=\"unsupported cases\" time=\"0\">\n"
             "      <skipped message=\"" +
             xml(u(s.skipped) + " case(s) the driver reported unsupported in every attempt") +
             "\"/>\n    </testcase>\n";
  }
  if (!s.error.empty() || s.interrupted) {
    ++tests;
    ++errors;
    cases += "    <testcase classname=\"campaign\" name=\"campaign\" time=\"0\">\n"
             "      <error message=\"" +
             xml(s.interrupted ? "interrupted" : s.error) + "\"/>\n    </testcase>\n";
  }
  char time[32];
  std::snprintf(time, sizeof time, "%.3f", s.seconds);
  const std::string counts = "tests=\"" + u(tests) + "\" failures=\"" + u(failures) +
                             "\" errors=\"" + u(errors) + "\" skipped=\"" + u(skipped) +
                             "\" time=\"" + time + "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"rastrules fuzz\" " + counts + ">\n";
  out += "  <testsuite name=\"" + xml(suite_name(st)) + "\" " + counts + ">\n";
  out += "    <properties>\n";
  for (const auto& [name, value] : {std::pair<std::string, std::string>{"driver", st.driver_name},
                                    {"profile", std::string(to_string(st.profile))},
                                    {"mode", std::string(to_string(st.mode))},
                                    {"seed", u(st.seed)},
                                    {"cases", u(s.cases)},
                                    {"mismatches", u(s.mismatches)},
                                    {"baseline", baseline ? baseline->path : std::string()}}) {
    out += "      <property name=\"" + xml(name) + "\" value=\"" + xml(value) + "\"/>\n";
  }
  out += "    </properties>\n" + cases + "  </testsuite>\n</testsuites>\n";
  return out;
}

// rule: FUZZ.RESULTS
std::string summary_json(const Settings& st, const std::string& description, const Summary& s,
                         const Baseline* baseline) {
  json j = detail::campaign_json(st, description);
  j.update({{"cases", s.cases},
            {"mismatches", s.mismatches},
            {"unique_scenes", s.unique},
            {"line_allowance", s.line_allowance},
            {"tie_rounding", s.tie_rounding},
            {"seconds", s.seconds}});
  json skipped = {{"cases", s.skipped},
                  {"case_indices", s.skipped_cases},
                  {"reason", "the driver reported every generated scene unsupported (16 attempts "
                             "per case, FUZZ.GENERATE)"}};
  json families = json::array();
  for (const auto& [family, why] : s.families_not_generated)
    families.push_back({{"family", family}, {"reason", why}});
  skipped["families_not_generated"] = families;
  j["skipped"] = skipped;
  json fam = json::object();
  for (const auto& [name, n] : s.families)
    fam[name] = {{"cases", n.cases}, {"mismatches", n.mismatches}};
  j["families"] = fam;
  json groups = json::array();
  std::uint64_t known = 0, fresh = 0;
  for (const Group& g : s.groups) {
    json e = {{"rule", g.key.rule}, {"class", g.key.klass},           {"count", g.count},
              {"scenes", g.scenes}, {"example_case", g.example_case}, {"example", g.example}};
    if (!g.picture.empty())
      e["picture"] = g.picture;
    if (baseline != nullptr) {
      e["known"] = g.known;
      if (!g.known_as.empty())
        e["finding"] = g.known_as;
    }
    (g.known ? known : fresh) += 1;
    groups.push_back(e);
  }
  j["groups"] = groups;
  if (baseline != nullptr) {
    json unused = json::array();
    for (const BaselineEntry& b : baseline->known) {
      const bool seen = std::any_of(s.groups.begin(), s.groups.end(),
                                    [&](const Group& g) { return g.key == b.key; });
      if (!seen)
        unused.push_back({{"rule", b.key.rule}, {"class", b.key.klass}});
    }
    j["baseline"] = {{"path", baseline->path},
                     {"known_groups", known},
                     {"new_groups", fresh},
                     {"entries_not_seen", unused}};
  }
  if (!s.error.empty())
    j["error"] = s.error;
  if (s.interrupted)
    j["interrupted"] = true;
  const bool fails = baseline != nullptr ? fresh != 0 : s.mismatches != 0;
  j["result"] = !s.error.empty() || s.interrupted ? "error" : (fails ? "fail" : "pass");
  return j.dump(2) + "\n";
}

} // namespace rastrules::fuzzer
