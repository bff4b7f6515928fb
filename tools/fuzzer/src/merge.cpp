// SPDX-License-Identifier: MIT
// Joining the reports of shard campaigns into the campaign they split.
// Implements: FUZZ.MERGE

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <variant>

#include <nlohmann/json.hpp>

#include "json_file.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer {
namespace {

using nlohmann::json;

std::vector<DiffEntry> diff_list(const json& a) {
  std::vector<DiffEntry> out;
  for (const json& d : a)
    out.push_back({d.at("prim").get<std::uint32_t>(), d.at("x").get<std::int32_t>(),
                   d.at("y").get<std::int32_t>(), d.at("mask").get<std::uint32_t>()});
  return out;
}

// rule: FUZZ.VALUES.REPORT
// Reads a value entry back (what value_json wrote; a distance written as null is infinite).
ValueDiff value_of(const json& e) {
  ValueDiff d;
  d.prim = e.at("prim").get<std::uint32_t>();
  d.x = e.at("x").get<std::int32_t>();
  d.y = e.at("y").get<std::int32_t>();
  for (const auto& [key, field] :
       {std::pair{"part", &d.part}, std::pair{"seg", &d.seg}, std::pair{"sample", &d.sample}}) {
    if (e.contains(key))
      *field = e.at(key).get<std::uint32_t>();
  }
  d.what = e.at("value").get<std::string>();
  d.rule = e.at("rule").get<std::string>();
  const auto number = [&](const char* key) {
    const json& v = e.at(key);
    return v.is_null() ? std::numeric_limits<double>::infinity() : v.get<double>();
  };
  d.expected = number("exact");
  d.reference = number("reference");
  d.got = number("got");
  d.distance = number("distance");
  d.allowed = number("allowed");
  d.within = e.at("within").get<bool>();
  return d;
}

std::optional<ValueDiff> worst_of(const json& e) {
  return e.is_null() ? std::nullopt : std::optional<ValueDiff>(value_of(e));
}

// Reads one finding of a report back (what finding_json wrote).
Finding finding_of(const json& e) {
  Finding f;
  f.case_index = e.at("case").get<std::uint64_t>();
  f.family = e.at("family").get<std::string>();
  f.key = e.at("shrunk_text").get<std::string>();
  f.group = {e.at("rule").get<std::string>(), e.at("class").get<std::string>()};
  f.comparison.missing = diff_list(e.at("missing"));
  f.comparison.extra = diff_list(e.at("extra"));
  if (auto fill = from_name<FillConvention>(e.at("compared_with_fill").get<std::string>()))
    f.comparison.compared_with = *fill;
  if (e.contains("values")) { // rule: FUZZ.VALUES.REPORT
    const json& v = e.at("values");
    ValueComparison c;
    c.attributes = v.at("attributes").get<std::uint64_t>();
    c.depths = v.at("depths").get<std::uint64_t>();
    c.beyond = v.at("beyond").get<std::uint64_t>();
    for (const json& d : v.at("differences"))
      c.diffs.push_back(value_of(d));
    c.worst_attribute = worst_of(v.at("worst_attribute"));
    c.worst_depth = worst_of(v.at("worst_depth"));
    f.comparison.values = std::move(c);
  }
  if (auto shrunk = io::read_scene(f.key); std::holds_alternative<Scene>(shrunk))
    f.shrunk = std::get<Scene>(std::move(shrunk));
  // Only the count of the generated scene's primitives is in the report; its scene file is.
  f.original.primitives.resize(e.at("primitives_before").get<std::size_t>());
  if (e.contains("scene")) {
    f.files.scene = e.at("scene").get<std::string>();
    f.files.shrunk = e.at("shrunk_scene").get<std::string>();
    f.files.picture = e.at("picture").get<std::string>();
    f.files.report = e.at("report").get<std::string>();
  }
  return f;
}

} // namespace

// rule: FUZZ.MERGE
std::optional<Summary> merge_reports(const std::vector<std::string>& dirs, Settings* settings,
                                     std::string* description, std::string* error) {
  if (dirs.empty()) {
    *error = "no shard report to merge";
    return std::nullopt;
  }
  Summary s;
  std::set<std::uint64_t> shards;
  std::map<FillConvention, std::uint64_t> tally;
  json first;
  for (const std::string& dir : dirs) {
    const std::string path = (std::filesystem::path(dir) / "report.json").string();
    auto j = detail::read_json_object(path, std::size_t{1} << 28, error);
    if (!j)
      return std::nullopt;
    try {
      if (first.is_null()) {
        first = *j;
        settings->driver_name = j->at("driver").get<std::string>();
        *description = j->at("description").get<std::string>();
        settings->profile = parse_profile(j->at("profile").get<std::string>()).value();
        settings->mode = parse_mode(j->at("mode").get<std::string>()).value();
        settings->seed = j->at("seed").get<std::uint64_t>();
        settings->cases = j->at("campaign_cases").get<std::uint64_t>();
        settings->shard_count = j->at("shard").at("count").get<std::uint64_t>();
        settings->shard_index = 0;
        if (j->contains("families_selected"))
          settings->families = j->at("families_selected").get<std::vector<std::string>>();
        settings->values = j->value("values_campaign", false);
      }
      // Shards of one campaign are all values campaigns or none. rule: FUZZ.VALUES.GENERATE
      if (j->value("values_campaign", false) != settings->values) {
        *error = path + ": values_campaign " + (settings->values ? "absent" : "true") +
                 " where the first report has " + (settings->values ? "true" : "none");
        return std::nullopt;
      }
      // Shards of one campaign select the same families. rule: FUZZ.FAMILIES
      if (j->value("families_selected", nlohmann::json()) !=
          first.value("families_selected", nlohmann::json())) {
        *error = path + ": families_selected " +
                 j->value("families_selected", nlohmann::json()).dump() + " differ from " +
                 first.value("families_selected", nlohmann::json()).dump() + " in the first report";
        return std::nullopt;
      }
      for (const char* key : {"driver", "profile", "mode", "seed", "campaign_cases"}) {
        if (j->at(key) != first.at(key)) {
          *error = path + ": " + key + " " + j->at(key).dump() + " differs from " +
                   first.at(key).dump() + " in the first report";
          return std::nullopt;
        }
      }
      const std::uint64_t count = j->at("shard").at("count").get<std::uint64_t>();
      const std::uint64_t index = j->at("shard").at("index").get<std::uint64_t>();
      if (count != settings->shard_count) {
        *error = path + ": shard count " + std::to_string(count) + " differs from " +
                 std::to_string(settings->shard_count) + " in the first report";
        return std::nullopt;
      }
      if (!shards.insert(index).second) {
        *error = path + ": shard " + std::to_string(index) + "/" + std::to_string(count) +
                 " given twice";
        return std::nullopt;
      }
      if (j->contains("error") || j->contains("interrupted")) {
        *error = path + ": the shard did not finish" +
                 (j->contains("error") ? ": " + j->at("error").get<std::string>() : "");
        return std::nullopt;
      }
      s.cases += j->at("cases").get<std::uint64_t>();
      s.skipped += j->at("skipped").get<std::uint64_t>();
      for (const json& c : j->at("skipped_cases"))
        s.skipped_cases.push_back(c.get<std::uint64_t>());
      s.line_allowance += j->at("line_allowance").get<std::uint64_t>();
      s.tie_rounding += j->at("tie_rounding").get<std::uint64_t>();
      s.seconds += j->at("seconds").get<double>();
      for (const auto& [name, n] : j->at("families").items()) {
        s.families[name].cases += n.at("cases").get<std::uint64_t>();
        s.families[name].mismatches += n.at("mismatches").get<std::uint64_t>();
      }
      // The same for every shard (the driver and profile are): the first report's, in order.
      if (dir == dirs.front()) {
        for (const json& e : j->at("families_not_generated"))
          s.families_not_generated.emplace_back(e.at("family").get<std::string>(),
                                                e.at("reason").get<std::string>());
      }
      if (j->contains("fill_conventions_matched")) {
        for (const auto& [name, n] : j->at("fill_conventions_matched").items()) {
          if (auto f = from_name<FillConvention>(name))
            tally[*f] += n.get<std::uint64_t>();
        }
      }
      // rule: FUZZ.VALUES.REPORT
      if (j->contains("values")) {
        const json& v = j->at("values");
        s.value_cases += v.at("cases").get<std::uint64_t>();
        s.value_attributes += v.at("attributes").get<std::uint64_t>();
        s.value_depths += v.at("depths").get<std::uint64_t>();
        const auto keep = [&](const char* key, std::optional<ValueDiff>& worst, std::uint64_t& at) {
          const auto d = worst_of(v.at(key));
          const std::uint64_t c = d ? v.at(key).at("case").get<std::uint64_t>() : 0;
          if (d && (!worst || d->distance > worst->distance ||
                    (d->distance == worst->distance && c < at))) {
            worst = d;
            at = c;
          }
        };
        keep("worst_attribute", s.worst_attribute, s.worst_attribute_case);
        keep("worst_depth", s.worst_depth, s.worst_depth_case);
      }
      for (const json& e : j->at("findings"))
        s.findings.push_back(finding_of(e));
    } catch (const std::exception& e) {
      *error = path + ": not a campaign report: " + e.what();
      return std::nullopt;
    }
  }
  if (shards.size() != settings->shard_count) {
    std::string absent;
    for (std::uint64_t k = 0; k < settings->shard_count; ++k) {
      if (shards.count(k) == 0)
        absent += (absent.empty() ? "" : ", ") + std::to_string(k);
    }
    *error = "shard(s) " + absent + " of " + std::to_string(settings->shard_count) + " missing";
    return std::nullopt;
  }
  // The unsharded campaign's order and deduplication: by case, first shrunk scene first.
  std::sort(s.findings.begin(), s.findings.end(),
            [](const Finding& a, const Finding& b) { return a.case_index < b.case_index; });
  std::sort(s.skipped_cases.begin(), s.skipped_cases.end());
  std::map<std::string, std::uint64_t> firsts;
  for (Finding& f : s.findings) {
    if (const auto it = firsts.find(f.key); it != firsts.end()) {
      f.duplicate_of = it->second;
    } else {
      f.duplicate_of.reset();
      firsts.emplace(f.key, f.case_index);
    }
  }
  s.mismatches = s.findings.size();
  s.unique = firsts.size();
  for (const auto& [f, n] : tally)
    s.legal_conventions.emplace_back(f, n);
  s.groups = group_findings(s.findings);
  settings->shard_count = 1;
  return s;
}

} // namespace rastrules::fuzzer
