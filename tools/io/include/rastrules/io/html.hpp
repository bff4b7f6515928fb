// SPDX-License-Identifier: MIT
// The pieces of the HTML pages the command line writes (the fuzz and check campaign's
// index.html, the showcase's index.html): escaping, one page frame with its style sheet and a
// self-check script, colour swatches. Pages are self-contained: no external script, style
// sheet, font or network access; pictures are linked by relative paths.
// Implements: FUZZ.REPORT.HTML

#pragma once

#include <string>
#include <string_view>

#include "rastrules/io/image.hpp"

namespace rastrules::io {

// Returns s with &, <, >, " and ' replaced by character references, and bytes that are not
// valid UTF-8 or are control characters other than tab and newline replaced by U+FFFD: safe
// inside element content and quoted attribute values.
// rule: FUZZ.REPORT.HTML
[[nodiscard]] std::string html_escape(std::string_view s);

// Returns the start of a page up to and including <body> and an <h1> with the title (escaped).
[[nodiscard]] std::string html_begin(std::string_view title);

// Returns the end of a page: the self-check script, then </body></html>. The script runs on
// load and writes into <body> data-images (the number of <img>), data-images-broken (those
// that did not load: complete with naturalWidth 0, or not complete) and marks each broken one
// data-broken="1"; any script error sets data-script-error. A test loads the page in a
// headless browser and reads the attributes from the DOM it dumps.
[[nodiscard]] std::string html_end();

// Returns an inline colour swatch (a small square of colour c) followed by the escaped text.
[[nodiscard]] std::string html_swatch(Rgb c, std::string_view text);

} // namespace rastrules::io
