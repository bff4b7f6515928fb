// SPDX-License-Identifier: MIT
// The external-process driver: any executable that reads a scene file on standard input and
// writes its coverage as a fragment list on standard output (spec/driver.md
// DRIVER.EXTERNAL.PROTOCOL). `rastrules render - --fragments -` is itself one.
// Implements: DRIVER.EXTERNAL.PROTOCOL

#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/driver/driver.hpp"

namespace rastrules::driver {

struct ExternalOptions {
  std::int64_t timeout_ms = 10000;                      // per scene; the process is killed after it
  std::size_t max_output_bytes = std::size_t{64} << 20; // standard output larger: an error
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
// (prim, x, y, seg, sample). Returns the fragments sorted as SCENE.OUTPUT.FRAGMENTS or an
// error message naming the fragment and field.
[[nodiscard]] std::variant<std::vector<Fragment>, std::string>
parse_external_fragments(std::string_view text, const Scene& scene);

// Opens "external:COMMAND" given COMMAND. On failure (empty command) returns nullptr and sets
// *error.
[[nodiscard]] std::unique_ptr<Driver>
open_external_driver(std::string_view command, std::string* error,
                     ExternalOptions options = default_external_options());

} // namespace rastrules::driver
