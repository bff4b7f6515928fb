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

#include "rastrules/io/scene_json.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::cases {

namespace {

namespace kp = rastrules::pipe;
namespace op = rastrules::oracle::pipe;
using nlohmann::json;

std::string read_text(const std::filesystem::path& p, bool& ok) {
  std::ifstream in(p, std::ios::binary);
  ok = static_cast<bool>(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string where(const Fragment& f) {
  return "prim " + std::to_string(f.prim) + " pixel (" + std::to_string(f.x) + ", " +
         std::to_string(f.y) + ")";
}

op::Raw2 raw(Vec2 v) {
  return {v.x.raw(), v.y.raw()};
}

// The oracle's barycentrics of drawn primitive d at s: a triangle's exact edge values, a line's
// projection parameter (as in the kernel's output, SCENE.OUTPUT.PIPELINE), a point's (1, 0, 0).
op::Bary bary_of(const kp::DrawnPrimitive& d, Vec2 s) {
  if (d.type == PrimitiveType::kTriangle)
    return op::barycentrics({raw(d.snapped[0]), raw(d.snapped[1]), raw(d.snapped[2])}, raw(s));
  op::Bary b;
  if (d.type == PrimitiveType::kPoint || d.snapped.size() < 2) {
    b.e = {1, 0, 0};
    b.area = 1;
    return b;
  }
  const std::int64_t dx = d.snapped[1].x.raw() - d.snapped[0].x.raw();
  const std::int64_t dy = d.snapped[1].y.raw() - d.snapped[0].y.raw();
  const std::int64_t px = s.x.raw() - d.snapped[0].x.raw();
  const std::int64_t py = s.y.raw() - d.snapped[0].y.raw();
  const std::int64_t den = dx * dx + dy * dy, num = px * dx + py * dy;
  b.e = {den - num, num, 0};
  b.area = den;
  return b;
}

std::string format_name(kp::DepthFormat f) {
  return std::string(kp::to_string(f));
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
  auto read = io::read_any_scene(text);
  if (auto* e = std::get_if<SceneError>(&read)) {
    fail("scene: " + e->what());
    return r;
  }
  if (!std::holds_alternative<kp::PipeScene>(read)) {
    fail("scene: not a pipeline scene (SCENE.PIPELINE)");
    return r;
  }
  const kp::PipeScene& s = std::get<kp::PipeScene>(read);
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

  // Invariants and the oracle, fragment by fragment.
  const kp::Viewport vp = s.viewport.value_or(kp::Viewport{
      0, 0, static_cast<float>(s.base.width), static_cast<float>(s.base.height), 0, 1});
  const SamplePattern& pattern = s.base.msaa.pattern;
  const kp::DepthFormat fmt = s.depth ? s.depth->format : kp::DepthFormat::kD24;
  const kp::DepthValue lo = kp::to_depth_format(vp.min_depth, 0, 1, fmt);
  const kp::DepthValue hi = kp::to_depth_format(vp.max_depth, 0, 1, fmt);
  std::size_t reported = 0;
  const auto report = [&](const std::string& m) {
    if (++reported <= 8)
      fail(m);
  };
  for (std::size_t i = 0; i < res.data.size(); ++i) {
    const Fragment& f = res.fragments[i];
    const kp::FragmentData& d = res.data[i];
    if (d.bary && d.bary->e[0] + d.bary->e[1] + d.bary->e[2] != d.bary->area)
      report(where(f) + ": barycentrics do not sum to the area (PIPE.BARY.SUM)");
    for (const float a : d.attr)
      if (!std::isfinite(a))
        report(where(f) + ": an attribute is not finite (PIPE.INTERP.HORIZON)");
    for (const kp::DepthValue& z : d.depth)
      if (stored_as_double(z, fmt) < stored_as_double(lo, fmt) ||
          stored_as_double(z, fmt) > stored_as_double(hi, fmt) ||
          (fmt == kp::DepthFormat::kD32F && !std::isfinite(z.f)))
        report(where(f) + ": a stored depth lies outside the viewport's range (PIPE.DEPTH.CLAMP)");
    if (res.drawn.empty())
      continue;
    const kp::DrawnPrimitive& dp = res.drawn[d.drawn];
    // Attributes against the exact oracle (PIPE.INTERP.BOUND).
    for (std::size_t a = 0; a < d.attr.size(); ++a) {
      const kp::AttributeDecl& decl = s.attributes[a];
      Vec2 at = pixel_center(f.x, f.y);
      if (decl.location == kp::Location::kCentroid && f.centroid)
        at = sample_position(f.x, f.y, f.centroid->offset);
      if (decl.location == kp::Location::kSample && f.sample)
        at = sample_position(f.x, f.y, pattern.positions[*f.sample]);
      const op::Bary b = bary_of(dp, at);
      ++r.oracle_checks;
      if (decl.interpolation == kp::Interpolation::kFlat) {
        if (d.attr[a] != dp.flat[a])
          report(where(f) + ": flat attribute " + decl.name + " is not the provoking vertex's");
        continue;
      }
      if (b.area == 0)
        continue; // a zero-length line: the flat value (PIPE.INTERP.HORIZON)
      const op::InterpCheck c =
          decl.interpolation == kp::Interpolation::kPerspective
              ? op::check_perspective(b, dp.attr[a], dp.w, dp.flat[a], d.attr[a])
              : op::check_linear(b, dp.attr[a], d.attr[a]);
      if (!c.ok)
        report(where(f) + ": attribute " + decl.name + ": " + c.describe());
    }
    // Depths against the exact oracle (PIPE.DEPTH.BOUND).
    std::size_t n = 0;
    for (std::uint32_t k = 0; k < pattern.count() && n < d.depth.size(); ++k) {
      if ((f.mask & (1u << k)) == 0)
        continue;
      const op::Bary b = bary_of(dp, sample_position(f.x, f.y, pattern.positions[k]));
      const kp::DepthValue& got = d.depth[n++];
      ++r.oracle_checks;
      if (b.area == 0)
        continue;
      const op::DepthCheck c = op::check_depth_stored(
          b, dp.z, vp.min_depth, vp.max_depth, format_name(fmt), op::Stored{got.unorm, got.f});
      if (!c.ok)
        report(where(f) + ": sample " + std::to_string(k) + ": " + c.describe(format_name(fmt)));
    }
  }
  if (reported > 8)
    fail("... and " + std::to_string(reported - 8) + " more");

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
