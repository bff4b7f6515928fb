// SPDX-License-Identifier: MIT
// The campaign's index.html (FUZZ.REPORT.HTML): strings from input are escaped, pictures and
// files are linked by relative paths, and each finding is classified by the rule that decided
// the reference's answer at its first differing pixel.

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rastrules/fuzzer/html_report.hpp"
#include "rastrules/io/html.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer {
namespace {

// rule: FUZZ.REPORT.HTML
TEST(HtmlReport, EscapesMarkupQuotesControlsAndInvalidUtf8) {
  EXPECT_EQ(io::html_escape("<a href=\"x\">'&'</a>"),
            "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(io::html_escape("tab\tline\n"), "tab\tline\n");
  EXPECT_EQ(io::html_escape(std::string("a\0b\x1b", 4)), "a\xEF\xBF\xBD"
                                                         "b\xEF\xBF\xBD");
  EXPECT_EQ(io::html_escape("caf\xC3\xA9"), "caf\xC3\xA9");           // valid UTF-8 kept
  EXPECT_EQ(io::html_escape("\xC3"), "\xEF\xBF\xBD");                 // truncated sequence
  EXPECT_EQ(io::html_escape("\xC0\xAF"), "\xEF\xBF\xBD\xEF\xBF\xBD"); // overlong '/'
  EXPECT_EQ(io::html_escape("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD"); // surrogate
}

Finding tie_finding() {
  // One triangle whose left edge passes through the centre of pixel (0, 0): the top-left rule
  // covers it; a driver that misses it has a "missing" finding decided by TRI.FILL.TOP_LEFT.
  Finding f;
  f.case_index = 3;
  f.family = "<family>";
  Scene s;
  s.width = s.height = 1;
  s.primitives.push_back(
      make_triangle({FloatPoint{0.5f, -1}, FloatPoint{1.5f, 1}, FloatPoint{0.5f, 1}}));
  f.original = f.shrunk = s;
  f.key = io::write_scene(s);
  f.comparison.expected = {Fragment{0, 0, 0}};
  f.comparison.missing = {DiffEntry{0, 0, 0, 1}};
  f.group = classify(f.shrunk, f.comparison);
  return f;
}

// rule: FUZZ.REPORT.HTML
TEST(HtmlReport, ClassifiesByTheDecidingRuleAndClass) {
  // The page shows the finding's FUZZ.GROUP key.
  const GroupKey k = tie_finding().group;
  EXPECT_EQ(k.klass, "triangle missing");
  EXPECT_EQ(k.rule, "TRI.FILL.TOP_LEFT");
}

// rule: FUZZ.REPORT.HTML
TEST(HtmlReport, EscapesEveryInputStringAndLinksRelatively) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rastrules-html-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Settings st;
  st.driver_name = "external:<script>alert(1)</script>";
  st.out_dir = dir.string();
  Summary s;
  s.cases = 1;
  s.mismatches = 1;
  s.unique = 1;
  s.error = "driver said \"<b>no</b>\"";
  Finding f = tie_finding();
  f.files.picture = (dir / "case-000003.png").string();
  f.files.shrunk = (dir / "case-000003.min.json").string();
  f.files.scene = (dir / "case-000003.scene.json").string();
  f.files.report = (dir / "case-000003.json").string();
  s.findings.push_back(f);
  ASSERT_EQ(write_html_report(st, "a <driver> & 'co'", s), std::nullopt);
  std::ifstream in(dir / "index.html");
  std::stringstream text;
  text << in.rdbuf();
  const std::string h = text.str();
  std::filesystem::remove_all(dir);
  EXPECT_EQ(h.find("<script>alert"), std::string::npos);
  EXPECT_NE(h.find("external:&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(h.find("a &lt;driver&gt; &amp; &#39;co&#39;"), std::string::npos);
  EXPECT_NE(h.find("driver said &quot;&lt;b&gt;no&lt;/b&gt;&quot;"), std::string::npos);
  EXPECT_NE(h.find("(&lt;family&gt;)"), std::string::npos);
  EXPECT_NE(h.find("<img src=\"case-000003.png\""), std::string::npos); // relative
  EXPECT_EQ(h.find(dir.string()), std::string::npos);                   // no absolute path
  EXPECT_NE(h.find("TRI.FILL.TOP_LEFT"), std::string::npos);
  EXPECT_NE(h.find("&quot;version&quot;: 1"), std::string::npos); // the minimal scene, inline
  EXPECT_NE(h.find("decided by:"), std::string::npos);            // its explanation
  // Exactly one script, inline, and nothing fetched from elsewhere.
  EXPECT_EQ(h.find("<script"), h.rfind("<script"));
  EXPECT_EQ(h.find("<script src"), std::string::npos);
  EXPECT_EQ(h.find("http:"), std::string::npos);
  EXPECT_EQ(h.find("https:"), std::string::npos);
}

} // namespace
} // namespace rastrules::fuzzer
