// SPDX-License-Identifier: MIT
// The campaign's index.html: the summary, findings by rule and class, and per finding its
// picture, minimal scene and the explanation of its differing pixels.
// Implements: FUZZ.REPORT.HTML

#include "rastrules/fuzzer/html_report.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <utility>
#include <variant>

#include "legend.hpp"
#include "rastrules/io/explain.hpp"
#include "rastrules/io/html.hpp"
#include "rastrules/io/output_file.hpp"

namespace rastrules::fuzzer {
namespace {

using io::html_escape;

// The differing pixels of a comparison, sorted by (y, x), each with whether the driver
// misses samples there and whether it adds some.
std::vector<std::pair<std::pair<std::int32_t, std::int32_t>, std::pair<bool, bool>>>
differing_pixels(const Comparison& c) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::pair<bool, bool>> m;
  for (const DiffEntry& d : c.missing)
    m[{d.y, d.x}].first = true;
  for (const DiffEntry& d : c.extra)
    m[{d.y, d.x}].second = true;
  std::vector<std::pair<std::pair<std::int32_t, std::int32_t>, std::pair<bool, bool>>> out;
  for (const auto& [yx, me] : m)
    out.push_back({{yx.second, yx.first}, me});
  return out;
}

std::string what(std::pair<bool, bool> me) {
  return me.first && me.second ? "missing and extra" : (me.first ? "missing" : "extra");
}

// The explanation of pixel (x, y) of the finding's shrunk scene, or why there is none.
std::string explain(const Scene& scene, const PreparedScene* prepared, std::int32_t x,
                    std::int32_t y) {
  if (prepared == nullptr)
    return "(the reference rejects the scene: no explanation)\n";
  return io::explain_window_pixel(scene, *prepared, x, y, false);
}

std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string cell(const std::string& s) {
  return "<td>" + html_escape(s) + "</td>";
}
std::string num(std::uint64_t n) {
  return "<td class=\"n\">" + std::to_string(n) + "</td>";
}

std::string summary_table(const Settings& st, const std::string& description, const Summary& s) {
  std::string h = "<table class=\"summary\">\n";
  const auto row = [&](const std::string& k, const std::string& v) {
    h += "<tr><th>" + k + "</th>" + v + "</tr>\n";
  };
  row("driver", cell(st.driver_name + (description.empty() ? "" : " (" + description + ")")));
  row("profile", cell(std::string(to_string(st.profile))));
  row("mode", cell(std::string(to_string(st.mode))));
  row("seed", num(st.seed));
  row("cases run", num(s.cases));
  row("skipped (the driver cannot draw them)", num(s.skipped));
  row("mismatches", num(s.mismatches));
  row("unique findings", num(s.unique));
  if (st.mode == Mode::kLegal) {
    std::string all;
    for (const auto& [f, n] : s.legal_conventions)
      all += (all.empty() ? "" : ", ") + std::string(to_string(f)) + " " + std::to_string(n);
    row("fill conventions that explain the driver's results (cases)",
        cell(all.empty() ? "none" : all));
  }
  if (s.interrupted)
    row("stopped", "<td class=\"bad\">interrupted: the report holds the cases run</td>");
  if (!s.error.empty())
    row("error", "<td class=\"bad\">" + html_escape(s.error) + "</td>");
  row("files", "<td><a href=\"report.json\">report.json</a> (machine-readable)</td>");
  return h + "</table>\n";
}

} // namespace

// rule: FUZZ.REPORT.HTML
std::optional<std::string> write_html_report(const Settings& settings,
                                             const std::string& driver_description,
                                             const Summary& summary) {
  if (settings.out_dir.empty())
    return std::nullopt;
  std::string h = io::html_begin(
      "rastrules " +
      std::string(settings.driver_name.empty() ? "campaign" : "fuzz: " + settings.driver_name) +
      " (" + std::string(to_string(settings.profile)) + ", " +
      std::string(to_string(settings.mode)) + ")");
  h += summary_table(settings, driver_description, summary);

  // Unique findings by rule and class; duplicates counted with their first.
  std::map<std::uint64_t, std::uint64_t> duplicates;
  for (const Finding& f : summary.findings)
    if (f.duplicate_of)
      ++duplicates[*f.duplicate_of];
  std::vector<const Finding*> unique;
  for (const Finding& f : summary.findings)
    if (!f.duplicate_of)
      unique.push_back(&f);
  // The groups of FUZZ.GROUP (Finding::group), as the summary and report.json list them.
  std::map<std::pair<std::string, std::string>, std::vector<const Finding*>> groups;
  for (const Finding* f : unique)
    groups[{f->group.rule, f->group.klass}].push_back(f);
  h += "<h2>Findings by rule and class</h2>\n";
  if (unique.empty()) {
    h += "<p>No difference: every case drawn agrees with the reference.</p>\n";
  } else {
    h += "<p>The groups of FUZZ.GROUP: the rule is the one the reference kernel applied at the "
         "finding's first differing pixel; the class names that pixel's primitive type and "
         "whether the driver misses coverage the reference has, adds coverage it does not have, "
         "or both (and the sample count of a multisampled target).</p>\n"
         "<table>\n<tr><th>rule</th><th>class</th><th>unique findings</th>"
         "<th>with duplicates</th><th>cases</th></tr>\n";
    for (const auto& [key, list] : groups) {
      std::uint64_t all = 0;
      std::string links;
      for (const Finding* f : list) {
        all += 1 + duplicates[f->case_index];
        const std::string id = "case-" + std::to_string(f->case_index);
        links += (links.empty() ? "" : ", ") +
                 ("<a href=\"#" + id + "\">" + std::to_string(f->case_index) + "</a>");
      }
      h += "<tr>" + cell(key.first) + cell(key.second) + num(list.size()) + num(all) + "<td>" +
           links + "</td></tr>\n";
    }
    h += "</table>\n";
  }

  if (!unique.empty()) {
    h += "<h2>Findings</h2>\n<p>Legend of the pictures (also drawn below each picture):</p>\n"
         "<ul class=\"legend\">\n";
    for (const LegendLine& l : difference_legend(unique.front()->shrunk))
      h += "<li>" + io::html_swatch(l.colour, (l.dot ? "dot: " : "") + l.text) + "</li>\n";
    h += "</ul>\n";
  }
  for (const Finding* f : unique) {
    const std::string id = "case-" + std::to_string(f->case_index);
    const Comparison& c = f->comparison;
    const auto pixels = differing_pixels(c);
    h += "<section id=\"" + id + "\">\n<h3>case " + std::to_string(f->case_index) + " (" +
         html_escape(f->family) + "): " + html_escape(f->group.rule) + ", " +
         html_escape(f->group.klass) + "</h3>\n";
    h += "<p>" + std::to_string(f->original.primitives.size()) + " primitive(s) shrunk to " +
         std::to_string(f->shrunk.primitives.size()) + " in a " + std::to_string(f->shrunk.width) +
         "x" + std::to_string(f->shrunk.height) + " target; " + std::to_string(c.missing.size()) +
         " missing, " + std::to_string(c.extra.size()) + " extra";
    if (duplicates[f->case_index] != 0)
      h += "; " + std::to_string(duplicates[f->case_index]) +
           " later case(s) shrank to the same "
           "scene";
    h += ".</p>\n";
    if (!f->files.picture.empty()) {
      std::string where;
      for (std::size_t k = 0; k < pixels.size() && k < 8; ++k)
        where += (k == 0 ? "" : ", ") +
                 ("(" + std::to_string(pixels[k].first.first) + ", " +
                  std::to_string(pixels[k].first.second) + ") " + what(pixels[k].second));
      if (pixels.size() > 8)
        where += ", and " + std::to_string(pixels.size() - 8) + " more";
      h += "<figure><img src=\"" + html_escape(file_name(f->files.picture)) + "\" alt=\"" + id +
           ": expected, actual and difference\">\n<figcaption>Left to right: expected (the "
           "reference under the " +
           html_escape(std::string(to_string(c.compared_with))) +
           " fill convention), actual (the driver), difference (blue: the driver misses it, "
           "red: the driver adds it). Pixel coordinates on the axes: x to the right, y down, "
           "pixel (0, 0) at the top left" +
           (settings.profile == Profile::kOpenGL
                ? " (OpenGL's lower-left origin is flipped to this frame by the adapter)"
                : std::string()) +
           ". Differing pixels: " + html_escape(where) + ".</figcaption>\n</figure>\n";
      h += "<p>Files: <a href=\"" + html_escape(file_name(f->files.shrunk)) +
           "\">minimal scene</a> (<code>rastrules check " +
           html_escape(file_name(f->files.shrunk)) + " --driver " +
           html_escape(settings.driver_name) + "</code> reproduces it), <a href=\"" +
           html_escape(file_name(f->files.scene)) + "\">generated scene</a>, <a href=\"" +
           html_escape(file_name(f->files.report)) + "\">finding (JSON)</a></p>\n";
    }
    h += "<details open><summary>minimal scene</summary>\n<pre>" + html_escape(f->key) +
         "</pre>\n</details>\n";
    auto prepared = prepare(f->shrunk);
    const auto* ps = std::get_if<PreparedScene>(&prepared);
    h += "<details open><summary>why: the reference's decision at the differing pixels";
    if (pixels.size() > kExplainedPixels)
      h += " (the first " + std::to_string(kExplainedPixels) + " of " +
           std::to_string(pixels.size()) + ")";
    h += "</summary>\n";
    for (std::size_t k = 0; k < pixels.size() && k < kExplainedPixels; ++k) {
      const auto [xy, me] = pixels[k];
      h += "<p>pixel (" + std::to_string(xy.first) + ", " + std::to_string(xy.second) +
           "): " + what(me) + " in the driver (<code>rastrules explain " +
           html_escape(file_name(f->files.shrunk)) + " --pixel " + std::to_string(xy.first) + "," +
           std::to_string(xy.second) + "</code>)</p>\n<pre>" +
           html_escape(explain(f->shrunk, ps, xy.first, xy.second)) + "</pre>\n";
    }
    h += "</details>\n";
    // rule: FUZZ.VALUES.REPORT
    if (c.values && !c.values->diffs.empty()) {
      const auto num = [](double v) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return std::string(buf);
      };
      h += "<details open><summary>values beyond the allowance (" +
           std::to_string(c.values->beyond) + " of " +
           std::to_string(c.values->attributes + c.values->depths) +
           " compared; distances in float32 steps, or units of the depth format)</summary>\n"
           "<table>\n<tr><th>pixel</th><th>value</th><th>rule</th><th>exactly rounded</th>"
           "<th>reference</th><th>driver</th><th>distance</th><th>allowed</th></tr>\n";
      for (std::size_t k = 0; k < c.values->diffs.size() && k < 8; ++k) {
        const ValueDiff& v = c.values->diffs[k];
        h += "<tr><td>(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ")</td><td>" +
             html_escape(v.what) + "</td><td>" + html_escape(v.rule) + "</td><td>" +
             num(v.expected) + "</td><td>" + num(v.reference) + "</td><td>" + num(v.got) +
             "</td><td>" + num(v.distance) + "</td><td>" + num(v.allowed) + "</td></tr>\n";
      }
      h += "</table>\n</details>\n";
    }
    h += "</section>\n";
  }
  if (!duplicates.empty()) {
    h += "<h2>Duplicates</h2>\n<table>\n<tr><th>case</th><th>same minimal scene as</th></tr>\n";
    for (const Finding& f : summary.findings)
      if (f.duplicate_of)
        h += "<tr>" + num(f.case_index) + "<td><a href=\"#case-" + std::to_string(*f.duplicate_of) +
             "\">case " + std::to_string(*f.duplicate_of) + "</a></td></tr>\n";
    h += "</table>\n";
  }
  h += io::html_end();
  return io::write_text(std::filesystem::path(settings.out_dir) / "index.html", h);
}

} // namespace rastrules::fuzzer
