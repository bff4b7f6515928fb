// SPDX-License-Identifier: MIT
// Properties of io::html_escape, through which every string from input reaches the HTML pages:
// on any bytes the result holds no markup character and no bare '&', and on text of valid
// UTF-8 without control characters undoing the five references gives the input back.
// Implements (properties for): FUZZ.REPORT.HTML

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/io/html.hpp"

namespace {

namespace io = rastrules::io;

// Replaces the five character references html_escape writes by their characters.
std::string unescape(std::string_view s) {
  static constexpr std::array<std::pair<std::string_view, char>, 5> kRefs = {
      {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&#39;", '\''}}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool matched = false;
    for (const auto& [ref, c] : kRefs) {
      if (s.substr(i, ref.size()) == ref) {
        out += c;
        i += ref.size();
        matched = true;
        break;
      }
    }
    if (!matched)
      out += s[i++];
  }
  return out;
}

// Text pieces: ASCII letters and markup characters, tab and newline, and one-, two-, three-
// and four-byte UTF-8 characters.
rc::Gen<std::string> text() {
  const std::vector<std::string> pieces = {"a",
                                           "Z",
                                           "0",
                                           " ",
                                           "<",
                                           ">",
                                           "&",
                                           "\"",
                                           "'",
                                           "\t",
                                           "\n",
                                           "&amp;",
                                           "\xC3\xA9",
                                           "\xE2\x86\x92",
                                           "\xF0\x9F\x98\x80",
                                           "<script>"};
  return rc::gen::map(rc::gen::container<std::vector<std::string>>(rc::gen::elementOf(pieces)),
                      [](const std::vector<std::string>& v) {
                        std::string s;
                        for (const std::string& p : v)
                          s += p;
                        return s;
                      });
}

// rule: FUZZ.REPORT.HTML
RC_GTEST_PROP(HtmlEscape, NoMarkupCharacterAndNoBareAmpersandOnAnyBytes, (const std::string& s)) {
  const std::string e = io::html_escape(s);
  for (const char c : std::string_view("<>\"'"))
    RC_ASSERT(e.find(c) == std::string::npos);
  for (std::size_t i = e.find('&'); i != std::string::npos; i = e.find('&', i + 1)) {
    const std::string_view rest = std::string_view(e).substr(i);
    RC_ASSERT(rest.starts_with("&amp;") || rest.starts_with("&lt;") || rest.starts_with("&gt;") ||
              rest.starts_with("&quot;") || rest.starts_with("&#39;"));
  }
  for (const char c : e) {
    const auto u = static_cast<unsigned char>(c);
    RC_ASSERT((u >= 0x20 && u != 0x7F) || c == '\t' || c == '\n');
  }
}

// rule: FUZZ.REPORT.HTML
RC_GTEST_PROP(HtmlEscape, UnescapingGivesValidTextBack, ()) {
  const std::string s = *text();
  RC_ASSERT(unescape(io::html_escape(s)) == s);
}

} // namespace
