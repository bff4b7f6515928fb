// SPDX-License-Identifier: MIT
// The showcase's index.html.
// Implements: FUZZ.REPORT.HTML

#include "showcase_html.hpp"

#include "rastrules/io/html.hpp"
#include "rastrules/io/output_file.hpp"
#include "rastrules/io/picture.hpp"

namespace rastrules::cli {

// rule: FUZZ.REPORT.HTML
std::optional<std::string> write_showcase_index(const std::filesystem::path& dir,
                                                const std::vector<ShowcaseEntry>& entries) {
  using io::html_escape;
  std::size_t agree = 0;
  for (const ShowcaseEntry& e : entries)
    agree += e.agree ? 1 : 0;
  std::string h = io::html_begin("rastrules showcase");
  h += "<p>" + std::to_string(entries.size()) +
       " built-in scenes, each rendered by the kernel "
       "and compared with the exact oracle: " +
       std::to_string(agree) + " agree, " + std::to_string(entries.size() - agree) +
       " differ.</p>\n";
  h += "<table>\n<tr><th>scene</th><th>target</th><th>primitives</th><th>fragments</th>"
       "<th>oracle</th></tr>\n";
  for (const ShowcaseEntry& e : entries) {
    h += "<tr><td><a href=\"#" + html_escape(e.name) + "\">" + html_escape(e.name) +
         "</a></td><td>" + std::to_string(e.width) + "x" + std::to_string(e.height) +
         "</td><td class=\"n\">" + std::to_string(e.primitives) + "</td><td class=\"n\">" +
         std::to_string(e.fragments) + "</td>" +
         (e.agree ? "<td>agrees</td>" : "<td class=\"bad\">differs</td>") + "</tr>\n";
  }
  h += "</table>\n<h2>Legend</h2>\n<ul class=\"legend\">\n";
  for (const io::LegendEntry& l : io::picture_legend(true, true))
    h += "<li>" + io::html_swatch(l.colour, (l.dot ? "dot: " : "") + l.text) + "</li>\n";
  h += "</ul>\n<p>Sample points are drawn for multisampled scenes; elsewhere a small cross marks "
       "each pixel centre.</p>\n";
  for (const ShowcaseEntry& e : entries) {
    const std::string n = html_escape(e.name);
    const std::string s = std::to_string(e.scale);
    h += "<section id=\"" + n + "\">\n<h3>" + n + "</h3>\n<figure><img src=\"" + n +
         ".png\" alt=\"" + n + ": the kernel's coverage\">\n<figcaption><b>" + n +
         "</b>: " + html_escape(e.description) + ". Target " + std::to_string(e.width) + "x" +
         std::to_string(e.height) + " pixels, " + std::to_string(e.primitives) + " primitive(s), " +
         std::to_string(e.fragments) + " fragment(s); magnified " + s +
         " times: pixel (x, y) is the square whose top-left corner is image pixel (" + s + "x, " +
         s + "y), x to the right, y down, pixel (0, 0) at the top left and (" +
         std::to_string(e.width - 1) + ", " + std::to_string(e.height - 1) +
         ") at the bottom right" + (e.samples ? "; sample points shown" : "") +
         ". The exact oracle " + (e.agree ? "agrees" : "<span class=\"bad\">differs</span>") +
         " (checked by " + html_escape(e.checked_by) + ").</figcaption>\n</figure>\n";
    if (e.resolve)
      h += "<figure><img src=\"" + n + ".resolve.png\" alt=\"" + n +
           ": the resolved target\">\n<figcaption>The resolved target (MSAA.RESOLVE.AVERAGE), one "
           "image pixel per target pixel.</figcaption>\n</figure>\n";
    h += "<p>Files: <a href=\"" + n + ".scene.json\">scene</a> (<code>rastrules render " + n +
         ".scene.json --png OUT.png</code>), <a href=\"" + n +
         ".fragments.json\">fragments</a></p>\n</section>\n";
  }
  h += io::html_end();
  return io::write_text(dir / "index.html", h);
}

} // namespace rastrules::cli
