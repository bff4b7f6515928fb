// SPDX-License-Identifier: MIT
// Private to the driver library: the constructor of each built-in driver, called by
// registry.cpp. Each returns nullptr and sets *error to a one-line reason on failure. arg is
// the part of the name after the entry's prefix ("" for a plain name).
// Implements: DRIVER.INTERFACE

#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "rastrules/driver/driver.hpp"

namespace rastrules::driver::detail {

std::unique_ptr<Driver> open_reference(std::string_view arg, std::string* error);
// imprecise.cpp: arg "" is "imprecise" (all planted bugs), else one bug: "float-edges", ...
std::unique_ptr<Driver> open_imprecise(std::string_view arg, std::string* error);
// external.cpp: arg is the command line (DRIVER.EXTERNAL.PROTOCOL).
std::unique_ptr<Driver> open_external(std::string_view arg, std::string* error);
// external.cpp: Skia (canvaskit-wasm) and tiny-skia (@resvg/resvg-js) as Node programs run
// through the external protocol (DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA); always built, they
// fail to open with what to run when node or the npm packages are missing.
std::unique_ptr<Driver> open_skia(std::string_view arg, std::string* error);
std::unique_ptr<Driver> open_tiny_skia(std::string_view arg, std::string* error);
// path_planted.cpp: 2D rasterizers with one planted bug each (DRIVER.PATH.PLANTED).
std::unique_ptr<Driver> open_planted_path(std::string_view arg, std::string* error);
#if defined(RASTRULES_HAVE_FREETYPE)
// freetype.cpp: FreeType's monochrome and gray rasterizers (DRIVER.PATH.FREETYPE).
std::unique_ptr<Driver> open_freetype(std::string_view arg, std::string* error);
#endif
#if defined(RASTRULES_HAVE_CAIRO)
// cairo.cpp: cairo_fill into an A8 image surface (DRIVER.PATH.CAIRO); arg "" or the antialias
// mode of antialiased paths: "default", "best", "good", "fast".
std::unique_ptr<Driver> open_cairo(std::string_view arg, std::string* error);
#endif
#if defined(RASTRULES_HAVE_AGG)
// agg.cpp: AGG's rasterizer_scanline_aa into a gray8 buffer (DRIVER.PATH.AGG).
std::unique_ptr<Driver> open_agg(std::string_view arg, std::string* error);
#endif
#if defined(RASTRULES_HAVE_LAVAPIPE)
std::unique_ptr<Driver> open_lavapipe(std::string_view arg, std::string* error);
#endif
#if defined(RASTRULES_HAVE_OPENGL)
std::unique_ptr<Driver> open_opengl(std::string_view arg, std::string* error);
#endif

// Returns the fragments a driver reports for a kernel result: helper lanes removed, and the
// fields drivers cannot observe (coverage_q16, centroid, derivatives) cleared. seg and sample
// are kept: they are part of a fragment's key.
// rule: DRIVER.INTERFACE
[[nodiscard]] std::vector<Fragment> observable(std::vector<Fragment> fragments);

// Returns a pipeline result as a driver reports it (DRIVER.VALUES): helper lanes removed, the
// fragments observable, each with its part, attributes and depths (none when run_pipeline gave
// no data), sorted as sort_drawing() sorts.
// rule: DRIVER.VALUES
[[nodiscard]] Drawing observable_drawing(pipe::PipeResult result);

// Returns the fragments of a drawing (or its error): draw() of the drivers that draw through
// draw_values().
[[nodiscard]] DrawResult coverage_of(ValuesResult r);

// Returns the info of a driver that draws everything a scene can ask for (every sample count,
// primitive, line mode, the sample mask and sample shading, targets up to kMaxTargetSide): the
// reference and, by declaration, an external process.
[[nodiscard]] DriverInfo full_capabilities(std::string name, std::string description,
                                           int subpixel_bits);

} // namespace rastrules::driver::detail
