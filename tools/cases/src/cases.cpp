// SPDX-License-Identifier: MIT
// The hard-case catalog checker (spec/cases/README.md, PIPE.CATALOG).
#include "rastrules/cases/cases.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <variant>

#include <nlohmann/json.hpp>

#include "rastrules/check/check.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::cases {

namespace {

namespace kp = rastrules::pipe;
using nlohmann::json;

// Returns the file's bytes, or nullopt (and `problem` recorded in r) when it cannot be opened.
std::optional<std::string> read_text(const std::filesystem::path& p, const char* problem,
                                     CaseReport& r) {
  std::ifstream in(p, std::ios::binary);
  if (!in) {
    r.failures.push_back(p.filename().string() + ": " + problem);
    return std::nullopt;
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

double stored_as_double(const kp::DepthValue& v, kp::DepthFormat f) {
  return f == kp::DepthFormat::kD32F ? static_cast<double>(v.f) : static_cast<double>(v.unorm);
}

using Counts = std::map<std::uint32_t, std::size_t>;

// What a pipeline result holds, counted as the sidecar's expectations name it.
struct Tally {
  Counts per_prim, passed_per_prim, killed_per_prim; // fragments per primitive
  std::set<std::uint32_t> parts;                     // the parts fragments came from
  std::set<double> depths;                           // every stored depth value
};

// Returns the expectations object of the sidecar `side` and sets r.rules and
// r.what, or nullopt when the sidecar is missing or malformed (the failure
// recorded in r).
std::optional<json> read_sidecar(const std::filesystem::path& side, CaseReport& r) {
  const std::optional<std::string> side_text = read_text(side, "missing", r);
  if (!side_text)
    return std::nullopt;
  try {
    const json j = json::parse(*side_text);
    for (const auto& id : j.at("rules"))
      r.rules.push_back(id.get<std::string>());
    r.what = j.at("what").get<std::string>();
    return j.value("expect", json::object());
  } catch (const std::exception& e) {
    r.failures.push_back(side.filename().string() + ": " + e.what());
    return std::nullopt;
  }
}

// Returns the pipeline scene at `path`, or nullopt when it cannot be read or is
// not a pipeline scene (the failure recorded in r).
std::optional<Scene> read_pipe_scene(const std::filesystem::path& path, CaseReport& r) {
  const std::optional<std::string> text = read_text(path, "cannot be read", r);
  if (!text)
    return std::nullopt;
  auto read = io::read_scene(*text);
  if (auto* e = std::get_if<SceneError>(&read)) {
    r.failures.push_back("scene: " + e->what());
    return std::nullopt;
  }
  if (!has_pipeline_state(std::get<Scene>(read))) {
    r.failures.push_back("scene: not a pipeline scene (SCENE.PIPELINE)");
    return std::nullopt;
  }
  return std::get<Scene>(std::move(read));
}

// Returns the counts of res that the expectations compare with.
Tally tally(const Scene& s, const kp::PipeResult& res) {
  const kp::DepthFormat fmt = s.depth ? s.conventions.depth : kp::DepthFormat::kD24;
  Tally t;
  for (std::size_t i = 0; i < res.fragments.size(); ++i) {
    const Fragment& f = res.fragments[i];
    ++t.per_prim[f.prim];
    const bool has_data = !res.data.empty();
    const std::uint32_t passed = has_data ? res.data[i].passed : f.mask;
    if (passed != 0)
      ++t.passed_per_prim[f.prim];
    if (s.depth && passed == 0 && !f.helper)
      ++t.killed_per_prim[f.prim];
    if (has_data && res.data[i].part)
      t.parts.insert(*res.data[i].part);
    if (has_data)
      for (const auto& z : res.data[i].depth)
        t.depths.insert(stored_as_double(z, fmt));
  }
  return t;
}

// Returns an object from primitive index to count as a map, sorted by primitive. Throws on bad
// JSON.
Counts count_map(const json& j) {
  Counts m;
  for (const auto& [k, v] : j.items())
    m[static_cast<std::uint32_t>(std::stoul(k))] = v.get<std::size_t>();
  return m;
}

// Records in `failures` each primitive whose count in `got` differs from expect[key], when the
// sidecar has that key. Throws on bad JSON.
void compare_counts(const json& expect, const char* key, const Counts& got,
                    std::vector<std::string>& failures) {
  if (!expect.contains(key))
    return;
  for (const auto& [prim, want] : count_map(expect.at(key))) {
    const auto it = got.find(prim);
    const std::size_t have = it == got.end() ? 0 : it->second;
    if (have != want)
      failures.push_back(std::string(key) + "[" + std::to_string(prim) + "]: expected " +
                         std::to_string(want) + ", got " + std::to_string(have));
  }
}

// Records in `failures` each stored depth that is not as expect's depth_values
// and depth_range say. Throws on bad JSON.
void compare_depths(const json& expect, const std::set<double>& depths,
                    std::vector<std::string>& failures) {
  if (expect.contains("depth_values")) {
    const auto want = expect.at("depth_values").get<std::set<double>>();
    if (want != depths) {
      std::string got;
      for (const double z : depths)
        got += " " + std::to_string(z);
      failures.push_back("depth_values: not the expected set; got" + got);
    }
  }
  if (expect.contains("depth_range")) {
    const auto range = expect.at("depth_range").get<std::array<double, 2>>();
    if (!depths.empty() && (*depths.begin() < range[0] || *depths.rbegin() > range[1]))
      failures.push_back("depth_range: a stored depth lies outside [" + std::to_string(range[0]) +
                         ", " + std::to_string(range[1]) + "]");
  }
}

// Records in `failures` each attribute of expect's attr_range that is unknown
// or that some fragment interpolates outside its range (the first such value).
// Throws on bad JSON.
void compare_attr_ranges(const json& expect, const Scene& s, const kp::PipeResult& res,
                         std::vector<std::string>& failures) {
  if (!expect.contains("attr_range"))
    return;
  for (const auto& [name, range_j] : expect.at("attr_range").items()) {
    const auto range = range_j.get<std::array<double, 2>>();
    std::size_t a = 0;
    while (a < s.attributes.size() && s.attributes[a].name != name)
      ++a;
    if (a == s.attributes.size()) {
      failures.push_back("attr_range: no attribute " + name);
      continue;
    }
    for (const auto& d : res.data)
      if (a < d.attr.size() && (d.attr[a] < range[0] || d.attr[a] > range[1])) {
        failures.push_back("attr_range: " + name + " = " + std::to_string(d.attr[a]) +
                           " outside the range");
        break;
      }
  }
}

// Records in `failures` every expectation of the sidecar that res does not
// meet, and every key the sidecar names that is not an expectation. Throws on
// bad JSON.
void compare_expectations(const json& expect, const Scene& s, const kp::PipeResult& res,
                          std::vector<std::string>& failures) {
  const Tally t = tally(s, res);
  if (expect.contains("fragments") &&
      expect.at("fragments").get<std::size_t>() != res.fragments.size())
    failures.push_back("fragments: expected " +
                       std::to_string(expect.at("fragments").get<std::size_t>()) + ", got " +
                       std::to_string(res.fragments.size()));
  compare_counts(expect, "fragments_per_prim", t.per_prim, failures);
  compare_counts(expect, "passed_per_prim", t.passed_per_prim, failures);
  compare_counts(expect, "killed_per_prim", t.killed_per_prim, failures);
  if (expect.contains("parts")) {
    const auto want = expect.at("parts").get<std::set<std::uint32_t>>();
    if (want != t.parts)
      failures.push_back("parts: not the expected set");
  }
  compare_depths(expect, t.depths, failures);
  compare_attr_ranges(expect, s, res, failures);
  if (expect.contains("hiz_rejected_at_least") &&
      res.stats.hiz_rejected < expect.at("hiz_rejected_at_least").get<std::uint64_t>())
    failures.push_back("hiz_rejected_at_least: Hi-Z rejected " +
                       std::to_string(res.stats.hiz_rejected));
  static const std::set<std::string> known = {
      "fragments",    "fragments_per_prim", "passed_per_prim", "killed_per_prim",      "parts",
      "depth_values", "depth_range",        "attr_range",      "hiz_rejected_at_least"};
  for (const auto& [key, v] : expect.items()) {
    if (!known.contains(key))
      failures.push_back("expect." + key + ": unknown expectation");
    (void)v;
  }
}

} // namespace

std::vector<std::filesystem::path> catalog(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string n = e.path().filename().string();
    if (e.is_regular_file() && n.size() > 5 && n.ends_with(".json") && !n.ends_with(".expect.json"))
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// rule: PIPE.CATALOG
CaseReport check_case(const std::filesystem::path& scene_path) {
  CaseReport r;
  r.name = scene_path.stem().string();
  std::filesystem::path side = scene_path;
  side.replace_extension(".expect.json");
  const std::optional<json> expect = read_sidecar(side, r);
  if (!expect)
    return r;

  // The scene, through the pipeline with every optimization and with none.
  const std::optional<Scene> s = read_pipe_scene(scene_path, r);
  if (!s)
    return r;
  auto fast_or = kp::run_pipeline(*s);
  auto plain_or = kp::run_pipeline(*s, kp::PipeOptions::plain());
  if (auto* e = std::get_if<SceneError>(&fast_or)) {
    r.failures.push_back("run_pipeline: " + e->what());
    return r;
  }
  const kp::PipeResult& res = std::get<kp::PipeResult>(fast_or);
  const kp::PipeResult& plain = std::get<kp::PipeResult>(plain_or);
  r.fragments = res.fragments.size();
  // rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR
  if (res.fragments != plain.fragments || res.data != plain.data ||
      res.depth_buffer != plain.depth_buffer)
    r.failures.push_back("the optimized result differs from the plain path (PIPE.OPT.*)");

  // Invariants and the oracle, fragment by fragment (check/).
  check::PipelineStats stats;
  const check::Mismatches values = check::check_pipeline(*s, res, check::CheckOptions{8}, &stats);
  r.oracle_checks = stats.values_checked;
  for (const std::string& m : values.mismatches)
    r.failures.push_back(m);
  if (values.count > 8)
    r.failures.push_back("... and " + std::to_string(values.count - 8) + " more");

  // The sidecar's expectations.
  try {
    compare_expectations(*expect, *s, res, r.failures);
  } catch (const std::exception& e) {
    r.failures.push_back(side.filename().string() + ": " + e.what());
  }
  return r;
}

std::string format_report(const std::vector<CaseReport>& reports) {
  std::ostringstream o;
  std::size_t failed = 0;
  for (const CaseReport& r : reports) {
    if (r.ok()) {
      o << "OK    " << r.name << "  (" << r.fragments << " fragments, " << r.oracle_checks
        << " values checked against the exact oracle)";
      for (std::size_t i = 0; i < r.rules.size(); ++i)
        o << (i == 0 ? "  " : ", ") << r.rules[i];
      o << "\n";
    } else {
      ++failed;
      o << "FAIL  " << r.name << "\n";
      for (const std::string& m : r.failures)
        o << "        " << m << "\n";
    }
  }
  o << reports.size() - failed << " of " << reports.size() << " cases hold\n";
  return o.str();
}

} // namespace rastrules::cases
