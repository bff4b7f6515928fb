// SPDX-License-Identifier: MIT
// The scene reader (a strict, streaming SAX handler over nlohmann::json) and writer.
// Implements: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.INPUT.ERRORS, SCENE.PRIM.POINT,
//             SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE, SCENE.MSAA
// The multisampling keys (SCENE.MSAA): the reader checks each key's type and range and builds
// the sample pattern from "samples" and "sample_pattern"; the rules between keys (a sample mask
// wider than the pattern, lines a pattern cannot draw) are prepare()'s (MSAA.LIMITS), except
// an explicit all-ones "sample_mask", which prepare() cannot tell from the default.

#include "rastrules/io/scene_json.hpp"

#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "rastrules/fixed.hpp"
#include "rastrules/snap.hpp"

namespace rastrules::io {
namespace {

// Returns whether a decimal number text (JSON syntax, known not to be zero) has a magnitude
// of at least 1. Used only after std::from_chars reported the value out of float32's range,
// where it tells overflow (|x| > FLT_MAX) from underflow (|x| < half the smallest subnormal).
bool magnitude_at_least_one(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && text[i] == '-') ++i;
  // order = decimal exponent of the first non-zero digit, before applying the exponent part.
  std::int64_t order = 0;
  bool found = false;
  std::int64_t int_digits_after_first = -1;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
    if (!found && text[i] != '0') found = true;
    if (found) ++int_digits_after_first;
  }
  if (found) {
    order = int_digits_after_first;
  } else if (i < text.size() && text[i] == '.') {
    ++i;
    std::int64_t pos = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
      ++pos;
      if (text[i] != '0') {
        found = true;
        order = -pos;
        break;
      }
    }
  }
  while (i < text.size() && text[i] != 'e' && text[i] != 'E') ++i;
  std::int64_t exponent = 0;
  if (i < text.size()) {
    ++i;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
      if (exponent < (std::int64_t{1} << 40)) exponent = exponent * 10 + (text[i] - '0');
    }
    if (negative) exponent = -exponent;
  }
  return found && order + exponent >= 0;
}

enum class Ctx {
  kRootObject,
  kTargetObject,
  kPrimitiveArray,
  kPrimitiveObject,
  kVertexArray,
  kCoordArray,
  kPatternArray,  // "sample_pattern": [[i, j], ...]
  kPatternPair,   // one [i, j]
  kColorArray,    // "clear_color" or "primitives[i].color": [r, g, b, a]
};

// Where a value goes.
enum class Slot {
  kRoot,
  kVersion,
  kTarget,
  kCull,
  kFrontFace,
  kFill,
  kLineMode,
  kPrimitives, // root object
  kWidth,
  kHeight, // target
  kPrimitive,
  kType,
  kVertices,
  kAA,
  kVertex,
  kCoord, // primitives
  kSamples,
  kSamplePattern,
  kSampleMask,
  kCentroid,
  kShading,
  kQuads,
  kDerivatives,
  kClearColor, // root object, multisampling (SCENE.MSAA)
  kColor,      // primitives[i].color
  kPatternEntry,
  kPatternCoord,
  kColorChannel,
};

struct KeySpec {
  std::string_view name;
  Slot slot;
  bool required;
};

constexpr std::array<KeySpec, 15> kRootKeys = {{{"version", Slot::kVersion, false},
                                                {"target", Slot::kTarget, true},
                                                {"cull", Slot::kCull, false},
                                                {"front_face", Slot::kFrontFace, false},
                                                {"fill", Slot::kFill, false},
                                                {"line_mode", Slot::kLineMode, false},
                                                {"samples", Slot::kSamples, false},
                                                {"sample_pattern", Slot::kSamplePattern, false},
                                                {"sample_mask", Slot::kSampleMask, false},
                                                {"centroid", Slot::kCentroid, false},
                                                {"shading", Slot::kShading, false},
                                                {"quads", Slot::kQuads, false},
                                                {"derivatives", Slot::kDerivatives, false},
                                                {"clear_color", Slot::kClearColor, false},
                                                {"primitives", Slot::kPrimitives, true}}};
constexpr std::array<KeySpec, 2> kTargetKeys = {{{"width", Slot::kWidth, true},
                                                 {"height", Slot::kHeight, true}}};
constexpr std::array<KeySpec, 4> kPrimitiveKeys = {{{"type", Slot::kType, true},
                                                    {"v", Slot::kVertices, true},
                                                    {"aa", Slot::kAA, false},
                                                    {"color", Slot::kColor, false}}};
constexpr std::size_t kAAKeyIndex = 2;

// The scene-file names of the multisampling enumerations (SCENE.MSAA).
constexpr std::array<std::pair<std::string_view, CentroidRule>, 2> kCentroidNames = {
    {{"d3d11", CentroidRule::kD3D11}, {"d3d10", CentroidRule::kD3D10}}};
constexpr std::array<std::pair<std::string_view, ShadingRate>, 2> kShadingNames = {
    {{"pixel", ShadingRate::kPixel}, {"sample", ShadingRate::kSample}}};
constexpr std::array<std::pair<std::string_view, DerivativeMode>, 2> kDerivativeNames = {
    {{"fine", DerivativeMode::kFine}, {"coarse", DerivativeMode::kCoarse}}};

// The scene-file names of the line modes (SCENE.LINE_MODE).
constexpr std::array<std::pair<std::string_view, LineMode>, 4> kLineModeNames = {
    {{"d3d", LineMode::kD3DDiamond},
     {"vulkan-bresenham", LineMode::kVulkanBresenham},
     {"quad-wide", LineMode::kQuadWide},
     {"quad-narrow", LineMode::kQuadNarrow}}};

// The vertex count a primitive type needs, for messages.
std::string vertex_count_text(PrimitiveType t) {
  const std::size_t need = required_vertex_count(t);
  if (need == 0)
    return "at least 2 vertices";
  if (need == 1)
    return "exactly 1 vertex";
  return "exactly " + std::to_string(need) + " vertices";
}

enum class Kind { kNull, kBool, kInt, kUint, kFloat, kString, kObject, kArray };

struct Value {
  Kind kind = Kind::kNull;
  bool b = false;
  std::int64_t i = 0;
  std::uint64_t u = 0;
  std::string_view text;  // number text for kFloat, content for kString
};

std::string describe(const Value& v) {
  switch (v.kind) {
    case Kind::kNull: return "null";
    case Kind::kBool: return v.b ? "true" : "false";
    case Kind::kInt: return std::to_string(v.i);
    case Kind::kUint: return std::to_string(v.u);
    case Kind::kFloat: return printable(v.text);
    case Kind::kString: return "the string \"" + printable(v.text) + "\"";
    case Kind::kObject: return "an object";
    case Kind::kArray: return "an array";
  }
  return "a value";
}

struct Frame {
  Ctx ctx;
  std::string path;        // field path of this object or array
  unsigned seen = 0;       // objects: bit k set when key k was given
  std::size_t count = 0;   // arrays: number of elements so far
  Slot key_slot = Slot::kRoot;
  std::string key_path;    // objects: path of the value of the last key
};

// The SAX handler: validates the schema while the parser streams, so that memory stays
// proportional to the scene, and stops at the first error.
// rule: SCENE.FORMAT.V1, SCENE.INPUT.ERRORS
class SceneReader {
 public:
  using json = nlohmann::json;

  bool null() { return value(Value{Kind::kNull, false, 0, 0, {}}); }
  bool boolean(bool b) { return value(Value{Kind::kBool, b, 0, 0, {}}); }
  bool number_integer(json::number_integer_t i) { return value(Value{Kind::kInt, false, i, 0, {}}); }
  // nlohmann reports every non-negative integer here; those an int64_t holds go on as kInt.
  bool number_unsigned(json::number_unsigned_t u) {
    if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      return value(Value{Kind::kInt, false, static_cast<std::int64_t>(u), 0, {}});
    }
    return value(Value{Kind::kUint, false, 0, u, {}});
  }
  bool number_float(json::number_float_t, const json::string_t& s) {
    return value(Value{Kind::kFloat, false, 0, 0, s});
  }
  bool string(json::string_t& s) { return value(Value{Kind::kString, false, 0, 0, s}); }
  bool binary(json::binary_t&) { return fail("scene", "binary values are not JSON text"); }
  bool start_object(std::size_t) { return value(Value{Kind::kObject, false, 0, 0, {}}); }
  bool start_array(std::size_t) { return value(Value{Kind::kArray, false, 0, 0, {}}); }

  bool key(json::string_t& k) {
    Frame& f = stack_.back();
    // An empty key is named "" so that the error still names a field (found by fuzz_scene_parser).
    const std::string name = k.empty() ? std::string("\"\"") : printable(k);
    const std::string field = f.path.empty() ? name : f.path + "." + name;
    auto check = [&](const auto& keys) {
      for (std::size_t n = 0; n < keys.size(); ++n) {
        if (keys[n].name != k) continue;
        if ((f.seen & (1u << n)) != 0) return fail(field, "duplicate key");
        f.seen |= 1u << n;
        f.key_slot = keys[n].slot;
        f.key_path = field;
        return true;
      }
      std::string expected;
      for (const KeySpec& s : keys) expected += (expected.empty() ? "" : ", ") + std::string(s.name);
      return fail(field, "unknown key (expected " + expected + ")");
    };
    switch (f.ctx) {
      case Ctx::kRootObject: return check(kRootKeys);
      case Ctx::kTargetObject: return check(kTargetKeys);
      case Ctx::kPrimitiveObject: return check(kPrimitiveKeys);
      default: return fail(f.path, "internal error: key outside an object");
    }
  }

  bool end_object() {
    const Frame f = std::move(stack_.back());
    stack_.pop_back();
    auto required = [&](const auto& keys) {
      for (std::size_t n = 0; n < keys.size(); ++n) {
        if (keys[n].required && (f.seen & (1u << n)) == 0) {
          return fail(f.path.empty() ? std::string(keys[n].name)
                                     : f.path + "." + std::string(keys[n].name),
                      "is missing");
        }
      }
      return true;
    };
    switch (f.ctx) {
      case Ctx::kRootObject: return required(kRootKeys) && finish_pattern();
      case Ctx::kTargetObject: return required(kTargetKeys);
      case Ctx::kPrimitiveObject: {
        if (!required(kPrimitiveKeys)) return false;
        // rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
        // The type may come after "v" and "aa", so both are checked against it here.
        const std::size_t n = current_.v.size();
        const std::size_t need = required_vertex_count(current_.type);
        if ((need != 0 && n != need) || (need == 0 && n < 2)) {
          return fail(f.path + ".v", "a " + std::string(to_string(current_.type)) + " must have " +
                                         vertex_count_text(current_.type) + " [x, y], got " +
                                         std::to_string(n));
        }
        const bool line =
            current_.type == PrimitiveType::kLine || current_.type == PrimitiveType::kLineStrip;
        if ((f.seen & (1u << kAAKeyIndex)) != 0 && !line) {
          return fail(f.path + ".aa", "only lines and line strips take \"aa\", not a " +
                                          std::string(to_string(current_.type)));
        }
        scene_.primitives.push_back(std::move(current_));
        return true;
      }
      default: return fail(f.path, "internal error: unbalanced object");
    }
  }

  bool end_array() {
    const Frame f = std::move(stack_.back());
    stack_.pop_back();
    if (f.ctx == Ctx::kCoordArray && f.count != 2) {
      return fail(f.path, "must have exactly 2 coordinates [x, y], got " + std::to_string(f.count));
    }
    // rule: SCENE.MSAA, MSAA.PATTERN.CUSTOM
    if (f.ctx == Ctx::kPatternArray && f.count == 0) {
      return fail(f.path, "must have 1 to " + std::to_string(kMaxSamples) +
                              " positions [i, j], got none");
    }
    if (f.ctx == Ctx::kPatternPair && f.count != 2) {
      return fail(f.path, "must have exactly 2 offsets [i, j], got " + std::to_string(f.count));
    }
    if (f.ctx == Ctx::kColorArray && f.count != 4) {
      return fail(f.path, "must have exactly 4 channels [r, g, b, a], got " + std::to_string(f.count));
    }
    return true;
  }

  bool parse_error(std::size_t, const std::string& last_token,
                   const nlohmann::detail::exception& ex) {
    if (error_) return false;
    if (ex.id == 406) {
      // A number beyond double's range ("1e400"): nlohmann stops here. Treat it as the
      // number it is (an infinity in float32) and report what that value means in place.
      if (!value(Value{Kind::kFloat, false, 0, 0, last_token})) return false;
      return fail(last_path_, "is " + std::string(to_string(snap_to_subpixel(
                                           std::numeric_limits<float>::infinity()).status)));
    }
    std::string what = ex.what();
    const std::size_t close = what.find("] ");
    if (what.rfind("[json.exception.", 0) == 0 && close != std::string::npos) {
      what = what.substr(close + 2);
    }
    error_ = SceneError{"", printable(what, 300)};
    return false;
  }

  [[nodiscard]] std::variant<Scene, SceneError> result(bool ok) {
    if (error_) return *error_;
    if (!ok) return SceneError{"", "parse error: input ended early"};
    return std::move(scene_);
  }

 private:
  bool fail(std::string field, std::string message) {
    if (!error_) error_ = SceneError{std::move(field), std::move(message)};
    return false;
  }

  bool type_error(const std::string& field, std::string_view expected, const Value& v) {
    return fail(field, "must be " + std::string(expected) + ", got " + describe(v));
  }

  // Dispatches one value (scalar, or the start of an object or array) to its slot.
  bool value(const Value& v) {
    Slot slot = Slot::kRoot;
    std::string field = "scene";
    if (!stack_.empty()) {
      Frame& f = stack_.back();
      switch (f.ctx) {
        case Ctx::kRootObject:
        case Ctx::kTargetObject:
        case Ctx::kPrimitiveObject:
          slot = f.key_slot;
          field = f.key_path;
          break;
        case Ctx::kPrimitiveArray:
          // rule: SCENE.INPUT.LIMITS
          if (f.count >= kMaxScenePrimitives) {
            return fail(f.path, "more than " + std::to_string(kMaxScenePrimitives) +
                                    " primitives (limit SCENE.INPUT.LIMITS)");
          }
          slot = Slot::kPrimitive;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
        case Ctx::kVertexArray:
          // rule: SCENE.INPUT.LIMITS
          if (f.count >= kMaxStripVertices) {
            return fail(f.path, "more than " + std::to_string(kMaxStripVertices) +
                                    " vertices in one primitive (limit SCENE.INPUT.LIMITS)");
          }
          slot = Slot::kVertex;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
        case Ctx::kCoordArray:
          if (f.count == 2) {
            return fail(f.path, "must have exactly 2 coordinates [x, y], got more");
          }
          slot = Slot::kCoord;
          coord_ = f.count;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
        case Ctx::kPatternArray:
          // rule: MSAA.LIMITS
          if (f.count >= kMaxSamples) {
            return fail(f.path, "must have 1 to " + std::to_string(kMaxSamples) +
                                    " positions [i, j], got more");
          }
          slot = Slot::kPatternEntry;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
        case Ctx::kPatternPair:
          if (f.count == 2) return fail(f.path, "must have exactly 2 offsets [i, j], got more");
          slot = Slot::kPatternCoord;
          coord_ = f.count;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
        case Ctx::kColorArray:
          if (f.count == 4) return fail(f.path, "must have exactly 4 channels [r, g, b, a], got more");
          slot = Slot::kColorChannel;
          coord_ = f.count;
          field = f.path + "[" + std::to_string(f.count++) + "]";
          break;
      }
    } else if (root_done_) {
      return fail("scene", "more than one JSON value");
    }
    last_path_ = field;
    switch (slot) {
      case Slot::kRoot:
        if (v.kind != Kind::kObject) return type_error("scene", "a JSON object", v);
        root_done_ = true;
        return push(Ctx::kRootObject, "");
      case Slot::kVersion:
        if (v.kind == Kind::kInt && v.i == 1) return true;
        return type_error(field, "the integer 1", v);
      case Slot::kTarget:
        if (v.kind != Kind::kObject) return type_error(field, "an object {\"width\", \"height\"}", v);
        return push(Ctx::kTargetObject, field);
      case Slot::kWidth: return size(field, v, scene_.width);
      case Slot::kHeight: return size(field, v, scene_.height);
      case Slot::kCull:
        return enumeration(field, v, std::array<std::pair<std::string_view, CullMode>, 3>{{
                                         {"none", CullMode::kNone},
                                         {"back", CullMode::kBack},
                                         {"front", CullMode::kFront}}},
                           scene_.state.cull);
      case Slot::kFrontFace:
        return enumeration(field, v, std::array<std::pair<std::string_view, FrontFace>, 2>{{
                                         {"cw", FrontFace::kClockwise},
                                         {"ccw", FrontFace::kCounterClockwise}}},
                           scene_.state.front_face);
      case Slot::kFill:
        return enumeration(field, v, std::array<std::pair<std::string_view, FillConvention>, 4>{{
                                         {"top-left", FillConvention::kTopLeft},
                                         {"top-right", FillConvention::kTopRight},
                                         {"bottom-left", FillConvention::kBottomLeft},
                                         {"bottom-right", FillConvention::kBottomRight}}},
                           scene_.state.fill);
      case Slot::kLineMode:
        // rule: SCENE.LINE_MODE
        return enumeration(field, v, kLineModeNames, scene_.line_mode);
      case Slot::kPrimitives:
        if (v.kind != Kind::kArray) return type_error(field, "an array of primitives", v);
        return push(Ctx::kPrimitiveArray, field);
      case Slot::kPrimitive:
        if (v.kind != Kind::kObject) return type_error(field, "an object {\"type\", \"v\"}", v);
        current_ = Primitive{};
        current_.v.clear();
        return push(Ctx::kPrimitiveObject, field);
      case Slot::kType:
        if (v.kind != Kind::kString) return type_error(field, "a string", v);
        for (const PrimitiveType t : {PrimitiveType::kTriangle, PrimitiveType::kPoint,
                                      PrimitiveType::kLine, PrimitiveType::kLineStrip}) {
          if (v.text == to_string(t)) {
            current_.type = t;
            return true;
          }
        }
        return fail(field, "unknown primitive type \"" + printable(v.text) +
                               "\" (expected \"triangle\", \"point\", \"line\" or \"line_strip\")");
      case Slot::kVertices:
        if (v.kind != Kind::kArray)
          return type_error(field, "an array of vertices [x, y]", v);
        return push(Ctx::kVertexArray, field);
      case Slot::kAA:
        // rule: SCENE.PRIM.LINE
        if (v.kind != Kind::kBool)
          return type_error(field, "true or false", v);
        current_.aa = v.b;
        return true;
      case Slot::kVertex:
        if (v.kind != Kind::kArray) return type_error(field, "an array [x, y]", v);
        current_.v.push_back(FloatPoint{0.0f, 0.0f});
        return push(Ctx::kCoordArray, field);
      case Slot::kCoord: return coordinate(field, v);
      // rule: SCENE.MSAA, MSAA.LIMITS
      case Slot::kSamples:
        if (v.kind == Kind::kInt && v.i >= 1 && v.i <= kMaxSamples) {
          samples_ = static_cast<std::uint32_t>(v.i);
          return true;
        }
        return type_error(field, "an integer in [1, " + std::to_string(kMaxSamples) + "]", v);
      case Slot::kSamplePattern:
        if (v.kind == Kind::kString && v.text == "standard") {
          pattern_kind_ = PatternKind::kStandard;
          return true;
        }
        if (v.kind == Kind::kString && v.text == "center") {
          pattern_kind_ = PatternKind::kCenter;
          return true;
        }
        if (v.kind == Kind::kArray) {
          pattern_kind_ = PatternKind::kCustom;
          return push(Ctx::kPatternArray, field);
        }
        return type_error(field, "\"standard\", \"center\" or an array of [i, j] offsets", v);
      case Slot::kPatternEntry:
        if (v.kind != Kind::kArray) return type_error(field, "an array [i, j]", v);
        custom_.push_back(SampleOffset{});
        return push(Ctx::kPatternPair, field);
      case Slot::kPatternCoord: {
        // rule: MSAA.PATTERN.GRID
        const bool on_grid = v.kind == Kind::kInt && v.i >= kSampleGridMin && v.i <= kSampleGridMax;
        if (!on_grid) {
          return type_error(field, "an integer in [" + std::to_string(kSampleGridMin) + ", " +
                                       std::to_string(kSampleGridMax) + "]", v);
        }
        (coord_ == 0 ? custom_.back().x : custom_.back().y) = static_cast<std::int8_t>(v.i);
        return true;
      }
      case Slot::kSampleMask:
        // rule: MSAA.MASK.AND
        // Only the type and the 32-bit range here; bits beyond the pattern are prepare()'s.
        if (v.kind == Kind::kInt && v.i >= 0 && v.i <= 0xFFFFFFFFll) {
          scene_.msaa.sample_mask = static_cast<std::uint32_t>(v.i);
          sample_mask_given_ = true;
          return true;
        }
        return type_error(field, "an integer in [0, 4294967295]", v);
      case Slot::kCentroid:
        scene_.msaa.has_centroid = true;
        return enumeration(field, v, kCentroidNames, scene_.msaa.centroid_rule);
      case Slot::kShading: return enumeration(field, v, kShadingNames, scene_.msaa.shading);
      case Slot::kQuads:
        if (v.kind != Kind::kBool) return type_error(field, "true or false", v);
        scene_.msaa.quads = v.b;
        return true;
      case Slot::kDerivatives:
        return enumeration(field, v, kDerivativeNames, scene_.msaa.derivatives);
      case Slot::kClearColor:
      case Slot::kColor:
        if (v.kind != Kind::kArray) return type_error(field, "an array [r, g, b, a]", v);
        color_ = slot == Slot::kClearColor ? &scene_.clear_color : &current_.color;
        return push(Ctx::kColorArray, field);
      case Slot::kColorChannel:
        if (v.kind == Kind::kInt && v.i >= 0 && v.i <= 255) {
          (*color_)[coord_] = static_cast<std::uint8_t>(v.i);
          return true;
        }
        return type_error(field, "an integer in [0, 255]", v);
    }
    return fail(field, "internal error: unknown slot");
  }

  // Builds the sample pattern from "samples" and "sample_pattern", which may come in either
  // order, once the root object is complete.
  // rule: SCENE.MSAA, MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM
  bool finish_pattern() {
    if (pattern_kind_ == PatternKind::kCustom) {
      if (samples_ && *samples_ != custom_.size()) {
        return fail("samples", std::to_string(*samples_) + " does not match the " +
                                   std::to_string(custom_.size()) +
                                   " positions of sample_pattern");
      }
      scene_.msaa.pattern = custom_pattern(std::move(custom_));
      return check_explicit_all_ones_mask();
    }
    const std::uint32_t n = samples_.value_or(1);
    if (!is_standard_count(n)) {
      return fail("samples", std::to_string(n) + " has no " +
                                 std::string(to_string(pattern_kind_)) +
                                 " pattern (1, 2, 4, 8, 16)");
    }
    scene_.msaa.pattern =
        pattern_kind_ == PatternKind::kCenter ? center_pattern(n) : standard_pattern(n);
    return check_explicit_all_ones_mask();
  }

  // In memory, 0xFFFFFFFF is the default "all samples" and prepare() accepts it whatever the
  // count; in a file the key holds at most the pattern's bits (MSAA.LIMITS), so the all-ones
  // value written out is refused here, with prepare()'s message for any wider mask.
  // rule: MSAA.LIMITS
  bool check_explicit_all_ones_mask() {
    const std::uint32_t n = scene_.msaa.pattern.count();
    if (!sample_mask_given_ || scene_.msaa.sample_mask != 0xFFFFFFFFu || n >= 32) return true;
    return fail("sample_mask", "must be an integer in [0, " + std::to_string(full_mask(n)) +
                                   "] (bit k is sample k of " + std::to_string(n) +
                                   "), got 4294967295 (0xffffffff)");
  }

  bool push(Ctx ctx, std::string path) {
    stack_.push_back(Frame{ctx, std::move(path), 0, 0, Slot::kRoot, {}});
    return true;
  }

  // rule: SCENE.TARGET.LIMITS
  // The range itself is checked by the kernel's prepare(); here only that the value is an
  // integer that an int32_t holds, with the same message for values beyond it.
  bool size(const std::string& field, const Value& v, std::int32_t& out) {
    const std::string expected = "an integer in [1, " + std::to_string(kMaxTargetSide) + "]";
    if (v.kind == Kind::kInt && v.i >= std::numeric_limits<std::int32_t>::min() &&
        v.i <= std::numeric_limits<std::int32_t>::max()) {
      out = static_cast<std::int32_t>(v.i);
      return true;
    }
    return type_error(field, expected, v);
  }

  template <class Enum, std::size_t N>
  bool enumeration(const std::string& field, const Value& v,
                   const std::array<std::pair<std::string_view, Enum>, N>& names, Enum& out) {
    std::string expected = "one of";
    for (std::size_t n = 0; n < N; ++n) {
      expected += (n == 0 ? " \"" : ", \"") + std::string(names[n].first) + "\"";
    }
    if (v.kind != Kind::kString) return type_error(field, expected, v);
    for (const auto& [name, e] : names) {
      if (v.text == name) {
        out = e;
        return true;
      }
    }
    return type_error(field, expected, v);
  }

  // rule: SCENE.NUMBER.FLOAT32
  bool coordinate(const std::string& field, const Value& v) {
    float f = 0.0f;
    switch (v.kind) {
      case Kind::kInt: f = static_cast<float>(v.i); break;   // one correct rounding
      case Kind::kUint: f = static_cast<float>(v.u); break;  // one correct rounding
      case Kind::kFloat: {
        const std::optional<float> d = decimal_to_float32(v.text);
        if (!d) return fail(field, "is not a number: " + printable(v.text));
        f = *d;
        break;
      }
      case Kind::kString:
        if (v.text == "NaN") {
          f = std::numeric_limits<float>::quiet_NaN();
        } else if (v.text == "Infinity") {
          f = std::numeric_limits<float>::infinity();
        } else if (v.text == "-Infinity") {
          f = -std::numeric_limits<float>::infinity();
        } else {
          return type_error(field, "a number, \"NaN\", \"Infinity\" or \"-Infinity\"", v);
        }
        break;
      default: return type_error(field, "a number, \"NaN\", \"Infinity\" or \"-Infinity\"", v);
    }
    current_.v.back()[coord_] = f;
    return true;
  }

  std::vector<Frame> stack_;
  Scene scene_;
  Primitive current_;
  std::size_t coord_ = 0;
  std::optional<std::uint32_t> samples_;  // "samples", when given
  PatternKind pattern_kind_ = PatternKind::kStandard;
  std::vector<SampleOffset> custom_;      // the positions of a custom "sample_pattern"
  Rgba8* color_ = nullptr;                // the colour being read
  bool sample_mask_given_ = false;
  bool root_done_ = false;
  std::string last_path_;
  std::optional<SceneError> error_;
};

void append_escaped(std::string& out, unsigned char c) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += "\\x";
  out += kHex[c >> 4];
  out += kHex[c & 15u];
}

}  // namespace

std::string_view line_mode_name(LineMode m) {
  for (const auto& [name, mode] : kLineModeNames) {
    if (mode == m)
      return name;
  }
  return "unknown";
}

std::string printable(std::string_view s, std::size_t max_len) {
  std::string out;
  for (const char ch : s) {
    if (out.size() >= max_len) {
      out += "...";
      break;
    }
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) {
      out += ch;
    } else {
      append_escaped(out, c);
    }
  }
  return out;
}

// rule: SCENE.NUMBER.FLOAT32
std::optional<float> decimal_to_float32(std::string_view text) {
  if (text.empty() || !(text[0] == '-' || (text[0] >= '0' && text[0] <= '9'))) return std::nullopt;
  float f = 0.0f;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  // std::from_chars is correctly rounded (round to nearest, ties to even) from the text.
  const std::from_chars_result r = std::from_chars(first, last, f, std::chars_format::general);
  if (r.ptr != last) return std::nullopt;
  if (r.ec == std::errc::result_out_of_range) {
    const bool negative = text[0] == '-';
    if (magnitude_at_least_one(text)) {
      return negative ? -std::numeric_limits<float>::infinity()
                      : std::numeric_limits<float>::infinity();
    }
    return negative ? -0.0f : 0.0f;
  }
  if (r.ec != std::errc{}) return std::nullopt;
  return f;
}

std::string format_float(float v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Infinity" : "-Infinity";
  // "-0" would read back as the integer 0, that is +0.0; "-0.0" is a float and keeps the sign.
  if (v == 0.0f && std::signbit(v)) return "-0.0";
  std::array<char, 64> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

// rule: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.INPUT.ERRORS
std::variant<Scene, SceneError> read_scene(std::string_view json_text) {
  SceneReader reader;
  const bool ok = nlohmann::json::sax_parse(json_text.begin(), json_text.end(), &reader,
                                            nlohmann::json::input_format_t::json,
                                            /*strict=*/true, /*ignore_comments=*/false);
  return reader.result(ok);
}

// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
std::variant<std::string, SceneError> read_scene_file(const std::string& path) {
  const bool is_stdin = path == "-";
  const std::string name = is_stdin ? "<stdin>" : path;
  std::FILE* file = is_stdin ? stdin : std::fopen(path.c_str(), "rb");
  if (file == nullptr) return SceneError{name, std::string("cannot open: ") + std::strerror(errno)};
  std::string text;
  std::array<char, 1 << 16> buf{};
  bool too_large = false;
  for (;;) {
    const std::size_t n = std::fread(buf.data(), 1, buf.size(), file);
    text.append(buf.data(), n);
    if (text.size() > kMaxSceneBytes) {
      too_large = true;
      break;
    }
    if (n < buf.size()) break;
  }
  const bool failed = std::ferror(file) != 0;
  const int err = errno;
  if (!is_stdin) std::fclose(file);
  if (too_large) {
    return SceneError{name, "is larger than " + std::to_string(kMaxSceneBytes >> 20) +
                                " MiB, the largest scene file accepted (limit SCENE.INPUT.LIMITS)"};
  }
  if (failed) return SceneError{name, std::string("cannot read: ") + std::strerror(err)};
  return text;
}

namespace {
// "[r, g, b, a]".
std::string color_text(const Rgba8& c) {
  return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
         ", " + std::to_string(c[3]) + "]";
}
}  // namespace

// rule: SCENE.FORMAT.V1
std::string write_scene(const Scene& scene) {
  std::string out;
  out += "{\n  \"version\": 1,\n";
  out += "  \"target\": {\"width\": " + std::to_string(scene.width) +
         ", \"height\": " + std::to_string(scene.height) + "},\n";
  out += "  \"cull\": \"" + std::string(to_string(scene.state.cull)) + "\",\n";
  out += "  \"front_face\": \"" + std::string(to_string(scene.state.front_face)) + "\",\n";
  out += "  \"fill\": \"" + std::string(to_string(scene.state.fill)) + "\",\n";
  if (scene.line_mode != LineMode::kD3DDiamond) {
    out += "  \"line_mode\": \"" + std::string(line_mode_name(scene.line_mode)) + "\",\n";
  }
  // rule: SCENE.MSAA
  // The multisampling keys, each only when it differs from its default.
  const MultisampleState& ms = scene.msaa;
  if (ms.pattern.kind == PatternKind::kCustom) {
    out += "  \"sample_pattern\": [";
    for (std::size_t k = 0; k < ms.pattern.positions.size(); ++k) {
      const SampleOffset o = ms.pattern.positions[k];
      out += (k == 0 ? "[" : ", [") + std::to_string(o.x) + ", " + std::to_string(o.y) + "]";
    }
    out += "],\n";
  } else {
    if (ms.pattern.count() != 1) out += "  \"samples\": " + std::to_string(ms.pattern.count()) + ",\n";
    if (ms.pattern.kind == PatternKind::kCenter) out += "  \"sample_pattern\": \"center\",\n";
  }
  if (ms.sample_mask != MultisampleState{}.sample_mask) {
    out += "  \"sample_mask\": " + std::to_string(ms.sample_mask) + ",\n";
  }
  if (ms.has_centroid) out += "  \"centroid\": \"" + std::string(to_string(ms.centroid_rule)) + "\",\n";
  if (ms.shading != ShadingRate::kPixel) out += "  \"shading\": \"" + std::string(to_string(ms.shading)) + "\",\n";
  if (ms.quads) out += "  \"quads\": true,\n";
  if (ms.derivatives != DerivativeMode::kNone) {
    out += "  \"derivatives\": \"" + std::string(to_string(ms.derivatives)) + "\",\n";
  }
  if (scene.clear_color != Rgba8{0, 0, 0, 0}) out += "  \"clear_color\": " + color_text(scene.clear_color) + ",\n";
  out += "  \"primitives\": [";
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    out += p == 0 ? "\n" : ",\n";
    const Primitive& prim = scene.primitives[p];
    out += "    {\"type\": \"" + std::string(to_string(prim.type)) + "\", ";
    if (prim.aa)
      out += "\"aa\": true, ";
    if (prim.color != Primitive{}.color) out += "\"color\": " + color_text(prim.color) + ", ";
    out += "\"v\": [";
    for (std::size_t i = 0; i < prim.v.size(); ++i) {
      if (i != 0) out += ", ";
      out += "[";
      for (std::size_t k = 0; k < 2; ++k) {
        if (k != 0) out += ", ";
        const float f = prim.v[i][k];
        const bool quoted = std::isnan(f) || std::isinf(f);
        out += quoted ? "\"" + format_float(f) + "\"" : format_float(f);
      }
      out += "]";
    }
    out += "]}";
  }
  out += scene.primitives.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

bool same_scene(const Scene& a, const Scene& b) {
  if (a.width != b.width || a.height != b.height || a.state.cull != b.state.cull ||
      a.state.front_face != b.state.front_face || a.state.fill != b.state.fill ||
      a.line_mode != b.line_mode || a.primitives.size() != b.primitives.size()) {
    return false;
  }
  const MultisampleState& ma = a.msaa;
  const MultisampleState& mb = b.msaa;
  if (ma.pattern != mb.pattern || ma.sample_mask != mb.sample_mask ||
      ma.has_centroid != mb.has_centroid ||
      (ma.has_centroid && ma.centroid_rule != mb.centroid_rule) || ma.shading != mb.shading ||
      ma.quads != mb.quads || ma.derivatives != mb.derivatives ||
      a.clear_color != b.clear_color) {
    return false;
  }
  for (std::size_t p = 0; p < a.primitives.size(); ++p) {
    const Primitive& pa = a.primitives[p];
    const Primitive& pb = b.primitives[p];
    if (pa.type != pb.type || pa.aa != pb.aa || pa.color != pb.color || pa.v.size() != pb.v.size()) {
      return false;
    }
    for (std::size_t i = 0; i < pa.v.size(); ++i) {
      for (std::size_t k = 0; k < 2; ++k) {
        const float x = pa.v[i][k];
        const float y = pb.v[i][k];
        if (std::isnan(x) && std::isnan(y)) continue;
        if (std::bit_cast<std::uint32_t>(x) != std::bit_cast<std::uint32_t>(y)) return false;
      }
    }
  }
  return true;
}

}  // namespace rastrules::io
