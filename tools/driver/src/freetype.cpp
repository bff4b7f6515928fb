// SPDX-License-Identifier: MIT
// FreeType's two rasterizers as a 2D library driver: the monochrome one ("smooth" off,
// FT_PIXEL_MODE_MONO, with its dropout control) for aliased paths and the gray one (256 levels)
// for antialiased paths, both through FT_Outline_Get_Bitmap on the path's own outline in 26.6
// (io::freetype_outline_of: lines, conic arcs, cubics; FT_OUTLINE_EVEN_ODD_FILL for even-odd).
// Implements: DRIVER.PATH.FREETYPE

#include <variant>

#include "drivers.hpp"
#include "path_library.hpp"
#include "rastrules/io/glyph.hpp"

namespace rastrules::driver {
namespace {

class FreeTypeDriver final : public detail::PathLibraryDriver {
public:
  explicit FreeTypeDriver(DriverInfo info) : PathLibraryDriver(std::move(info)) {}

protected:
  // rule: DRIVER.PATH.FREETYPE
  std::optional<std::string> raster(const detail::PathJob& job,
                                    std::vector<std::uint8_t>& alpha) override {
    io::Glyph g;
    g.path = *job.path;
    g.width = job.width;
    g.height = job.height;
    auto outline = io::freetype_outline_of(g);
    if (const auto* e = std::get_if<io::GlyphError>(&outline))
      return e->what();
    const auto& ft = std::get<io::FreeTypeGlyph>(outline);
    if (job.antialiased)
      ft.render_gray(bitmap_);
    else
      ft.render_mono(bitmap_);
    alpha = bitmap_.pixels;
    return std::nullopt;
  }

private:
  io::GlyphBitmap bitmap_;
};

} // namespace

namespace detail {

// rule: DRIVER.PATH.FREETYPE
std::unique_ptr<Driver> open_freetype(std::string_view arg, std::string* error) {
  if (!arg.empty()) {
    *error = "driver 'freetype' takes no argument";
    return nullptr;
  }
  PathSupport ps;
  ps.samples = ps.area = ps.nonzero = ps.evenodd = ps.quadratics = ps.cubics = true;
  ps.grid_raw = 4;
  ps.grid = "26.6";
  ps.aliased_method = "monochrome raster: pixel centres inside, with dropout control";
  ps.antialiased_method = "gray raster: signed-area cells accumulated per scanline";
  return std::make_unique<FreeTypeDriver>(
      path_library_info("freetype",
                        "FreeType " + io::FreeTypeGlyph::freetype_version() +
                            " (FT_Outline_Get_Bitmap: monochrome for samples, gray for area)",
                        ps, 16384));
}

} // namespace detail
} // namespace rastrules::driver
