// SPDX-License-Identifier: MIT
// libFuzzer target: an external driver's output under the streaming reader (tools/driver,
// rastrules::driver::read_external_fragments), as the driver reads it from the process: in
// pieces of any size, with a fragment limit. Byte 0 chooses the scene (fz::protocol_scene),
// byte 1 the fragment limit (0: the default, else 1 to 255), byte 2 the piece sizes; the rest is
// the output text. Must never crash, leak, hang or hit undefined behaviour, and:
// - the result read piece by piece is the result of the whole text read at once
//   (parse_external_fragments), error or fragments, whatever the pieces (the NUL byte's line
//   and column included);
// - an accepted output lists at most the limit's fragments; an output the default limit
//   accepts with more is refused naming the limit, and one within the limit is read the same
//   under both limits.
// rule: DRIVER.EXTERNAL.PROTOCOL, SCENE.INPUT.ERRORS

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/driver/external.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace {

namespace fz = rastrules::fuzz;
namespace drv = rastrules::driver;
using Parsed = std::variant<std::vector<rastrules::Fragment>, std::string>;

std::string describe(const Parsed& p) {
  if (const auto* e = std::get_if<std::string>(&p))
    return "error: " + *e;
  return std::to_string(std::get<0>(p).size()) + " fragments";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3 || size > (std::size_t{1} << 20))
    return 0;
  const rastrules::Scene scene = fz::protocol_scene(data[0]);
  const std::uint64_t limit = data[1] == 0 ? drv::kDefaultExternalMaxFragments : data[1];
  std::uint32_t state = 0x9e3779b9u ^ data[2]; // piece sizes: 1 to 1 + (data[2] & 63)
  const std::string_view text(reinterpret_cast<const char*>(data + 3), size - 3);

  std::size_t at = 0;
  const auto next = [&]() -> std::string_view {
    state = state * 1664525u + 1013904223u;
    const std::size_t n = 1 + (state >> 16) % (1u + (data[2] & 63u));
    const std::string_view piece = text.substr(at, n);
    at += piece.size();
    return piece;
  };
  const Parsed pieces = drv::read_external_fragments(next, scene, limit);
  const Parsed whole = drv::parse_external_fragments(text, scene, limit);
  if (pieces != whole) {
    fz::fail("the output read in pieces differs from the whole text",
             {describe(pieces), describe(whole)}, &scene, data, size);
  }
  if (const auto* e = std::get_if<std::string>(&whole)) {
    if (e->empty())
      fz::fail("an empty error", {}, &scene, data, size);
  } else if (std::get<0>(whole).size() > limit) {
    fz::fail("accepted more fragments than the limit", {describe(whole)}, &scene, data, size);
  }
  if (limit != drv::kDefaultExternalMaxFragments) {
    const Parsed unlimited = drv::parse_external_fragments(text, scene);
    const bool over = unlimited.index() == 0 && std::get<0>(unlimited).size() > limit;
    const std::string refused = "fragments: more than " + std::to_string(limit) +
                                " fragments (limit DRIVER.EXTERNAL.PROTOCOL)";
    if (over && whole != Parsed(refused))
      fz::fail("an output beyond the limit is not refused naming it", {describe(whole)}, &scene,
               data, size);
    if (!over && unlimited.index() == 0 && whole != unlimited)
      fz::fail("an output within the limit reads differently under it",
               {describe(whole), describe(unlimited)}, &scene, data, size);
  }
  return 0;
}
