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

std::string read_text(const std::filesystem::path& p, bool& ok) {
  std::ifstream in(p, std::ios::binary);
  ok = static_cast<bool>(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

double stored_as_double(const kp::DepthValue& v, kp::DepthFormat f) {
  return f == kp::DepthFormat::kD32F ? static_cast<double>(v.f) : static_cast<double>(v.unorm);
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
  const auto fail = [&](const std::string& m) { r.failures.push_back(m); };

  // The sidecar.
  std::filesystem::path side = scene_path;
  side.replace_extension(".expect.json");
  bool ok = false;
  const std::string side_text = read_text(side, ok);
  json expect;
  if (!ok) {
    fail(side.filename().string() + ": missing");
    return r;
  }
  try {
    const json j = json::parse(side_text);
    for (const auto& id : j.at("rules"))
      r.rules.push_back(id.get<std::string>());
    r.what = j.at("what").get<std::string>();
    expect = j.value("expect", json::object());
  } catch (const std::exception& e) {
    fail(side.filename().string() + ": " + e.what());
    return r;
  }

  // The scene, through the pipeline with every optimization and with none.
  const std::string text = read_text(scene_path, ok);
  if (!ok) {
    fail(scene_path.filename().string() + ": cannot be read");
    return r;
  }
  auto read = io::read_scene(text);
  if (auto* e = std::get_if<SceneError>(&read)) {
    fail("scene: " + e->what());
    return r;
  }
  if (!has_pipeline_state(std::get<Scene>(read))) {
    fail("scene: not a pipeline scene (SCENE.PIPELINE)");
    return r;
  }
  const Scene& s = std::get<Scene>(read);
  auto fast_or = kp::run_pipeline(s);
  auto plain_or = kp::run_pipeline(s, kp::PipeOptions::plain());
  if (auto* e = std::get_if<SceneError>(&fast_or)) {
    fail("run_pipeline: " + e->what());
    return r;
  }
  const kp::PipeResult& res = std::get<kp::PipeResult>(fast_or);
  const kp::PipeResult& plain = std::get<kp::PipeResult>(plain_or);
  r.fragments = res.fragments.size();
  // rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR
  if (res.fragments != plain.fragments || res.data != plain.data ||
      res.depth_buffer != plain.depth_buffer)
    fail("the optimized result differs from the plain path (PIPE.OPT.*)");

  // Invariants and the oracle, fragment by fragment (check/).
  const kp::DepthFormat fmt = s.depth ? s.depth->format : kp::DepthFormat::kD24;
  const check::Mismatches values =
      check::check_pipeline_values(s, res, check::CheckOptions{8}, &r.oracle_checks);
  for (const std::string& m : values.mismatches)
    fail(m);
  if (values.count > 8)
    fail("... and " + std::to_string(values.count - 8) + " more");

  // The sidecar's expectations.
  try {
    std::map<std::uint32_t, std::size_t> per_prim, passed_per_prim, killed_per_prim;
    std::set<std::uint32_t> parts;
    std::set<double> depths;
    for (std::size_t i = 0; i < res.fragments.size(); ++i) {
      const Fragment& f = res.fragments[i];
      ++per_prim[f.prim];
      const bool has_data = !res.data.empty();
      const std::uint32_t passed = has_data ? res.data[i].passed : f.mask;
      if (passed != 0)
        ++passed_per_prim[f.prim];
      if (s.depth && passed == 0 && !f.helper)
        ++killed_per_prim[f.prim];
      if (has_data && res.data[i].part)
        parts.insert(*res.data[i].part);
      if (has_data)
        for (const auto& z : res.data[i].depth)
          depths.insert(stored_as_double(z, fmt));
    }
    const auto count_map = [](const json& j) {
      std::map<std::uint32_t, std::size_t> m;
      for (const auto& [k, v] : j.items())
        m[static_cast<std::uint32_t>(std::stoul(k))] = v.get<std::size_t>();
      return m;
    };
    const auto compare_counts = [&](const char* key,
                                    const std::map<std::uint32_t, std::size_t>& got) {
      if (!expect.contains(key))
        return;
      for (const auto& [prim, want] : count_map(expect.at(key))) {
        const auto it = got.find(prim);
        const std::size_t have = it == got.end() ? 0 : it->second;
        if (have != want)
          fail(std::string(key) + "[" + std::to_string(prim) + "]: expected " +
               std::to_string(want) + ", got " + std::to_string(have));
      }
    };
    if (expect.contains("fragments") &&
        expect.at("fragments").get<std::size_t>() != res.fragments.size())
      fail("fragments: expected " + std::to_string(expect.at("fragments").get<std::size_t>()) +
           ", got " + std::to_string(res.fragments.size()));
    compare_counts("fragments_per_prim", per_prim);
    compare_counts("passed_per_prim", passed_per_prim);
    compare_counts("killed_per_prim", killed_per_prim);
    if (expect.contains("parts")) {
      const auto want = expect.at("parts").get<std::set<std::uint32_t>>();
      if (want != parts)
        fail("parts: not the expected set");
    }
    if (expect.contains("depth_values")) {
      const auto want = expect.at("depth_values").get<std::set<double>>();
      if (want != depths) {
        std::string got;
        for (const double z : depths)
          got += " " + std::to_string(z);
        fail("depth_values: not the expected set; got" + got);
      }
    }
    if (expect.contains("depth_range")) {
      const auto range = expect.at("depth_range").get<std::array<double, 2>>();
      if (!depths.empty() && (*depths.begin() < range[0] || *depths.rbegin() > range[1]))
        fail("depth_range: a stored depth lies outside [" + std::to_string(range[0]) + ", " +
             std::to_string(range[1]) + "]");
    }
    if (expect.contains("attr_range")) {
      for (const auto& [name, range_j] : expect.at("attr_range").items()) {
        const auto range = range_j.get<std::array<double, 2>>();
        std::size_t a = 0;
        while (a < s.attributes.size() && s.attributes[a].name != name)
          ++a;
        if (a == s.attributes.size()) {
          fail("attr_range: no attribute " + name);
          continue;
        }
        for (const auto& d : res.data)
          if (a < d.attr.size() && (d.attr[a] < range[0] || d.attr[a] > range[1])) {
            fail("attr_range: " + name + " = " + std::to_string(d.attr[a]) + " outside the range");
            break;
          }
      }
    }
    if (expect.contains("hiz_rejected_at_least") &&
        res.stats.hiz_rejected < expect.at("hiz_rejected_at_least").get<std::uint64_t>())
      fail("hiz_rejected_at_least: Hi-Z rejected " + std::to_string(res.stats.hiz_rejected));
    for (const auto& [key, v] : expect.items()) {
      static const std::set<std::string> known = {
          "fragments",    "fragments_per_prim", "passed_per_prim", "killed_per_prim",      "parts",
          "depth_values", "depth_range",        "attr_range",      "hiz_rejected_at_least"};
      if (!known.contains(key))
        fail("expect." + key + ": unknown expectation");
      (void)v;
    }
  } catch (const std::exception& e) {
    fail(side.filename().string() + ": " + e.what());
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
