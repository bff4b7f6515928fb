// SPDX-License-Identifier: MIT
// open_driver() and driver_names(): one table of entries, one line per driver. A driver is
// added by declaring its constructor in drivers.hpp and adding its row to kEntries.
// Implements: DRIVER.INTERFACE

#include <algorithm>
#include <array>

#include "drivers.hpp"
#include "rastrules/driver/driver.hpp"

namespace rastrules::driver {
namespace {

using Opener = std::unique_ptr<Driver> (*)(std::string_view arg, std::string* error);

struct Entry {
  std::string_view name;  // the name, or the prefix when prefix is true ("external:")
  bool prefix;            // the rest of the name is the driver's argument
  std::string_view usage; // how driver_names() shows it
  Opener open;
};

// rule: DRIVER.INTERFACE
constexpr auto kEntries = std::to_array<Entry>({
  {"reference", false, "reference", &detail::open_reference},
      {"imprecise", false, "imprecise", &detail::open_imprecise},
      {"imprecise:", true,
       "imprecise:float-edges|fill-bottom-right|4-bit-subpixel|screen-space|provoking-vertex|d24-"
       "truncate",
       &detail::open_imprecise},
      {"external:", true, "external:COMMAND", &detail::open_external},
      {"skia", false, "skia", &detail::open_skia},
      {"tiny-skia", false, "tiny-skia", &detail::open_tiny_skia},
      {"imprecise-path:", true, "imprecise-path:float-accumulation|4-bit-winding|flatten-quarter",
       &detail::open_planted_path},
#if defined(RASTRULES_HAVE_FREETYPE)
      {"freetype", false, "freetype", &detail::open_freetype},
#endif
#if defined(RASTRULES_HAVE_CAIRO)
      {"cairo", false, "cairo", &detail::open_cairo},
      {"cairo:", true, "cairo:default|best|good|fast", &detail::open_cairo},
#endif
#if defined(RASTRULES_HAVE_AGG)
      {"agg", false, "agg", &detail::open_agg},
#endif
#if defined(RASTRULES_HAVE_LAVAPIPE)
      {"lavapipe", false, "lavapipe", &detail::open_lavapipe},
#endif
#if defined(RASTRULES_HAVE_OPENGL)
      {"opengl", false, "opengl", &detail::open_opengl},
#endif
});

} // namespace

std::unique_ptr<Driver> open_driver(std::string_view name, std::string* error) {
  std::string ignored;
  std::string* err = error != nullptr ? error : &ignored;
  for (const Entry& e : kEntries) {
    if (e.prefix ? name.starts_with(e.name) : name == e.name) {
      err->clear();
      return e.open(name.substr(e.prefix ? e.name.size() : name.size()), err);
    }
  }
  std::string known;
  for (const std::string& n : driver_names())
    known += (known.empty() ? "" : ", ") + n;
  *err = "unknown driver '" + std::string(name) + "' (this build has: " + known + ")";
  return nullptr;
}

std::vector<std::string> driver_names() {
  std::vector<std::string> names;
  names.reserve(kEntries.size());
  for (const Entry& e : kEntries)
    names.emplace_back(e.usage);
  return names;
}

} // namespace rastrules::driver
