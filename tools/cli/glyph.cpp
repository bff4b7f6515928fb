// SPDX-License-Identifier: MIT
// rastrules glyph: a glyph of a font file as a path scene (PATH.GLYPH.SOURCE), through
// FreeType's outline (rastrules/io/glyph.hpp), so that real fonts become scenes to render,
// explain and check.
// Implements: PATH.GLYPH.SOURCE, PATH.GLYPH.ERRORS (the command)

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cli.hpp"
#include "parser.hpp"
#include "rastrules/io/glyph.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::cli {
namespace {

// Reads "--char" as one UTF-8 character or "U+XXXX" (1 to 6 hex digits, at most U+10FFFF).
std::optional<char32_t> code_point_of(const std::string& text) {
  if (text.size() > 2 && (text[0] == 'U' || text[0] == 'u') && text[1] == '+') {
    if (text.size() > 8)
      return std::nullopt;
    char32_t v = 0;
    for (std::size_t i = 2; i < text.size(); ++i) {
      const char c = text[i];
      const int d = c >= '0' && c <= '9'   ? c - '0'
                    : c >= 'a' && c <= 'f' ? c - 'a' + 10
                    : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                           : -1;
      if (d < 0)
        return std::nullopt;
      v = v * 16 + static_cast<char32_t>(d);
    }
    return v <= 0x10FFFF ? std::optional<char32_t>(v) : std::nullopt;
  }
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const std::size_t n = text.empty()            ? 0
                        : b(0) < 0x80           ? 1
                        : (b(0) & 0xE0) == 0xC0 ? 2
                        : (b(0) & 0xF0) == 0xE0 ? 3
                        : (b(0) & 0xF8) == 0xF0 ? 4
                                                : 0;
  if (n == 0 || text.size() != n)
    return std::nullopt;
  char32_t v = n == 1 ? b(0) : b(0) & (0x7Fu >> n);
  for (std::size_t i = 1; i < n; ++i) {
    if ((b(i) & 0xC0) != 0x80)
      return std::nullopt;
    v = (v << 6) | (b(i) & 0x3Fu);
  }
  return v;
}

} // namespace

// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.ERRORS, SCENE.PRIM.PATH
int run_glyph(const Args& args) {
  CommandLine cl("glyph",
                 "Write a glyph of a font file as a path scene (SCENE.PRIM.PATH) through "
                 "FreeType's unhinted outline, exactly (PATH.GLYPH.SOURCE), to standard output or "
                 "SCENE.json.");
  std::vector<std::string> fonts;
  std::optional<std::string> ch, size, coverage, out;
  cl.positionals("FONT", fonts, "the font file");
  cl.value("--char", ch, "C", "the character: itself or U+XXXX (required)", "--char needs a value");
  cl.value("--size", size, "N", "the size in pixels (default 64)", "--size needs a value");
  cl.value("--coverage", coverage, "samples|area", "the path's coverage (default samples)",
           "--coverage needs a value");
  cl.value("--out", out, "SCENE.json", "the scene file written (default: standard output)",
           "--out needs a value");
  if (const auto stop = cl.parse(args, "glyph: "))
    return *stop;
  if (fonts.size() > 1)
    return usage_error("glyph: one font file only");
  if (fonts.empty())
    return usage_error("glyph: missing FONT");
  const std::string font = fonts.front();
  if (!ch)
    return usage_error("glyph: missing --char C (a character or U+XXXX)");
  const std::optional<char32_t> code = code_point_of(*ch);
  if (!code)
    return error("--char needs one character or U+XXXX, got " + shown_value(ch));
  const auto px = parse_int(size.value_or("64"), io::kGlyphMinPixelSize, io::kGlyphMaxPixelSize);
  if (!px) {
    return error("--size needs an integer in [" + std::to_string(io::kGlyphMinPixelSize) + ", " +
                 std::to_string(io::kGlyphMaxPixelSize) + "], got " + shown_value(size));
  }
  const auto kind = from_name<path::Coverage>(coverage.value_or("samples"));
  if (!kind)
    return error("--coverage must be samples or area, got " + shown_value(coverage));
  auto loaded = io::load_glyph(font, *code, static_cast<int>(*px));
  if (const auto* e = std::get_if<io::GlyphError>(&loaded))
    return error(e->what());
  const io::Glyph& g = std::get<io::Glyph>(loaded);
  const Scene scene = io::glyph_scene(g, *kind);
  const std::string text = io::write_scene(scene);
  if (!out || *out == "-") {
    std::fputs(text.c_str(), stdout);
    return kExitOk;
  }
  if (const auto e = write_text(*out, text))
    return error(*e);
  return kExitOk;
}

} // namespace rastrules::cli
