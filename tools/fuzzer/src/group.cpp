// SPDX-License-Identifier: MIT
// Findings grouped by the rule that decided them and their class, and the baseline of known
// groups.
// Implements: FUZZ.GROUP, FUZZ.BASELINE

#include <bit>
#include <map>
#include <set>
#include <variant>

#include <nlohmann/json.hpp>

#include "json_file.hpp"
#include "rastrules/decision.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/rules.hpp"

namespace rastrules::fuzzer {
namespace {

// The rule that decided one sample for a primitive made of triangles: a covering triangle's
// tie edge (its fill rule) or its edge functions; for an uncovered sample, the fill rule when
// every edge that excludes it is a tie, else the culling or zero-area rule, else the edge
// functions (the sample is strictly outside).
std::string triangle_rule(const std::vector<TriangleDecision>& triangles) {
  for (const TriangleDecision& t : triangles) {
    if (!t.covered)
      continue;
    for (const EdgeDecision& e : t.edges) {
      if (e.e == EdgeValue{})
        return std::string(e.rule.id);
    }
    return std::string(rules::kTriEdgeFunction.id);
  }
  for (const TriangleDecision& t : triangles) {
    if (!t.has_edges || t.culled)
      continue;
    bool tie_only = false;
    bool strict = false;
    std::string rule;
    for (const EdgeDecision& e : t.edges) {
      if (e.inside)
        continue;
      if (e.e == EdgeValue{}) {
        tie_only = true;
        rule = std::string(e.rule.id);
      } else {
        strict = true;
      }
    }
    if (tie_only && !strict)
      return rule;
  }
  for (const TriangleDecision& t : triangles) {
    if (!t.has_edges || t.culled)
      return std::string(t.rule.id);
  }
  return std::string(rules::kTriEdgeFunction.id);
}

std::string pixel_rule(const Scene& scene, const Comparison& c, const DiffEntry& d) {
  // A pipeline scene's primitives are clipped and transformed before the rules decide: the
  // decision record (of window-space scenes) does not apply, and the group names the pipeline.
  if (has_pipeline_state(scene))
    return "SCENE.PIPELINE";
  auto prepared = prepare(scene);
  if (std::holds_alternative<SceneError>(prepared))
    return "SCENE.INPUT.ERRORS";
  const PixelDecision p = decide_pixel(std::get<PreparedScene>(prepared), d.prim, d.x, d.y);
  if (p.path)
    return std::string(rules::kScenePrimPath.id);
  const auto sample = static_cast<std::uint32_t>(std::countr_zero(d.mask));
  if (!p.segments.empty()) {
    // A line drawn without triangles: on a multisampled target both produce the pixel and
    // differ in its samples (MSAA.LINE.MODE), or the segment's own rule decided it.
    const bool both = std::any_of(c.actual.begin(), c.actual.end(),
                                  [&](const Fragment& f) {
                                    return f.prim == d.prim && f.x == d.x && f.y == d.y;
                                  }) &&
                      p.covered;
    if (scene.msaa.count() > 1 && both)
      return std::string(rules::kMsaaLineMode.id);
    for (const LineSegmentDecision& s : p.segments) {
      if (s.covered)
        return std::string(s.rule.id);
    }
    return std::string(p.segments.front().rule.id);
  }
  if (p.msaa && !p.msaa->samples.empty()) {
    for (const SampleDecision& s : p.msaa->samples) {
      if (s.index == sample)
        return triangle_rule(s.triangles);
    }
  }
  return triangle_rule(p.triangles);
}

} // namespace

// rule: FUZZ.GROUP
GroupKey classify(const Scene& scene, const Comparison& c) {
  const bool has_missing = !c.missing.empty();
  // rule: FUZZ.VALUES.EXACT
  // Equal coverage, different values: the rule of the first value beyond the allowance, and
  // the class names the primitive type and what differs ("triangle attr perspective",
  // "line depth d24").
  if (!has_missing && c.extra.empty() && c.values && !c.values->diffs.empty()) {
    const ValueDiff& d = c.values->diffs.front();
    GroupKey k;
    k.rule = d.rule;
    k.klass = d.prim < scene.primitives.size() ? std::string(name_of(scene.primitives[d.prim].type))
                                               : std::string("primitive");
    if (d.what.starts_with("depth")) {
      k.klass += " depth " + std::string(name_of(scene.conventions.depth));
    } else {
      const std::string name = d.what.substr(5);
      for (const pipe::AttributeDecl& a : scene.attributes) {
        if (a.name == name)
          k.klass += " attr " + std::string(name_of(a.interpolation));
      }
    }
    if (scene.msaa.count() > 1)
      k.klass += " " + std::to_string(scene.msaa.count()) + "x";
    return k;
  }
  if (!has_missing && c.extra.empty())
    return {};
  const DiffEntry& first = has_missing ? c.missing.front() : c.extra.front();
  Scene s = scene;
  s.conventions.fill = c.compared_with;
  GroupKey k;
  k.rule = pixel_rule(s, c, first);
  const auto of_prim = [&](const std::vector<DiffEntry>& list) {
    return std::any_of(list.begin(), list.end(),
                       [&](const DiffEntry& d) { return d.prim == first.prim; });
  };
  const bool missing = of_prim(c.missing), extra = of_prim(c.extra);
  k.klass = first.prim < scene.primitives.size()
                ? std::string(name_of(scene.primitives[first.prim].type))
                : std::string("primitive");
  k.klass += missing && extra ? " missing+extra" : (missing ? " missing" : " extra");
  if (scene.msaa.count() > 1)
    k.klass += " " + std::to_string(scene.msaa.count()) + "x";
  return k;
}

// rule: FUZZ.GROUP
std::vector<Group> group_findings(const std::vector<Finding>& findings) {
  std::map<GroupKey, Group> groups;
  std::map<GroupKey, std::set<std::string>> scenes;
  for (const Finding& f : findings) {
    Group& g = groups[f.group];
    if (g.count == 0) {
      g.key = f.group;
      g.example_case = f.case_index;
      g.example = f.key;
      g.picture = f.files.picture;
    }
    ++g.count;
    scenes[f.group].insert(f.key);
  }
  std::vector<Group> out;
  for (auto& [key, g] : groups) {
    g.scenes = scenes[key].size();
    out.push_back(std::move(g));
  }
  return out;
}

// rule: FUZZ.BASELINE
std::optional<Baseline> read_baseline(const std::string& path, std::string* error) {
  const auto read = detail::read_json_object(path, std::size_t{1} << 24, error);
  if (!read)
    return std::nullopt;
  const nlohmann::json& j = *read;
  if (!j.contains("version") || j["version"] != 1) {
    *error = path + ": version: must be 1";
    return std::nullopt;
  }
  if (!j.contains("known") || !j["known"].is_array()) {
    *error = path + ": known: must be an array";
    return std::nullopt;
  }
  Baseline b;
  b.path = path;
  for (std::size_t i = 0; i < j["known"].size(); ++i) {
    const nlohmann::json& e = j["known"][i];
    const std::string at = path + ": known[" + std::to_string(i) + "]";
    if (!e.is_object()) {
      *error = at + ": must be an object";
      return std::nullopt;
    }
    BaselineEntry entry;
    for (const auto& [name, field] : {std::pair<const char*, std::string*>{"rule", &entry.key.rule},
                                      {"class", &entry.key.klass},
                                      {"finding", &entry.finding},
                                      {"note", &entry.note}}) {
      const bool required = std::string_view(name) == "rule" || std::string_view(name) == "class";
      if (!e.contains(name)) {
        if (required) {
          *error = at + "." + name + ": missing";
          return std::nullopt;
        }
        continue;
      }
      if (!e[name].is_string() || (required && e[name].get<std::string>().empty())) {
        *error = at + "." + name + ": must be a non-empty string";
        return std::nullopt;
      }
      *field = e[name].get<std::string>();
    }
    b.known.push_back(std::move(entry));
  }
  return b;
}

// rule: FUZZ.BASELINE
std::uint64_t apply_baseline(const Baseline& baseline, Summary& s) {
  std::uint64_t unknown = 0;
  for (Group& g : s.groups) {
    for (const BaselineEntry& e : baseline.known) {
      if (e.key == g.key) {
        g.known = true;
        g.known_as = e.finding;
        break;
      }
    }
    if (!g.known)
      ++unknown;
  }
  return unknown;
}

} // namespace rastrules::fuzzer
