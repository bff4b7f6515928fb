// SPDX-License-Identifier: MIT
// HTML escaping, the page frame and swatches (rastrules/io/html.hpp).
// Implements: FUZZ.REPORT.HTML

#include "rastrules/io/html.hpp"

#include <cstdint>
#include <cstdio>

namespace rastrules::io {
namespace {

// The length of the valid UTF-8 sequence starting at s[i], or 0 when it is not one
// (overlong forms, surrogates and code points above U+10FFFF are not valid).
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<std::uint8_t>(s[i + k]); };
  const std::uint8_t c = b(0);
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (c < 0x80)
    return 1;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
    cp = c & 0x1Fu;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    cp = c & 0x0Fu;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    cp = c & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size())
    return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xC0u) != 0x80u)
      return 0;
    cp = (cp << 6) | (b(k) & 0x3Fu);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  if (overlong || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF)
    return 0;
  return n;
}

} // namespace

// rule: FUZZ.REPORT.HTML
std::string html_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    const auto u = static_cast<std::uint8_t>(c);
    if (u >= 0x80) {
      const std::size_t n = utf8_length(s, i);
      if (n == 0) {
        out += "\xEF\xBF\xBD";
        ++i;
      } else {
        out.append(s.substr(i, n));
        i += n;
      }
      continue;
    }
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&#39;";
      break;
    default:
      if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7F)
        out += "\xEF\xBF\xBD";
      else
        out += c;
    }
    ++i;
  }
  return out;
}

std::string html_begin(std::string_view title) {
  std::string t = html_escape(title);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + t +
         "</title>\n<style>\n"
         "body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 1400px; }\n"
         "table { border-collapse: collapse; margin: 0.5em 0 1em; }\n"
         "th, td { border: 1px solid #bbb; padding: 0.2em 0.6em; text-align: left; "
         "vertical-align: top; }\n"
         "th { background: #eee; }\n"
         "td.n { text-align: right; font-variant-numeric: tabular-nums; }\n"
         "figure { margin: 0.5em 0; }\n"
         "figure img { border: 1px solid #ccc; max-width: 100%; height: auto; "
         "image-rendering: pixelated; }\n"
         "figcaption { font-size: 0.9em; color: #444; max-width: 60em; }\n"
         "pre { background: #f6f6f6; border: 1px solid #ddd; padding: 0.5em; overflow-x: auto; "
         "font-size: 0.85em; max-height: 40em; }\n"
         "section { border-top: 1px solid #ccc; margin-top: 1.5em; }\n"
         ".swatch { display: inline-block; width: 0.9em; height: 0.9em; border: 1px solid #888; "
         "vertical-align: middle; margin-right: 0.4em; }\n"
         "ul.legend { list-style: none; padding-left: 0; }\n"
         ".bad { color: #b00; font-weight: bold; }\n"
         "</style>\n</head>\n<body>\n<h1>" +
         t + "</h1>\n";
}

std::string html_end() {
  return "<script>\n"
         "// Self-check (FUZZ.REPORT.HTML): marks images that did not load and script errors.\n"
         "window.addEventListener('error', function (e) {\n"
         "  if (e instanceof ErrorEvent)\n"
         "    document.body.setAttribute('data-script-error', String(e.message));\n"
         "});\n"
         "window.addEventListener('load', function () {\n"
         "  var broken = 0;\n"
         "  for (var i = 0; i < document.images.length; ++i) {\n"
         "    var img = document.images[i];\n"
         "    if (!img.complete || img.naturalWidth === 0) {\n"
         "      img.setAttribute('data-broken', '1');\n"
         "      ++broken;\n"
         "    }\n"
         "  }\n"
         "  document.body.setAttribute('data-images', String(document.images.length));\n"
         "  document.body.setAttribute('data-images-broken', String(broken));\n"
         "});\n"
         "</script>\n</body>\n</html>\n";
}

std::string html_swatch(Rgb c, std::string_view text) {
  char colour[8];
  std::snprintf(colour, sizeof colour, "#%02x%02x%02x", c.r, c.g, c.b);
  return std::string("<span class=\"swatch\" style=\"background:") + colour + "\"></span>" +
         html_escape(text);
}

} // namespace rastrules::io
