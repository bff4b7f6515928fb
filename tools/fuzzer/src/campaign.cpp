// SPDX-License-Identifier: MIT
// Campaigns: generate, draw, compare, shrink every mismatch and write its outputs.
// Implements: FUZZ.GENERATE, FUZZ.SHRINK, FUZZ.REPORT

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "json_file.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/fuzzer/html_report.hpp"
#include "rastrules/io/interrupt.hpp"
#include "rastrules/io/output_file.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer {
namespace {

using nlohmann::json;

json diff_json(const std::vector<DiffEntry>& list) {
  json a = json::array();
  for (const DiffEntry& d : list)
    a.push_back({{"prim", d.prim}, {"x", d.x}, {"y", d.y}, {"mask", d.mask}});
  return a;
}

std::string origin_note(Profile p) {
  return p == Profile::kOpenGL ? "lower-left in OpenGL; scenes and reports use the y-down frame of "
                                 "spec/conventions.md (the opengl adapter sets an upper-left "
                                 "origin with glClipControl)"
                               : "upper-left";
}

// rule: FUZZ.VALUES.REPORT
json value_json(const ValueDiff& d) {
  json j = {{"prim", d.prim}, {"x", d.x}, {"y", d.y}};
  if (d.part)
    j["part"] = *d.part;
  if (d.seg)
    j["seg"] = *d.seg;
  if (d.sample)
    j["sample"] = *d.sample;
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  j.update({{"value", d.what},
            {"rule", d.rule},
            {"exact", number(d.expected)},
            {"reference", number(d.reference)},
            {"got", number(d.got)},
            {"distance", number(d.distance)},
            {"allowed", number(d.allowed)},
            {"within", d.within}});
  return j;
}

json values_json(const ValueComparison& v) {
  json diffs = json::array();
  for (const ValueDiff& d : v.diffs)
    diffs.push_back(value_json(d));
  json j = {{"attributes", v.attributes},
            {"depths", v.depths},
            {"beyond", v.beyond},
            {"differences", diffs}};
  j["worst_attribute"] = v.worst_attribute ? value_json(*v.worst_attribute) : json(nullptr);
  j["worst_depth"] = v.worst_depth ? value_json(*v.worst_depth) : json(nullptr);
  return j;
}

json finding_json(const Finding& f, const Settings& s, const std::string& driver) {
  json j = {{"seed", s.seed},
            {"case", f.case_index},
            {"family", f.family},
            {"driver", driver},
            {"profile", std::string(to_string(s.profile))},
            {"mode", std::string(to_string(s.mode))},
            {"origin", origin_note(s.profile)},
            {"compared_with_fill", std::string(to_string(f.comparison.compared_with))},
            {"primitives_before", f.original.primitives.size()},
            {"primitives_after", f.shrunk.primitives.size()},
            {"rule", f.group.rule},
            {"class", f.group.klass},
            {"missing", diff_json(f.comparison.missing)},
            {"extra", diff_json(f.comparison.extra)},
            {"shrunk_text", f.key}};
  if (f.comparison.values)
    j["values"] = values_json(*f.comparison.values);
  if (f.duplicate_of)
    j["duplicate_of"] = *f.duplicate_of;
  if (!f.files.scene.empty()) {
    j["scene"] = f.files.scene;
    j["shrunk_scene"] = f.files.shrunk;
    j["picture"] = f.files.picture;
    j["report"] = f.files.report;
  }
  return j;
}

json families_json(const Summary& s) {
  json j = json::object();
  for (const auto& [name, n] : s.families)
    j[name] = {{"cases", n.cases}, {"mismatches", n.mismatches}};
  return j;
}

json not_generated_json(const Summary& s) {
  json j = json::array();
  for (const auto& [family, why] : s.families_not_generated)
    j.push_back({{"family", family}, {"reason", why}});
  return j;
}

// Writes a report file; it appears only when complete (io::write_text).
bool write_text(const std::string& path, const std::string& text, std::string* error) {
  if (auto err = io::write_text(path, text)) {
    *error = *err;
    return false;
  }
  return true;
}

class Campaign {
public:
  Campaign(driver::Driver& driver, const Settings& settings)
      : driver_(driver), settings_(settings) {}

  // Compares one case; on a mismatch shrinks it and writes its outputs. Returns false when
  // the campaign must stop (s.error set).
  bool run_case(std::uint64_t index, const std::string& family, const Scene& scene, Summary& s) {
    std::string error;
    auto c = draw_and_compare(driver_, scene, settings_.profile, settings_.mode, &error);
    if (!c) {
      s.error = "case " + std::to_string(index) + ": " + error;
      return false;
    }
    ++s.cases;
    ++s.families[family].cases;
    for (const FillConvention f : c->conventions)
      ++tally_[f];
    if (c->line_allowance)
      ++s.line_allowance;
    if (c->tie_rounding)
      ++s.tie_rounding;
    // rule: FUZZ.VALUES.REPORT
    if (c->values) {
      ++s.value_cases;
      s.value_attributes += c->values->attributes;
      s.value_depths += c->values->depths;
      const auto keep = [&](const std::optional<ValueDiff>& d, std::optional<ValueDiff>& worst,
                            std::uint64_t& at) {
        if (d && (!worst || d->distance > worst->distance)) {
          worst = d;
          at = index;
        }
      };
      keep(c->values->worst_attribute, s.worst_attribute, s.worst_attribute_case);
      keep(c->values->worst_depth, s.worst_depth, s.worst_depth_case);
    }
    if (c->match)
      return true;
    ++s.mismatches;
    ++s.families[family].mismatches;
    Finding f;
    f.case_index = index;
    f.family = family;
    f.original = scene;
    f.shrunk = shrink(scene, [&](const Scene& t) {
      std::string ignored;
      auto r = draw_and_compare(driver_, t, settings_.profile, settings_.mode, &ignored);
      return r.has_value() && !r->match;
    });
    auto shrunk = draw_and_compare(driver_, f.shrunk, settings_.profile, settings_.mode, &error);
    f.comparison = shrunk ? std::move(*shrunk) : std::move(*c);
    if (!shrunk)
      f.shrunk = scene;
    f.key = io::write_scene(f.shrunk);
    f.group = classify(f.shrunk, f.comparison);
    if (const auto it = first_.find(f.key); it != first_.end()) {
      f.duplicate_of = it->second;
    } else {
      first_.emplace(f.key, index);
      ++s.unique;
      if (!settings_.out_dir.empty() && !write_outputs(f, s))
        return false;
    }
    s.findings.push_back(std::move(f));
    return true;
  }

  bool write_outputs(Finding& f, Summary& s) {
    namespace fs = std::filesystem;
    char stem[32];
    std::snprintf(stem, sizeof stem, "case-%06llu", static_cast<unsigned long long>(f.case_index));
    const fs::path dir(settings_.out_dir);
    f.files.scene = (dir / (std::string(stem) + ".scene.json")).string();
    f.files.shrunk = (dir / (std::string(stem) + ".min.json")).string();
    f.files.picture = (dir / (std::string(stem) + ".png")).string();
    f.files.report = (dir / (std::string(stem) + ".json")).string();
    std::string error;
    if (!write_text(f.files.scene, io::write_scene(f.original), &error) ||
        !write_text(f.files.shrunk, f.key, &error) ||
        !write_text(f.files.report,
                    finding_json(f, settings_, settings_.driver_name).dump(2) + "\n", &error)) {
      s.error = error;
      return false;
    }
    if (auto e = write_difference_png(f.files.picture, f.shrunk, f.comparison)) {
      s.error = f.files.picture + ": " + *e;
      return false;
    }
    return true;
  }

  bool finish(Summary& s) {
    for (const auto& [f, n] : tally_)
      s.legal_conventions.emplace_back(f, n);
    s.groups = group_findings(s.findings);
    if (settings_.out_dir.empty())
      return true;
    if (auto e = write_report(settings_, driver_.info().description, s)) {
      s.error = *e;
      return false;
    }
    // rule: FUZZ.REPORT.HTML
    if (auto err = write_html_report(settings_, driver_.info().description, s)) {
      s.error = *err;
      return false;
    }
    return true;
  }

private:
  driver::Driver& driver_;
  const Settings& settings_;
  std::map<std::string, std::uint64_t> first_;
  std::map<FillConvention, std::uint64_t> tally_;
};

bool make_out_dir(const Settings& settings, Summary& s) {
  if (settings.out_dir.empty())
    return true;
  std::error_code ec;
  std::filesystem::create_directories(settings.out_dir, ec);
  if (ec) {
    s.error = settings.out_dir + ": cannot create: " + ec.message();
    return false;
  }
  return true;
}

void progress(const Settings& settings, std::uint64_t done, std::uint64_t total, const Summary& s) {
  if (!settings.progress)
    return;
  constexpr int kWidth = 30;
  const auto filled = static_cast<int>(total == 0 ? kWidth : done * kWidth / total);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r[%s] %llu/%llu cases, %llu mismatches", bar.c_str(),
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
               static_cast<unsigned long long>(s.mismatches));
  if (done == total)
    std::fputc('\n', stderr);
  std::fflush(stderr);
}

} // namespace

// rule: FUZZ.REPORT, FUZZ.GROUP, FUZZ.SHARD
std::optional<std::string> write_report(const Settings& settings, const std::string& description,
                                        Summary& s) {
  json j = detail::campaign_json(settings, description);
  j.update({{"origin", origin_note(settings.profile)},
            {"cases", s.cases},
            {"skipped", s.skipped},
            {"skipped_cases", s.skipped_cases},
            {"mismatches", s.mismatches},
            {"unique", s.unique},
            {"line_allowance", s.line_allowance},
            {"tie_rounding", s.tie_rounding},
            {"families", families_json(s)},
            {"families_not_generated", not_generated_json(s)},
            {"seconds", s.seconds}});
  if (!s.error.empty())
    j["error"] = s.error;
  if (s.interrupted)
    j["interrupted"] = true;
  if (settings.mode == Mode::kLegal) {
    json t = json::object();
    for (const auto& [f, n] : s.legal_conventions)
      t[std::string(to_string(f))] = n;
    j["fill_conventions_matched"] = t;
  }
  if (settings.values)
    j["values_campaign"] = true;
  // rule: FUZZ.VALUES.REPORT
  if (s.value_cases != 0) {
    json v = {
        {"cases", s.value_cases}, {"attributes", s.value_attributes}, {"depths", s.value_depths}};
    v["worst_attribute"] = s.worst_attribute ? value_json(*s.worst_attribute) : json(nullptr);
    if (s.worst_attribute)
      v["worst_attribute"]["case"] = s.worst_attribute_case;
    v["worst_depth"] = s.worst_depth ? value_json(*s.worst_depth) : json(nullptr);
    if (s.worst_depth)
      v["worst_depth"]["case"] = s.worst_depth_case;
    j["values"] = v;
  }
  json groups = json::array();
  for (const Group& g : s.groups) {
    groups.push_back({{"rule", g.key.rule},
                      {"class", g.key.klass},
                      {"count", g.count},
                      {"scenes", g.scenes},
                      {"example_case", g.example_case},
                      {"example", g.example}});
  }
  j["groups"] = groups;
  json list = json::array();
  for (const Finding& f : s.findings)
    list.push_back(finding_json(f, settings, settings.driver_name));
  j["findings"] = list;
  s.report_path = (std::filesystem::path(settings.out_dir) / "report.json").string();
  std::string error;
  if (!write_text(s.report_path, j.dump(2) + "\n", &error))
    return error;
  return std::nullopt;
}

Summary run_fuzz(driver::Driver& driver, const Settings& settings) {
  Summary s;
  const auto start = std::chrono::steady_clock::now();
  s.families_not_generated =
      settings.values ? value_families_not_generated(settings.profile, driver, settings.families)
                      : families_not_generated(settings.profile, driver, settings.families);
  if (!make_out_dir(settings, s))
    return s;
  Campaign campaign(driver, settings);
  const std::uint64_t total =
      settings.cases > settings.shard_index
          ? (settings.cases - settings.shard_index + settings.shard_count - 1) /
                settings.shard_count
          : 0;
  std::uint64_t done = 0;
  // rule: FUZZ.SHARD
  // A shard runs every shard_count-th case from shard_index: the unsharded campaign's cases.
  for (std::uint64_t i = settings.shard_index; i < settings.cases; i += settings.shard_count) {
    // rule: FUZZ.REPORT
    // An interrupt stops the campaign between cases; the report holds what it has.
    if (io::interrupted()) {
      s.interrupted = true;
      break;
    }
    // rule: FUZZ.VALUES.GENERATE
    auto c =
        settings.values
            ? generate_value_case(settings.seed, i, settings.profile, driver, settings.families)
            : generate_case(settings.seed, i, settings.profile, driver, settings.families);
    if (!c) {
      ++s.skipped;
      s.skipped_cases.push_back(i);
    } else if (!campaign.run_case(i, c->family, c->scene, s)) {
      s.interrupted = io::interrupted(); // the driver was killed by the interrupt
      break;
    }
    progress(settings, ++done, total, s);
  }
  if (settings.progress && !s.error.empty())
    std::fputc('\n', stderr); // end the bar's line
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  campaign.finish(s);
  return s;
}

Summary run_check(driver::Driver& driver, const Scene& scene, const Settings& settings) {
  Summary s;
  const auto start = std::chrono::steady_clock::now();
  if (!make_out_dir(settings, s))
    return s;
  Campaign campaign(driver, settings);
  campaign.run_case(0, "check", scene, s);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  campaign.finish(s);
  return s;
}

void print_summary(std::FILE* out, const Settings& settings, const driver::Driver& driver,
                   const Summary& s) {
  print_summary(out, settings, driver.info().description, s, driver.info().capabilities);
}

// rule: FUZZ.REPORT, FUZZ.GROUP, FUZZ.BASELINE
void print_summary(std::FILE* out, const Settings& settings, const std::string& description,
                   const Summary& s, const std::string& capabilities) {
  std::fprintf(out, "driver      %s (%s)\n", settings.driver_name.c_str(), description.c_str());
  if (!capabilities.empty()) // rule: DRIVER.EXTERNAL.CAPABILITIES
    std::fprintf(out, "capabilities %s\n", capabilities.c_str());
  std::fprintf(out, "profile     %s, mode %s, seed %llu\n",
               std::string(to_string(settings.profile)).c_str(),
               std::string(to_string(settings.mode)).c_str(),
               static_cast<unsigned long long>(settings.seed));
  if (settings.shard_count > 1) {
    std::fprintf(out, "shard       %llu/%llu (cases i < %llu with i mod %llu = %llu)\n",
                 static_cast<unsigned long long>(settings.shard_index),
                 static_cast<unsigned long long>(settings.shard_count),
                 static_cast<unsigned long long>(settings.cases),
                 static_cast<unsigned long long>(settings.shard_count),
                 static_cast<unsigned long long>(settings.shard_index));
  }
  std::fprintf(out, "+------------+------------+---------+-----------+----------+\n");
  std::fprintf(out, "| cases      | mismatches | unique  | time (s)  | cases/s  |\n");
  std::fprintf(out, "+------------+------------+---------+-----------+----------+\n");
  const double rate = s.seconds > 0 ? static_cast<double>(s.cases) / s.seconds : 0.0;
  std::fprintf(out, "| %-10llu | %-10llu | %-7llu | %-9.2f | %-8.1f |\n",
               static_cast<unsigned long long>(s.cases),
               static_cast<unsigned long long>(s.mismatches),
               static_cast<unsigned long long>(s.unique), s.seconds, rate);
  std::fprintf(out, "+------------+------------+---------+-----------+----------+\n");
  if (s.skipped != 0)
    std::fprintf(out, "skipped     %llu cases the driver cannot draw\n",
                 static_cast<unsigned long long>(s.skipped));
  if (settings.mode == Mode::kLegal && settings.profile != Profile::kD3D11) {
    std::string all;
    for (const auto& [f, n] : s.legal_conventions) {
      all += (all.empty() ? "" : ", ") + std::string(to_string(f)) + " " + std::to_string(n);
    }
    std::fprintf(out, "fill conventions that explain the driver's results (cases): %s\n",
                 all.empty() ? "none" : all.c_str());
    if (s.line_allowance != 0)
      std::fprintf(out, "lines       %llu case(s) within the Bresenham allowance\n",
                   static_cast<unsigned long long>(s.line_allowance));
    if (s.tie_rounding != 0)
      std::fprintf(out, "ties        %llu case(s) with a snapping tie rounded the other way\n",
                   static_cast<unsigned long long>(s.tie_rounding));
  }
  // rule: FUZZ.VALUES.REPORT
  if (s.value_cases != 0) {
    const auto worst = [](const std::optional<ValueDiff>& d, std::uint64_t at, const char* unit) {
      if (!d)
        return std::string("none");
      char buf[160];
      std::snprintf(buf, sizeof buf, "%.17g %s (case %llu, %s, pixel %d,%d)", d->distance, unit,
                    static_cast<unsigned long long>(at), d->what.c_str(), d->x, d->y);
      return std::string(buf);
    };
    std::fprintf(out, "values      %llu attribute(s) and %llu depth(s) compared in %llu case(s)\n",
                 static_cast<unsigned long long>(s.value_attributes),
                 static_cast<unsigned long long>(s.value_depths),
                 static_cast<unsigned long long>(s.value_cases));
    std::fprintf(out, "worst attr  %s\n",
                 worst(s.worst_attribute, s.worst_attribute_case, "ulps").c_str());
    std::fprintf(out, "worst depth %s\n",
                 worst(s.worst_depth, s.worst_depth_case, "units (ulps for d32f)").c_str());
  }
  for (const Group& g : s.groups) {
    std::string known;
    if (g.known)
      known = g.known_as.empty() ? ", known" : ", known: " + g.known_as;
    std::fprintf(out, "finding     %s, %s: %llu case(s), %llu scene(s), e.g. case %llu%s%s%s\n",
                 g.key.rule.c_str(), g.key.klass.c_str(), static_cast<unsigned long long>(g.count),
                 static_cast<unsigned long long>(g.scenes),
                 static_cast<unsigned long long>(g.example_case),
                 g.picture.empty() ? "" : ", picture ", g.picture.c_str(), known.c_str());
  }
  if (!s.report_path.empty())
    std::fprintf(out, "report      %s\n", s.report_path.c_str());
}

} // namespace rastrules::fuzzer
