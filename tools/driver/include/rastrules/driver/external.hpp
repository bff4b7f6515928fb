// SPDX-License-Identifier: MIT
// The external-process driver: any executable that reads a scene file on standard input and
// writes its coverage as a fragment list on standard output (spec/driver.md
// DRIVER.EXTERNAL.PROTOCOL). `rastrules render - --fragments -` is itself one.
// Implements: DRIVER.EXTERNAL.PROTOCOL

#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/driver/driver.hpp"

namespace rastrules::driver {

// The most fragments one output may list by default: the default of `rastrules render
// --max-fragments` (SCENE.INPUT.LIMITS), so that a driver may return what the reference may.
inline constexpr std::uint64_t kDefaultExternalMaxFragments = std::uint64_t{1} << 26;

// The limits of one draw (DRIVER.EXTERNAL.PROTOCOL, item 5).
struct ExternalOptions {
  // Per scene, writing the scene and reading the output included; the process is killed after it.
  std::int64_t timeout_ms = 10000;
  std::size_t max_output_bytes = std::size_t{64} << 20;       // standard output larger: an error
  std::uint64_t max_fragments = kDefaultExternalMaxFragments; // a longer list: an error
};

// The most RASTRULES_EXTERNAL_TIMEOUT_MS may say: one day, in milliseconds.
inline constexpr std::int64_t kMaxExternalTimeoutMs = 86400000;

// Returns the default options, with timeout_ms taken from the environment variable
// RASTRULES_EXTERNAL_TIMEOUT_MS when it is set: an integer in [1, kMaxExternalTimeoutMs].
// Anything else sets *error to one line naming the variable and its range (and the default
// stays); error may be null.
// rule: DRIVER.EXTERNAL.PROTOCOL
[[nodiscard]] ExternalOptions default_external_options(std::string* error = nullptr);

// Splits COMMAND into arguments: on spaces and tabs when it holds only characters that no
// shell would treat specially (letters, digits, and _ - . / : = , + @ %); otherwise
// {"/bin/sh", "-c", COMMAND}. An empty command gives an empty vector.
[[nodiscard]] std::vector<std::string> external_argv(std::string_view command);

// Parses the fragment list the process wrote, checking it against the scene: every
// fragment inside the target, prim < number of primitives, mask < 2^samples, no duplicate
// (prim, x, y, seg, sample), at most max_fragments fragments. A strict streaming reader (no
// document tree): it checks each value as it reads it and stops at the first error, holding the
// fragments read so far (sizeof(Fragment), twice while the list grows, + at most 24 bytes each)
// and the current token.
// Returns the fragments sorted as SCENE.OUTPUT.FRAGMENTS or an error message naming the
// fragment and field (or the limit).
// rule: DRIVER.EXTERNAL.PROTOCOL
[[nodiscard]] std::variant<std::vector<Fragment>, std::string>
parse_external_fragments(std::string_view text, const Scene& scene,
                         std::uint64_t max_fragments = kDefaultExternalMaxFragments);

// The same, with the values of pipeline fragments (DRIVER.VALUES): `part`, `attr` and `depth`
// read into Drawing::values (empty when no fragment has any), `bary` and `passed` checked and
// not kept.
// rule: DRIVER.EXTERNAL.PROTOCOL, DRIVER.VALUES
[[nodiscard]] std::variant<Drawing, std::string>
parse_external_drawing(std::string_view text, const Scene& scene,
                       std::uint64_t max_fragments = kDefaultExternalMaxFragments);
[[nodiscard]] std::variant<Drawing, std::string>
read_external_drawing(const std::function<std::string_view()>& next, const Scene& scene,
                      std::uint64_t max_fragments = kDefaultExternalMaxFragments);

// The same, reading the text piece by piece as it arrives: next() returns the next bytes (valid
// until its next call), an empty view at the end; it is not called again after the first error.
// The external driver reads the process's standard output this way, within its timeout.
// rule: DRIVER.EXTERNAL.PROTOCOL
[[nodiscard]] std::variant<std::vector<Fragment>, std::string>
read_external_fragments(const std::function<std::string_view()>& next, const Scene& scene,
                        std::uint64_t max_fragments = kDefaultExternalMaxFragments);

// What an external driver declares it can draw, in its reply to the capabilities query
// (DRIVER.EXTERNAL.CAPABILITIES). Every key of the reply is optional; an absent key allows
// everything it would restrict, so a driver that declares nothing draws every scene.
struct Capabilities {
  std::uint32_t primitives = ~0u;    // bit PrimitiveType: the types it draws
  std::uint32_t line_modes = ~0u;    // bit LineMode (SCENE.LINE_MODE) of its line primitives
  std::uint32_t fill = ~0u;          // bit FillConvention (TRI.FILL.CONVENTION)
  std::uint32_t patterns = ~0u;      // bit PatternKind (MSAA.PATTERN.*)
  std::uint32_t sample_counts = ~0u; // bit log2(count): 1, 2, 4, 8, 16
  bool antialiased_lines = true;     // lines with "aa": true
  bool sample_mask = true;           // a sample mask that clears a sample
  bool sample_shading = true;        // sample-frequency shading
  bool pipeline = true;              // scenes with pipeline state (SCENE.PIPELINE)
  bool values = true;                // writes depth and attribute values (DRIVER.VALUES)
  std::int32_t max_target_side = std::numeric_limits<std::int32_t>::max();
  int subpixel_bits = -1; // as declared (-1: not said); reported, not used to decide
  // What it draws of paths (DRIVER.EXTERNAL.PATHS), from the reply's "paths" object; none
  // without it: path scenes are then never given to the driver.
  std::optional<PathSupport> paths;
};

// The name of the environment variable that turns a run of the driver into the capabilities
// query, and its value.
inline constexpr const char* kCapabilitiesQueryVariable = "RASTRULES_QUERY";
inline constexpr const char* kCapabilitiesQueryValue = "capabilities";

// Parses the reply to the capabilities query: {"capabilities": {...}} with the keys of
// DRIVER.EXTERNAL.CAPABILITIES. Returns the capabilities or one line naming the key and the
// problem (an unknown key or name, a wrong type, an empty list).
// rule: DRIVER.EXTERNAL.CAPABILITIES
[[nodiscard]] std::variant<Capabilities, std::string> parse_capabilities(std::string_view text);

// Returns an empty string when a driver with these capabilities can draw the scene, else the
// first reason it cannot ("line_mode 'quad-wide' not declared", ...).
// rule: DRIVER.EXTERNAL.CAPABILITIES
[[nodiscard]] std::string undeclared(const Capabilities& caps, const Scene& scene);

// Narrows a driver's info to its declaration: the primitive types, line modes, sample counts,
// mask, shading and target side campaigns may generate (FUZZ.GENERATE reads info()), and its
// paths (info.paths: none unless declared, DRIVER.EXTERNAL.PATHS).
// rule: DRIVER.EXTERNAL.CAPABILITIES
void apply_capabilities(const Capabilities& caps, DriverInfo& info);

// The environment variable that names the directory of the Node drivers (skia.mjs,
// tiny-skia.mjs and their node_modules; DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA).
inline constexpr const char* kNodeDriversVariable = "RASTRULES_NODE_DRIVERS";

// The directory of the Node drivers: $RASTRULES_NODE_DRIVERS when set and not empty, else the
// source tree's tools/driver/node as configured by CMake. The "skia" and "tiny-skia" drivers run
// `node DIR/skia.mjs` and `node DIR/tiny-skia.mjs` through the external protocol
// (DRIVER.EXTERNAL.PATHS).
// rule: DRIVER.PATH.SKIA, DRIVER.PATH.TINY_SKIA
[[nodiscard]] std::string node_drivers_dir();

// Opens "external:COMMAND" given COMMAND, and runs the capabilities query once
// (DRIVER.EXTERNAL.CAPABILITIES): a reply restricts what the driver is given (info() and
// unsupported()); no reply (a non-zero exit, no "capabilities" object) declares nothing. On
// failure (an empty command, a malformed reply) returns nullptr and sets *error.
[[nodiscard]] std::unique_ptr<Driver>
open_external_driver(std::string_view command, std::string* error,
                     ExternalOptions options = default_external_options());

} // namespace rastrules::driver
