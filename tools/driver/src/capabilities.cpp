// SPDX-License-Identifier: MIT
// The external driver's capabilities reply: what a driver declares it draws, read strictly,
// and the test of a scene against it.
// Implements: DRIVER.EXTERNAL.CAPABILITIES

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "rastrules/driver/external.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/path_types.hpp"

namespace rastrules::driver {

namespace {

using nlohmann::json;

// A list of names of enum E as a bit set; an error names the key and the bad entry.
template <class E>
std::variant<std::uint32_t, std::string> name_bits(const json& value, std::string_view key) {
  if (!value.is_array() || value.empty())
    return "capabilities: " + std::string(key) + ": expected a non-empty array of names";
  std::uint32_t bits = 0;
  for (const json& v : value) {
    if (!v.is_string())
      return "capabilities: " + std::string(key) + ": expected names (strings)";
    const auto e = from_name<E>(v.get<std::string>());
    if (!e) {
      std::string known;
      for (const auto& [name, _] : Names<E>::table)
        known += (known.empty() ? "" : ", ") + std::string(name);
      return "capabilities: " + std::string(key) + ": unknown name \"" +
             v.get<std::string>().substr(0, 40) + "\" (known: " + known + ")";
    }
    bits |= 1u << static_cast<unsigned>(*e);
  }
  return bits;
}

std::variant<bool, std::string> flag(const json& value, std::string_view key) {
  if (!value.is_boolean())
    return "capabilities: " + std::string(key) + ": expected true or false";
  return value.get<bool>();
}

// The longest method text a "paths" object may give (it is reported, one line).
constexpr std::size_t kMaxMethodChars = 200;

// The raw 16.8 step of a declared path grid: "float" (any float32, so every raw value: 1) or
// "I.F", a fixed-point format with I integer and F fractional bits (I in [1, 32], F in [0, 32]):
// 2^(8 - F) for F < 8 (26.6: 4), else 1. Zero: not a grid name.
std::int32_t grid_step(std::string_view grid) {
  if (grid == "float")
    return 1;
  const std::size_t dot = grid.find('.');
  if (dot == std::string_view::npos)
    return 0;
  const auto number = [](std::string_view t, int hi) {
    int n = -1;
    if (t.empty() || t.size() > 2 || (t.size() == 2 && t[0] == '0'))
      return -1;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
    return ec == std::errc{} && end == t.data() + t.size() && n <= hi ? n : -1;
  };
  const int whole = number(grid.substr(0, dot), 32);
  const int frac = number(grid.substr(dot + 1), 32);
  if (whole < 1 || frac < 0)
    return 0;
  return frac < 8 ? std::int32_t{1} << (8 - frac) : 1;
}

// The "paths" object (DRIVER.EXTERNAL.PATHS): every key optional, an absent one allowing what it
// would restrict, like the reply's other keys; "curves" may be empty (straight paths only).
// rule: DRIVER.EXTERNAL.PATHS
std::variant<PathSupport, std::string> parse_paths(const json& value) {
  if (!value.is_object())
    return std::string("capabilities: paths: expected an object");
  PathSupport ps;
  ps.samples = ps.area = ps.nonzero = ps.evenodd = ps.quadratics = ps.cubics = true;
  ps.grid = "float";
  for (const auto& [key, v] : value.items()) {
    const std::string at = "paths." + key;
    if (key == "samples" || key == "area") {
      const auto on = flag(v, at);
      if (const auto* e = std::get_if<std::string>(&on))
        return *e;
      (key == "samples" ? ps.samples : ps.area) = std::get<bool>(on);
    } else if (key == "fill_rules") {
      const auto bits = name_bits<path::FillRule>(v, at);
      if (const auto* e = std::get_if<std::string>(&bits))
        return *e;
      ps.nonzero = (std::get<std::uint32_t>(bits) >> unsigned(path::FillRule::kNonZero) & 1u) != 0;
      ps.evenodd = (std::get<std::uint32_t>(bits) >> unsigned(path::FillRule::kEvenOdd) & 1u) != 0;
    } else if (key == "curves") {
      if (!v.is_array())
        return "capabilities: " + at + ": expected an array of \"quadratic\", \"cubic\"";
      ps.quadratics = ps.cubics = false;
      for (const json& c : v) {
        const std::string name = c.is_string() ? c.get<std::string>() : c.dump();
        if (name == "quadratic")
          ps.quadratics = true;
        else if (name == "cubic")
          ps.cubics = true;
        else
          return "capabilities: " + at + ": unknown name \"" + name.substr(0, 40) +
                 "\" (known: quadratic, cubic)";
      }
    } else if (key == "grid") {
      const std::string g = v.is_string() ? v.get<std::string>() : std::string();
      ps.grid_raw = grid_step(g);
      if (ps.grid_raw == 0)
        return "capabilities: " + at + ": expected \"float\" or a fixed-point format \"I.F\" " +
               "(I in [1, 32], F in [0, 32] bits: \"26.6\")";
      ps.grid = g;
    } else if (key == "aliased_method" || key == "antialiased_method") {
      if (!v.is_string() || v.get<std::string>().empty() ||
          v.get<std::string>().size() > kMaxMethodChars)
        return "capabilities: " + at + ": expected a text of 1 to " +
               std::to_string(kMaxMethodChars) + " characters";
      (key == "aliased_method" ? ps.aliased_method : ps.antialiased_method) = v.get<std::string>();
    } else {
      return "capabilities: paths: unknown key \"" + key.substr(0, 40) + "\"";
    }
  }
  if (!ps.samples && !ps.area)
    return std::string("capabilities: paths: neither \"samples\" nor \"area\" is drawn");
  return ps;
}

} // namespace

// rule: DRIVER.EXTERNAL.CAPABILITIES
std::variant<Capabilities, std::string> parse_capabilities(std::string_view text) {
  const json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded())
    return std::string("capabilities: the reply is not JSON");
  if (!doc.is_object() || doc.size() != 1 || !doc.contains("capabilities"))
    return std::string("capabilities: expected {\"capabilities\": {...}} and nothing else");
  const json& c = doc["capabilities"];
  if (!c.is_object())
    return std::string("capabilities: expected an object");
  Capabilities caps;
  for (const auto& [key, value] : c.items()) {
    std::variant<std::uint32_t, std::string> bits = std::uint32_t{0};
    std::variant<bool, std::string> on = false;
    if (key == "primitives") {
      bits = name_bits<PrimitiveType>(value, key);
      if (const auto* b = std::get_if<std::uint32_t>(&bits))
        caps.primitives = *b;
    } else if (key == "line_modes") {
      bits = name_bits<LineMode>(value, key);
      if (const auto* b = std::get_if<std::uint32_t>(&bits))
        caps.line_modes = *b;
    } else if (key == "fill_conventions") {
      bits = name_bits<FillConvention>(value, key);
      if (const auto* b = std::get_if<std::uint32_t>(&bits))
        caps.fill = *b;
    } else if (key == "sample_patterns") {
      bits = name_bits<PatternKind>(value, key);
      if (const auto* b = std::get_if<std::uint32_t>(&bits))
        caps.patterns = *b;
    } else if (key == "sample_counts") {
      if (!value.is_array() || value.empty())
        return "capabilities: sample_counts: expected a non-empty array of 1, 2, 4, 8, 16";
      caps.sample_counts = 0;
      for (const json& v : value) {
        const std::uint64_t n = v.is_number_unsigned() ? v.get<std::uint64_t>() : 0;
        if (n == 0 || n > 16 || !std::has_single_bit(n))
          return "capabilities: sample_counts: " + v.dump().substr(0, 40) +
                 " is not one of 1, 2, 4, 8, 16";
        caps.sample_counts |= 1u << std::countr_zero(n);
      }
    } else if (key == "antialiased_lines") {
      if (on = flag(value, key); std::holds_alternative<bool>(on))
        caps.antialiased_lines = std::get<bool>(on);
    } else if (key == "sample_mask") {
      if (on = flag(value, key); std::holds_alternative<bool>(on))
        caps.sample_mask = std::get<bool>(on);
    } else if (key == "sample_shading") {
      if (on = flag(value, key); std::holds_alternative<bool>(on))
        caps.sample_shading = std::get<bool>(on);
    } else if (key == "pipeline") {
      if (on = flag(value, key); std::holds_alternative<bool>(on))
        caps.pipeline = std::get<bool>(on);
    } else if (key == "values") { // rule: DRIVER.VALUES
      if (on = flag(value, key); std::holds_alternative<bool>(on))
        caps.values = std::get<bool>(on);
    } else if (key == "paths") { // rule: DRIVER.EXTERNAL.PATHS
      auto ps = parse_paths(value);
      if (auto* e = std::get_if<std::string>(&ps))
        return std::move(*e);
      caps.paths = std::get<PathSupport>(std::move(ps));
    } else if (key == "max_target_side" || key == "subpixel_bits") {
      const std::int64_t hi = key == "max_target_side" ? std::int64_t{1} << 30 : 24;
      const std::int64_t n = value.is_number_integer() ? value.get<std::int64_t>() : -1;
      if (n < 1 || n > hi)
        return "capabilities: " + key + ": expected an integer in [1, " + std::to_string(hi) + "]";
      (key == "max_target_side" ? caps.max_target_side : caps.subpixel_bits) =
          static_cast<std::int32_t>(n);
    } else {
      return "capabilities: unknown key \"" + key.substr(0, 40) + "\"";
    }
    if (const auto* e = std::get_if<std::string>(&bits))
      return *e;
    if (const auto* e = std::get_if<std::string>(&on))
      return *e;
  }
  // rule: DRIVER.EXTERNAL.PATHS
  if (caps.paths && (caps.primitives >> static_cast<unsigned>(PrimitiveType::kPath) & 1u) == 0)
    return std::string("capabilities: paths: given, but \"path\" is not in primitives");
  return caps;
}

// rule: DRIVER.EXTERNAL.CAPABILITIES
std::string undeclared(const Capabilities& caps, const Scene& scene) {
  const auto has = [](std::uint32_t bits, auto e) {
    return (bits >> static_cast<unsigned>(e) & 1u) != 0;
  };
  const std::string declared = " not declared by the driver";
  if (!caps.pipeline && has_pipeline_state(scene))
    return "pipeline state" + declared;
  if (scene.width > caps.max_target_side || scene.height > caps.max_target_side)
    return "target " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
           " larger than its max_target_side " + std::to_string(caps.max_target_side);
  const MultisampleState& ms = scene.msaa;
  const std::uint32_t count = ms.count();
  if (!std::has_single_bit(count) || !has(caps.sample_counts, std::countr_zero(count)))
    return std::to_string(count) + " samples" + declared;
  if (!has(caps.patterns, ms.pattern.kind))
    return "sample pattern '" + std::string(to_string(ms.pattern.kind)) + "'" + declared;
  if (!caps.sample_mask && ms.effective_mask() != full_mask(count))
    return "a sample mask" + declared;
  if (!caps.sample_shading && ms.shading == ShadingRate::kSample)
    return "sample-frequency shading" + declared;
  bool triangles = false;
  for (const Primitive& p : scene.primitives) {
    if (!has(caps.primitives, p.type))
      return "primitive type '" + std::string(to_string(p.type)) + "'" + declared;
    if (p.type == PrimitiveType::kPath && !caps.paths) // rule: DRIVER.EXTERNAL.PATHS
      return "paths" + declared + " (its capabilities have no \"paths\" object)";
    if (p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip) {
      if (!has(caps.line_modes, scene.conventions.line_mode))
        return "line_mode '" + std::string(to_string(scene.conventions.line_mode)) + "'" + declared;
      if (p.aa && !caps.antialiased_lines)
        return "antialiased lines" + declared;
    }
    triangles = triangles || p.type == PrimitiveType::kTriangle;
  }
  if (triangles && !has(caps.fill, scene.conventions.fill))
    return "fill convention '" + std::string(to_string(scene.conventions.fill)) + "'" + declared;
  return {};
}

// rule: DRIVER.EXTERNAL.CAPABILITIES
void apply_capabilities(const Capabilities& c, DriverInfo& info) {
  const auto on = [](std::uint32_t bits, auto e) {
    return (bits >> static_cast<unsigned>(e) & 1u) != 0;
  };
  info.subpixel_bits = c.subpixel_bits;
  info.triangles = on(c.primitives, PrimitiveType::kTriangle);
  info.points = on(c.primitives, PrimitiveType::kPoint);
  const bool lines =
      on(c.primitives, PrimitiveType::kLine) || on(c.primitives, PrimitiveType::kLineStrip);
  info.lines_d3d = lines && on(c.line_modes, LineMode::kD3DDiamond);
  info.lines_bresenham = lines && on(c.line_modes, LineMode::kVulkanBresenham);
  info.lines_rectangular = lines && on(c.line_modes, LineMode::kQuadNarrow);
  info.sample_counts.clear();
  for (std::uint32_t n = 1; n <= 16; n *= 2) {
    if (on(c.sample_counts, std::countr_zero(n)))
      info.sample_counts.push_back(n);
  }
  info.sample_mask = info.sample_mask && c.sample_mask;
  info.sample_shading = info.sample_shading && c.sample_shading;
  info.values = info.values && c.values && c.pipeline; // rule: DRIVER.VALUES
  info.max_target_side = std::min(info.max_target_side, c.max_target_side);
  // rule: DRIVER.EXTERNAL.PATHS
  info.paths = c.paths && on(c.primitives, PrimitiveType::kPath) ? *c.paths : PathSupport{};
}

} // namespace rastrules::driver
