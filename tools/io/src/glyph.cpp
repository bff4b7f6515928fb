// SPDX-License-Identifier: MIT
// Glyph outlines through FreeType: loading, the 26.6 -> 16.8 mapping, the placement in a
// target, and FreeType's own rasterizers on the same outline (rastrules/io/glyph.hpp).
// Implements: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS

#include "rastrules/io/glyph.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <utility>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "rastrules/fixed.hpp"

namespace rastrules::io {

namespace {

std::string hex_error(FT_Error e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%02x", static_cast<unsigned>(e));
  return buf;
}

std::string code_point_name(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

// floor(v / 64) and ceil(v / 64) for signed 26.6 values.
std::int64_t floor64(std::int64_t v) {
  return v >= 0 ? v / 64 : -((-v + 63) / 64);
}
std::int64_t ceil64(std::int64_t v) {
  return -floor64(-v);
}

// The decomposition's state: the path being built and the placement.
// rule: PATH.GLYPH.SOURCE
struct Builder {
  path::Path* path = nullptr;
  std::int64_t origin_x = 0; // whole pixels
  std::int64_t origin_y = 0;
  path::Point current;
  bool out_of_range = false;

  // raw 16.8 = 4 * (26.6), y flipped about the baseline at origin_y.
  path::Point map(const FT_Vector* v) {
    const std::int64_t x = 4 * static_cast<std::int64_t>(v->x) + 256 * origin_x;
    const std::int64_t y = 256 * origin_y - 4 * static_cast<std::int64_t>(v->y);
    constexpr std::int64_t kRange = std::int64_t{1} << 23; // SNAP.VERTEX.RANGE
    if (x < -kRange || x > kRange || y < -kRange || y > kRange) {
      out_of_range = true;
      return {};
    }
    return path::Point{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
  }
  path::Contour& contour() { return path->contours.back(); }
};

int on_move(const FT_Vector* to, void* user) {
  auto& b = *static_cast<Builder*>(user);
  b.current = b.map(to);
  b.path->contours.push_back(path::Contour{b.current, {}});
  return 0;
}

int on_line(const FT_Vector* to, void* user) {
  auto& b = *static_cast<Builder*>(user);
  const path::Point p = b.map(to);
  // A zero-length line (FreeType closes a contour whose last point is its first with one)
  // changes nothing (PATH.DEGENERATE): left out.
  if (p == b.current)
    return 0;
  path::Segment s;
  s.kind = path::SegmentKind::kLine;
  s.p[0] = p;
  b.contour().segments.push_back(s);
  b.current = p;
  return 0;
}

int on_conic(const FT_Vector* control, const FT_Vector* to, void* user) {
  auto& b = *static_cast<Builder*>(user);
  path::Segment s;
  s.kind = path::SegmentKind::kQuadratic;
  s.p[0] = b.map(control);
  s.p[1] = b.map(to);
  b.contour().segments.push_back(s);
  b.current = s.p[1];
  return 0;
}

int on_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  auto& b = *static_cast<Builder*>(user);
  path::Segment s;
  s.kind = path::SegmentKind::kCubic;
  s.p[0] = b.map(c1);
  s.p[1] = b.map(c2);
  s.p[2] = b.map(to);
  b.contour().segments.push_back(s);
  b.current = s.p[2];
  return 0;
}

} // namespace

struct FreeTypeGlyph::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  FT_Outline outline{}; // a copy, translated to the target's placement (y up, bitmap rows)
  bool outline_made = false;
  Glyph glyph;
  std::vector<unsigned char> mono; // packed rows, pitch (width + 7) / 8
  std::vector<unsigned char> gray; // one byte a pixel
  ~Impl() {
    if (outline_made)
      FT_Outline_Done(library, &outline);
    if (face != nullptr)
      FT_Done_Face(face);
    if (library != nullptr)
      FT_Done_FreeType(library);
  }
  // Renders the outline into `buffer` (cleared first) as FreeType bitmap of the pixel mode.
  void raster(std::vector<unsigned char>& buffer, unsigned char mode) {
    FT_Bitmap bm{};
    bm.rows = static_cast<unsigned>(glyph.height);
    bm.width = static_cast<unsigned>(glyph.width);
    bm.pitch = mode == FT_PIXEL_MODE_MONO ? (glyph.width + 7) / 8 : glyph.width;
    bm.pixel_mode = mode;
    bm.num_grays = mode == FT_PIXEL_MODE_MONO ? 2 : 256;
    buffer.assign(static_cast<std::size_t>(bm.pitch) * bm.rows, 0);
    bm.buffer = buffer.data();
    if (bm.rows > 0 && bm.width > 0)
      FT_Outline_Get_Bitmap(library, &outline, &bm);
  }
};

FreeTypeGlyph::FreeTypeGlyph(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FreeTypeGlyph::~FreeTypeGlyph() = default;
FreeTypeGlyph::FreeTypeGlyph(FreeTypeGlyph&&) noexcept = default;
FreeTypeGlyph& FreeTypeGlyph::operator=(FreeTypeGlyph&&) noexcept = default;

const Glyph& FreeTypeGlyph::glyph() const {
  return impl_->glyph;
}

int FreeTypeGlyph::outline_points() const {
  return impl_->outline.n_points;
}

std::string FreeTypeGlyph::freetype_version() {
  return std::to_string(FREETYPE_MAJOR) + "." + std::to_string(FREETYPE_MINOR) + "." +
         std::to_string(FREETYPE_PATCH);
}

const std::uint8_t* FreeTypeGlyph::raster_mono() const {
  impl_->raster(impl_->mono, FT_PIXEL_MODE_MONO);
  return impl_->mono.data();
}

const std::uint8_t* FreeTypeGlyph::raster_gray() const {
  impl_->raster(impl_->gray, FT_PIXEL_MODE_GRAY);
  return impl_->gray.data();
}

void FreeTypeGlyph::render_mono(GlyphBitmap& out) const {
  const std::uint8_t* rows = raster_mono();
  const Glyph& g = impl_->glyph;
  const std::size_t pitch = static_cast<std::size_t>((g.width + 7) / 8);
  out.width = g.width;
  out.height = g.height;
  out.pixels.assign(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height), 0);
  for (std::int32_t y = 0; y < g.height; ++y)
    for (std::int32_t x = 0; x < g.width; ++x) {
      const unsigned byte =
          rows[static_cast<std::size_t>(y) * pitch + static_cast<std::size_t>(x / 8)];
      const unsigned shift = 7u - static_cast<unsigned>(x % 8);
      out.pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(g.width) +
                 static_cast<std::size_t>(x)] = static_cast<std::uint8_t>((byte >> shift) & 1u);
    }
}

void FreeTypeGlyph::render_gray(GlyphBitmap& out) const {
  const std::uint8_t* rows = raster_gray();
  const Glyph& g = impl_->glyph;
  out.width = g.width;
  out.height = g.height;
  out.pixels.assign(rows,
                    rows + static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
}

// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS
std::variant<FreeTypeGlyph, GlyphError> load_freetype_glyph(const std::string& font_file,
                                                            char32_t code_point, int pixel_size) {
  if (pixel_size < kGlyphMinPixelSize || pixel_size > kGlyphMaxPixelSize)
    return GlyphError{"pixel size " + std::to_string(pixel_size) + " outside [" +
                      std::to_string(kGlyphMinPixelSize) + ", " +
                      std::to_string(kGlyphMaxPixelSize) + "]"};
  auto impl = std::make_unique<FreeTypeGlyph::Impl>();
  if (const FT_Error e = FT_Init_FreeType(&impl->library); e != 0) {
    impl->library = nullptr;
    return GlyphError{"cannot start FreeType (error " + hex_error(e) + ")"};
  }
  if (const FT_Error e = FT_New_Face(impl->library, font_file.c_str(), 0, &impl->face); e != 0) {
    impl->face = nullptr;
    return GlyphError{"cannot read font file '" + font_file + "' (FreeType error " + hex_error(e) +
                      ")"};
  }
  FT_Face face = impl->face;
  const FT_UInt index =
      code_point > 0x10FFFF ? 0 : FT_Get_Char_Index(face, static_cast<FT_ULong>(code_point));
  if (index == 0)
    return GlyphError{"no glyph for " + code_point_name(code_point) + " in '" + font_file + "'"};
  if (const FT_Error e = FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_size)); e != 0)
    return GlyphError{"cannot set pixel size " + std::to_string(pixel_size) + " for '" + font_file +
                      "' (FreeType error " + hex_error(e) + ")"};
  if (const FT_Error e = FT_Load_Glyph(face, index, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP); e != 0)
    return GlyphError{"cannot load the glyph of " + code_point_name(code_point) + " in '" +
                      font_file + "' (FreeType error " + hex_error(e) + ")"};
  if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
    return GlyphError{"the glyph of " + code_point_name(code_point) + " in '" + font_file +
                      "' is not an outline"};
  const FT_Outline& src = face->glyph->outline;

  // rule: PATH.GLYPH.PLACE
  FT_BBox box{};
  FT_Outline_Get_CBox(&src, &box);
  const std::int64_t x_min = floor64(box.xMin), x_max = ceil64(box.xMax);
  const std::int64_t y_min = floor64(box.yMin), y_max = ceil64(box.yMax);
  const std::int64_t width = x_max - x_min + 2, height = y_max - y_min + 2;
  if (width > kMaxTargetSide || height > kMaxTargetSide)
    return GlyphError{"the glyph of " + code_point_name(code_point) + " at " +
                      std::to_string(pixel_size) + " px needs a target of " +
                      std::to_string(width) + " x " + std::to_string(height) + " px, above " +
                      std::to_string(kMaxTargetSide)};
  Glyph& g = impl->glyph;
  g.width = static_cast<std::int32_t>(width);
  g.height = static_cast<std::int32_t>(height);
  g.origin_x = static_cast<std::int32_t>(1 - x_min);
  g.origin_y = static_cast<std::int32_t>(1 + y_max);
  g.path.fill_rule = (src.flags & FT_OUTLINE_EVEN_ODD_FILL) != 0 ? path::FillRule::kEvenOdd
                                                                 : path::FillRule::kNonZero;

  // rule: PATH.GLYPH.SOURCE
  Builder b{&g.path, g.origin_x, g.origin_y, {}, false};
  const FT_Outline_Funcs funcs{on_move, on_line, on_conic, on_cubic, 0, 0};
  if (src.n_points > 0) {
    if (const FT_Error e = FT_Outline_Decompose(const_cast<FT_Outline*>(&src), &funcs, &b); e != 0)
      return GlyphError{"cannot decompose the outline of " + code_point_name(code_point) + " in '" +
                        font_file + "' (FreeType error " + hex_error(e) + ")"};
  }
  if (b.out_of_range)
    return GlyphError{"the outline of " + code_point_name(code_point) + " in '" + font_file +
                      "' has a coordinate beyond the 16.8 range (|raw| <= 2^23)"};

  // FreeType's copy for its rasterizers: bitmap rows count up from the bottom, so y moves by
  // height - origin_y pixels (then row r from the top is y_down in [r, r + 1]).
  if (FT_Outline_New(impl->library, static_cast<FT_UInt>(src.n_points),
                     static_cast<FT_Int>(src.n_contours), &impl->outline) != 0)
    return GlyphError{"out of memory copying the outline of " + code_point_name(code_point)};
  impl->outline_made = true;
  FT_Outline_Copy(&src, &impl->outline);
  FT_Outline_Translate(&impl->outline, static_cast<FT_Pos>(64 * g.origin_x),
                       static_cast<FT_Pos>(64 * (g.height - g.origin_y)));
  return FreeTypeGlyph(std::move(impl));
}

// rule: PATH.GLYPH.PLACE
std::variant<FreeTypeGlyph, GlyphError> freetype_outline_of(const Glyph& g) {
  // Points and tags, contour ends; 26.6, y up from the target's bottom edge.
  std::vector<FT_Vector> points;
  std::vector<char> tags;
  std::vector<short> ends;
  std::string bad;
  const auto add = [&](path::Point p, char tag) {
    if (p.x % 4 != 0 || p.y % 4 != 0) {
      if (bad.empty())
        bad = "point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
              ") (raw 16.8) is not on the 26.6 grid";
      return;
    }
    points.push_back(FT_Vector{static_cast<FT_Pos>(p.x / 4),
                               static_cast<FT_Pos>((256 * std::int64_t{g.height} - p.y) / 4)});
    tags.push_back(tag);
  };
  for (const path::Contour& c : g.path.contours) {
    add(c.start, FT_CURVE_TAG_ON);
    for (const path::Segment& s : c.segments) {
      if (s.kind == path::SegmentKind::kLine) {
        add(s.p[0], FT_CURVE_TAG_ON);
      } else if (s.kind == path::SegmentKind::kQuadratic) {
        add(s.p[0], FT_CURVE_TAG_CONIC);
        add(s.p[1], FT_CURVE_TAG_ON);
      } else {
        add(s.p[0], FT_CURVE_TAG_CUBIC);
        add(s.p[1], FT_CURVE_TAG_CUBIC);
        add(s.p[2], FT_CURVE_TAG_ON);
      }
    }
    if (points.size() > 32767)
      return GlyphError{"the path has more than 32767 points, FreeType's limit"};
    ends.push_back(static_cast<short>(points.size() - 1));
  }
  if (!bad.empty())
    return GlyphError{bad};
  auto impl = std::make_unique<FreeTypeGlyph::Impl>();
  if (const FT_Error e = FT_Init_FreeType(&impl->library); e != 0) {
    impl->library = nullptr;
    return GlyphError{"cannot start FreeType (error " + hex_error(e) + ")"};
  }
  if (FT_Outline_New(impl->library, static_cast<FT_UInt>(points.size()),
                     static_cast<FT_Int>(ends.size()), &impl->outline) != 0)
    return GlyphError{"out of memory making a FreeType outline"};
  impl->outline_made = true;
  std::copy(points.begin(), points.end(), impl->outline.points);
  std::copy(tags.begin(), tags.end(), impl->outline.tags);
  std::copy(ends.begin(), ends.end(), impl->outline.contours);
  // Add to FT_Outline_New's flags, never replace them: its FT_OUTLINE_OWNER is what makes
  // FT_Outline_Done free the arrays (without it every outline leaked its points).
  if (g.path.fill_rule == path::FillRule::kEvenOdd)
    impl->outline.flags |= FT_OUTLINE_EVEN_ODD_FILL;
  impl->glyph = g;
  return FreeTypeGlyph(std::move(impl));
}

// rule: PATH.GLYPH.SOURCE
std::variant<Glyph, GlyphError> load_glyph(const std::string& font_file, char32_t code_point,
                                           int pixel_size) {
  auto r = load_freetype_glyph(font_file, code_point, pixel_size);
  if (auto* e = std::get_if<GlyphError>(&r))
    return *e;
  return std::get<FreeTypeGlyph>(r).glyph();
}

// rule: PATH.GLYPH.SOURCE
Scene glyph_scene(const Glyph& g, path::Coverage coverage) {
  // raw / 256 is exact in float32 (|raw| < 2^24) and snaps back to raw.
  auto fpt = [](const path::Point& p) {
    return FloatPoint{static_cast<float>(p.x) / 256.0f, static_cast<float>(p.y) / 256.0f};
  };
  FloatPath fp;
  fp.fill_rule = g.path.fill_rule;
  fp.coverage = coverage;
  for (const path::Contour& c : g.path.contours) {
    FloatContour fc;
    fc.start = fpt(c.start);
    for (const path::Segment& s : c.segments) {
      FloatPathSegment fs;
      fs.kind = s.kind;
      for (std::size_t k = 0; k < path::point_count(s.kind); ++k)
        fs.p[k] = fpt(s.p[k]);
      fc.segments.push_back(fs);
    }
    fp.contours.push_back(std::move(fc));
  }
  Scene scene;
  scene.width = g.width;
  scene.height = g.height;
  scene.primitives.push_back(make_path(std::move(fp)));
  return scene;
}

} // namespace rastrules::io
