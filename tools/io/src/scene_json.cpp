// SPDX-License-Identifier: MIT
// The scene reader (a strict, streaming SAX handler over nlohmann::json, json_stream.hpp) and
// writer.
// Implements: SCENE.FORMAT.V1, SCENE.NUMBER.FLOAT32, SCENE.INPUT.ERRORS, SCENE.PRIM.POINT,
//             SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE, SCENE.MSAA,
//             SCENE.PIPELINE, SCENE.PRIM.PATH
// The multisampling keys (SCENE.MSAA): the reader checks each key's type and range and builds
// the sample pattern from "samples" and "sample_pattern"; the rules between keys (a sample mask
// wider than the pattern, lines a pattern cannot draw) are prepare()'s (MSAA.LIMITS), except
// an explicit all-ones "sample_mask", which prepare() cannot tell from the default.
// The pipeline keys (SCENE.PIPELINE): the reader checks types, counts, finiteness, the keys
// that exclude or need each other ("v" or "pos", "attr" and "attributes") and the ranges the
// format itself states (w > 0, depth.clear in [0, 1], at most 16 attributes with unique
// names); the viewport's ranges and the positions' magnitude are run_pipeline()'s.

#include "rastrules/io/scene_json.hpp"

#include <algorithm>
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
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rastrules/fixed.hpp"
#include "rastrules/io/json_stream.hpp"
#include "rastrules/io/svg_path.hpp"
#include "rastrules/names.hpp"
#include "rastrules/snap.hpp"

namespace rastrules::io {
namespace {

// Returns whether a decimal number text (JSON syntax, known not to be zero) has a magnitude
// of at least 1. Used only after std::from_chars reported the value out of float32's range,
// where it tells overflow (|x| > FLT_MAX) from underflow (|x| < half the smallest subnormal).
bool magnitude_at_least_one(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && text[i] == '-')
    ++i;
  // order = decimal exponent of the first non-zero digit, before applying the exponent part.
  std::int64_t order = 0;
  bool found = false;
  std::int64_t int_digits_after_first = -1;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
    if (!found && text[i] != '0')
      found = true;
    if (found)
      ++int_digits_after_first;
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
  while (i < text.size() && text[i] != 'e' && text[i] != 'E')
    ++i;
  std::int64_t exponent = 0;
  if (i < text.size()) {
    ++i;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
      negative = text[i++] == '-';
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
      if (exponent < (std::int64_t{1} << 40))
        exponent = exponent * 10 + (text[i] - '0');
    }
    if (negative)
      exponent = -exponent;
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
  kPatternArray, // "sample_pattern": [[i, j], ...]
  kPatternPair,  // one [i, j]
  kColorArray,   // "clear_color" or "primitives[i].color": [r, g, b, a]
  // Pipeline scenes (SCENE.PIPELINE).
  kViewportObject,
  kTransformObject,
  kMatrixArray, // "transform.model", ".view", ".projection": 16 numbers
  kDepthObject,
  kAttributesArray, // "attributes": [{...}, ...]
  kAttributeObject,
  kNumberList, // "primitives[i].z" or ".w": one number per vertex
  kPosArray,   // "primitives[i].pos": [[x, y, z(, w)], ...]
  kPosCoords,  // one [x, y, z(, w)]
  kAttrArray,  // "primitives[i].attr": [[a0, a1, ...], ...]
  kAttrValues, // one vertex's values
  // Path primitives (SCENE.PRIM.PATH).
  kContourList, // "primitives[i].contours": [contour, ...]
  kContour,     // one contour: [command, ...]
  kCommand,     // one command: ["M" | "L" | "Q" | "C", x, y, ...]
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
  kMultisampleEnable,
  kQuads,
  kDerivatives,
  kClearColor, // root object, multisampling (SCENE.MSAA)
  kColor,      // primitives[i].color
  kPatternEntry,
  kPatternCoord,
  kColorChannel,
  // Pipeline scenes (SCENE.PIPELINE): root keys
  kViewport,
  kTransform,
  kDepth,
  kAttributes,
  kProvoking,
  // viewport
  kViewportX,
  kViewportY,
  kViewportWidth,
  kViewportHeight,
  kViewportMinDepth,
  kViewportMaxDepth,
  // transform
  kModel,
  kView,
  kProjection,
  kMatrixEntry,
  // depth
  kDepthFormat,
  kDepthFunc,
  kDepthWrite,
  kDepthClear,
  kDepthClip,
  kDepthBias,
  kDepthSlopeBias,
  kDepthBiasClamp,
  // attributes
  kAttribute,
  kAttributeName,
  kAttributeInterpolation,
  kAttributeLocation,
  // primitives[i]
  kZ,
  kW,
  kPos,
  kAttr,
  kListNumber,
  kPosVertex,
  kPosCoord,
  kAttrVertex,
  kAttrValue,
  // primitives[i] of type "path" (SCENE.PRIM.PATH)
  kPathData,
  kContours,
  kFillRule,
  kPathCoverage,
  kContourEntry,
  kCommandEntry,
  kCommandItem,
};

struct KeySpec {
  std::string_view name;
  Slot slot;
  bool required;
  bool pipeline = false; // the key makes the scene a pipeline scene (SCENE.PIPELINE)
};

constexpr std::array<KeySpec, 21> kRootKeys = {
    {{"version", Slot::kVersion, false},
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
     {"multisample_enable", Slot::kMultisampleEnable, false},
     {"quads", Slot::kQuads, false},
     {"derivatives", Slot::kDerivatives, false},
     {"clear_color", Slot::kClearColor, false},
     {"primitives", Slot::kPrimitives, true},
     {"viewport", Slot::kViewport, false, true},
     {"transform", Slot::kTransform, false, true},
     {"depth", Slot::kDepth, false, true},
     {"attributes", Slot::kAttributes, false, true},
     {"provoking_vertex", Slot::kProvoking, false, true}}};
constexpr std::array<KeySpec, 2> kTargetKeys = {
    {{"width", Slot::kWidth, true}, {"height", Slot::kHeight, true}}};
// "v" is required unless "pos" is given, or for a path "d" or "contours" (checked when the
// primitive ends).
constexpr std::array<KeySpec, 12> kPrimitiveKeys = {{{"type", Slot::kType, true},
                                                     {"v", Slot::kVertices, false},
                                                     {"aa", Slot::kAA, false},
                                                     {"color", Slot::kColor, false},
                                                     {"z", Slot::kZ, false, true},
                                                     {"w", Slot::kW, false, true},
                                                     {"pos", Slot::kPos, false, true},
                                                     {"attr", Slot::kAttr, false, true},
                                                     {"d", Slot::kPathData, false},
                                                     {"contours", Slot::kContours, false},
                                                     {"fill_rule", Slot::kFillRule, false},
                                                     {"coverage", Slot::kPathCoverage, false}}};
constexpr std::size_t kVKeyIndex = 1;
constexpr std::size_t kAAKeyIndex = 2;
constexpr std::size_t kZKeyIndex = 4;
constexpr std::size_t kWKeyIndex = 5;
constexpr std::size_t kPosKeyIndex = 6;
constexpr std::size_t kAttrKeyIndex = 7;
constexpr std::size_t kDKeyIndex = 8;
constexpr std::size_t kContoursKeyIndex = 9;
constexpr std::size_t kFillRuleKeyIndex = 10;
constexpr std::size_t kCoverageKeyIndex = 11;

// The pipeline objects (SCENE.PIPELINE). Every key is optional but an attribute's name.
constexpr std::array<KeySpec, 6> kViewportKeys = {{{"x", Slot::kViewportX, false},
                                                   {"y", Slot::kViewportY, false},
                                                   {"width", Slot::kViewportWidth, false},
                                                   {"height", Slot::kViewportHeight, false},
                                                   {"min_depth", Slot::kViewportMinDepth, false},
                                                   {"max_depth", Slot::kViewportMaxDepth, false}}};
constexpr std::array<KeySpec, 3> kTransformKeys = {{{"model", Slot::kModel, false},
                                                    {"view", Slot::kView, false},
                                                    {"projection", Slot::kProjection, false}}};
constexpr std::array<KeySpec, 8> kDepthKeys = {{{"format", Slot::kDepthFormat, false},
                                                {"func", Slot::kDepthFunc, false},
                                                {"write", Slot::kDepthWrite, false},
                                                {"clear", Slot::kDepthClear, false},
                                                {"clip", Slot::kDepthClip, false},
                                                {"bias", Slot::kDepthBias, false},
                                                {"slope_scaled_bias", Slot::kDepthSlopeBias, false},
                                                {"bias_clamp", Slot::kDepthBiasClamp, false}}};
constexpr std::array<KeySpec, 3> kAttributeKeys = {
    {{"name", Slot::kAttributeName, true},
     {"interpolation", Slot::kAttributeInterpolation, false},
     {"location", Slot::kAttributeLocation, false}}};

// The keys of each object; a context not listed is no object.
constexpr std::array<std::pair<Ctx, std::span<const KeySpec>>, 7> kObjectKeys = {
    {{Ctx::kRootObject, kRootKeys},
     {Ctx::kTargetObject, kTargetKeys},
     {Ctx::kPrimitiveObject, kPrimitiveKeys},
     {Ctx::kViewportObject, kViewportKeys},
     {Ctx::kTransformObject, kTransformKeys},
     {Ctx::kDepthObject, kDepthKeys},
     {Ctx::kAttributeObject, kAttributeKeys}}};

// The keys an object of `ctx` takes (empty when `ctx` is no object).
std::span<const KeySpec> object_keys(Ctx ctx) {
  for (const auto& [c, keys] : kObjectKeys) {
    if (c == ctx)
      return keys;
  }
  return {};
}

// The pipeline keys of one primitive, kept beside it only when it has any.
struct PipeExtras {
  std::vector<pipe::Vec4f> pos;
  std::vector<float> z, w;
  std::vector<std::vector<float>> attr;
};

// The multisampling words the reader accepts: "derivatives" has no "none" in a scene file.
constexpr std::array<std::pair<std::string_view, DerivativeMode>, 2> kDerivativeNames = {
    {Names<DerivativeMode>::table[1], Names<DerivativeMode>::table[2]}};

using Kind = JsonKind;
using Value = JsonValue;

std::string describe(const Value& v) {
  switch (v.kind) {
  case Kind::kNull:
    return "null";
  case Kind::kBool:
    return v.b ? "true" : "false";
  case Kind::kInt:
    return std::to_string(v.i);
  case Kind::kUint:
    return std::to_string(v.u);
  case Kind::kFloat:
    return printable(v.text);
  case Kind::kString:
    return "the string \"" + printable(v.text) + "\"";
  case Kind::kObject:
    return "an object";
  case Kind::kArray:
    return "an array";
  }
  return "a value";
}

struct Frame {
  Ctx ctx;
  std::string path;      // field path of this object or array
  unsigned seen = 0;     // objects: bit k set when key k was given
  std::size_t count = 0; // arrays: number of elements so far
  Slot key_slot = Slot::kRoot;
  std::string key_path; // objects: path of the value of the last key
};

// The SAX handler: validates the schema while the parser streams, so that memory stays
// proportional to the scene, and stops at the first error.
// rule: SCENE.FORMAT.V1, SCENE.INPUT.ERRORS
class SceneReader final : public JsonHandler {
public:
  bool key(std::string_view k) override {
    Frame& f = stack_.back();
    // An empty key is named "" so that the error still names a field (found by fuzz_scene_parser).
    const std::string name = k.empty() ? std::string("\"\"") : printable(k);
    const std::string field = f.path.empty() ? name : f.path + "." + name;
    const std::span<const KeySpec> keys = object_keys(f.ctx);
    if (keys.empty())
      return fail(f.path, "internal error: key outside an object");
    for (std::size_t n = 0; n < keys.size(); ++n) {
      if (keys[n].name != k)
        continue;
      if ((f.seen & (1u << n)) != 0)
        return fail(field, "duplicate key");
      f.seen |= 1u << n;
      f.key_slot = keys[n].slot;
      f.key_path = field;
      if (keys[n].pipeline && pipeline_key_.empty())
        pipeline_key_ = field;
      return true;
    }
    std::string expected;
    for (const KeySpec& s : keys)
      expected += (expected.empty() ? "" : ", ") + std::string(s.name);
    return fail(field, "unknown key (expected " + expected + ")");
  }

  bool end_object() override {
    const Frame f = std::move(stack_.back());
    stack_.pop_back();
    // Every object first checks its required keys (the pipeline objects have none).
    const std::span<const KeySpec> keys = object_keys(f.ctx);
    for (std::size_t n = 0; n < keys.size(); ++n) {
      if (keys[n].required && (f.seen & (1u << n)) == 0) {
        return fail(f.path.empty() ? std::string(keys[n].name)
                                   : f.path + "." + std::string(keys[n].name),
                    "is missing");
      }
    }
    switch (f.ctx) {
    case Ctx::kRootObject:
      return finish_pattern() && finish_pipeline();
    case Ctx::kTargetObject:
      return true;
    case Ctx::kPrimitiveObject: {
      const auto given = [&](std::size_t key) { return (f.seen & (1u << key)) != 0; };
      // rule: SCENE.PIPELINE
      const bool has_pos = given(kPosKeyIndex);
      // rule: SCENE.PRIM.PATH
      if (!finish_path(f.path, given(kVKeyIndex), given(kDKeyIndex), given(kContoursKeyIndex),
                       given(kFillRuleKeyIndex), given(kCoverageKeyIndex)))
        return false;
      const bool is_path = current_.type == PrimitiveType::kPath;
      if (!is_path && has_pos && given(kVKeyIndex)) {
        return fail(f.path + ".pos", "a primitive has either \"v\" (window space) or \"pos\" "
                                     "(positions before the transform), not both");
      }
      if (!is_path && !has_pos && !given(kVKeyIndex))
        return fail(f.path + ".v", "is missing");
      // rule: SCENE.PRIM.LINE
      // "aa" is a key of lines only, whatever its value (the type may come after it).
      if (given(kAAKeyIndex) && current_.type != PrimitiveType::kLine &&
          current_.type != PrimitiveType::kLineStrip) {
        return fail(f.path + ".aa", "only lines and line strips take \"aa\", not a " +
                                        std::string(to_string(current_.type)));
      }
      // Vertex counts, z and w with "v" only, and the per-vertex lists against the vertex count
      // and the declared attributes are rules of the scene, checked once, by the kernel
      // (prepare, run_pipeline): the reader checks syntax and types (SCENE.INPUT.ERRORS).
      const std::size_t index = scene_.primitives.size();
      scene_.primitives.push_back(std::move(current_));
      if (given(kZKeyIndex) || given(kWKeyIndex) || has_pos || given(kAttrKeyIndex)) {
        extras_of_.resize(index);
        extras_of_.push_back(std::move(extras_));
      }
      return true;
    }
    // rule: SCENE.PIPELINE
    case Ctx::kViewportObject:
      viewport_seen_ = f.seen;
      return true;
    case Ctx::kTransformObject:
    case Ctx::kDepthObject:
      return true;
    case Ctx::kAttributeObject: {
      for (std::size_t k = 0; k < pipe_.attributes.size(); ++k) {
        if (pipe_.attributes[k].name == attribute_.name) {
          return fail(f.path + ".name", "duplicate attribute name \"" + printable(attribute_.name) +
                                            "\" (also attributes[" + std::to_string(k) + "])");
        }
      }
      pipe_.attributes.push_back(std::move(attribute_));
      return true;
    }
    default:
      return fail(f.path, "internal error: unbalanced object");
    }
  }

  bool end_array() override {
    const Frame f = std::move(stack_.back());
    stack_.pop_back();
    if (f.ctx == Ctx::kCoordArray && f.count != 2) {
      return fail(f.path, "must have exactly 2 coordinates [x, y], got " + std::to_string(f.count));
    }
    // rule: SCENE.MSAA, MSAA.PATTERN.CUSTOM
    if (f.ctx == Ctx::kPatternArray && f.count == 0) {
      return fail(f.path,
                  "must have 1 to " + std::to_string(kMaxSamples) + " positions [i, j], got none");
    }
    if (f.ctx == Ctx::kPatternPair && f.count != 2) {
      return fail(f.path, "must have exactly 2 offsets [i, j], got " + std::to_string(f.count));
    }
    if (f.ctx == Ctx::kColorArray && f.count != 4) {
      return fail(f.path,
                  "must have exactly 4 channels [r, g, b, a], got " + std::to_string(f.count));
    }
    // rule: SCENE.PIPELINE
    if (f.ctx == Ctx::kMatrixArray && f.count != 16) {
      return fail(f.path, "must have exactly 16 numbers (a row-major 4x4 matrix), got " +
                              std::to_string(f.count));
    }
    // An empty per-vertex list would read as an absent key: refused as the empty array it is.
    if ((f.ctx == Ctx::kNumberList || f.ctx == Ctx::kPosArray || f.ctx == Ctx::kAttrArray) &&
        f.count == 0) {
      return fail(f.path, "must have one entry per vertex, got none");
    }
    // rule: SCENE.PRIM.PATH
    if (f.ctx == Ctx::kCommand)
      return finish_command(f.path, f.count);
    if (f.ctx == Ctx::kContour && f.count == 0)
      return fail(f.path, "must start with [\"M\", x, y], got an empty contour");
    if (f.ctx == Ctx::kPosCoords && f.count < 3) {
      return fail(f.path, "must have 3 or 4 coordinates [x, y, z] or [x, y, z, w], got " +
                              std::to_string(f.count));
    }
    return true;
  }

  bool syntax_error(const JsonSyntaxError& ex) override {
    if (error_)
      return false;
    if (ex.id == 406) {
      // A number beyond double's range ("1e400"): nlohmann stops here. Treat it as the
      // number it is (an infinity in float32) and report what that value means in place.
      if (!value(Value{Kind::kFloat, false, 0, 0, ex.last_token}))
        return false;
      return fail(last_path_,
                  "is " + std::string(to_string(
                              snap_to_subpixel(std::numeric_limits<float>::infinity()).status)));
    }
    std::string what = ex.what;
    const std::size_t close = what.find("] ");
    if (what.rfind("[json.exception.", 0) == 0 && close != std::string::npos) {
      what = what.substr(close + 2);
    }
    error_ = SceneError{"", printable(what, 300)};
    return false;
  }

  [[nodiscard]] std::variant<Scene, SceneError> result(bool ok) {
    if (error_)
      return *error_;
    if (!ok)
      return SceneError{"", "parse error: input ended early"};
    return std::move(scene_);
  }

private:
  bool fail(std::string field, std::string message) {
    if (!error_)
      error_ = SceneError{std::move(field), std::move(message)};
    return false;
  }

  bool type_error(const std::string& field, std::string_view expected, const Value& v) {
    return fail(field, "must be " + std::string(expected) + ", got " + describe(v));
  }

  // Dispatches one value (scalar, or the start of an object or array) to its slot.
  bool value(const Value& v) override {
    Slot slot = Slot::kRoot;
    std::string field = "scene";
    if (!stack_.empty()) {
      Frame& f = stack_.back();
      switch (f.ctx) {
      case Ctx::kRootObject:
      case Ctx::kTargetObject:
      case Ctx::kPrimitiveObject:
      case Ctx::kViewportObject:
      case Ctx::kTransformObject:
      case Ctx::kDepthObject:
      case Ctx::kAttributeObject:
        slot = f.key_slot;
        field = f.key_path;
        break;
      default: // an array: its next element
        // rule: SCENE.INPUT.LIMITS, MSAA.LIMITS, SCENE.PIPELINE
        if (f.count >= element_limit(f.ctx))
          return fail(f.path, overflow_message(f.ctx));
        slot = element_slot(f.ctx);
        coord_ = f.count;
        field = f.path + "[" + std::to_string(f.count++) + "]";
        break;
      }
    } else if (root_done_) {
      return fail("scene", "more than one JSON value");
    }
    last_path_ = field;
    if (const auto r = scene_value(slot, field, v))
      return *r;
    if (const auto r = sample_value(slot, field, v))
      return *r;
    if (const auto r = pipeline_value(slot, field, v))
      return *r;
    if (const auto r = primitive_pipeline_value(slot, field, v))
      return *r;
    if (const auto r = path_value(slot, field, v))
      return *r;
    return fail(field, "internal error: unknown slot");
  }

  // The root, the target, the raster state and the primitives' window-space keys. Returns nullopt
  // for a slot of another group.
  std::optional<bool> scene_value(Slot slot, const std::string& field, const Value& v) {
    switch (slot) {
    case Slot::kRoot:
      if (v.kind != Kind::kObject)
        return type_error("scene", "a JSON object", v);
      root_done_ = true;
      return push(Ctx::kRootObject, "");
    case Slot::kVersion:
      if (v.kind == Kind::kInt && v.i == 1)
        return true;
      return type_error(field, "the integer 1", v);
    case Slot::kTarget:
      if (v.kind != Kind::kObject)
        return type_error(field, "an object {\"width\", \"height\"}", v);
      return push(Ctx::kTargetObject, field);
    case Slot::kWidth:
      return size(field, v, scene_.width);
    case Slot::kHeight:
      return size(field, v, scene_.height);
    case Slot::kCull:
      return enumeration(field, v, Names<CullMode>::table, scene_.cull);
    case Slot::kFrontFace:
      return enumeration(field, v, Names<FrontFace>::table, scene_.conventions.front_face);
    case Slot::kFill:
      return enumeration(field, v, Names<FillConvention>::table, scene_.conventions.fill);
    case Slot::kLineMode:
      // rule: SCENE.LINE_MODE
      return enumeration(field, v, Names<LineMode>::table, scene_.conventions.line_mode);
    case Slot::kPrimitives:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array of primitives", v);
      return push(Ctx::kPrimitiveArray, field);
    case Slot::kPrimitive:
      if (v.kind != Kind::kObject)
        return type_error(field, "an object {\"type\", \"v\"}", v);
      current_ = Primitive{};
      current_.v.clear();
      extras_ = PipeExtras{};
      path_ = FloatPath{};
      d_text_.clear();
      return push(Ctx::kPrimitiveObject, field);
    case Slot::kType:
      if (v.kind != Kind::kString)
        return type_error(field, "a string", v);
      if (const auto t = from_name<PrimitiveType>(v.text)) {
        current_.type = *t;
        return true;
      }
      return fail(field, "unknown primitive type \"" + printable(v.text) +
                             "\" (expected \"triangle\", \"point\", \"line\", \"line_strip\" or "
                             "\"path\")");
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
      if (v.kind != Kind::kArray)
        return type_error(field, "an array [x, y]", v);
      current_.v.push_back(FloatPoint{0.0f, 0.0f});
      return push(Ctx::kCoordArray, field);
    case Slot::kCoord:
      return coordinate(field, v);
    default:
      return std::nullopt;
    }
  }

  // The multisampling keys (SCENE.MSAA) and the colours. Returns nullopt for a slot of another
  // group.
  std::optional<bool> sample_value(Slot slot, const std::string& field, const Value& v) {
    switch (slot) {
    // rule: SCENE.MSAA, MSAA.LIMITS
    case Slot::kSamples:
      if (v.kind == Kind::kInt && v.i >= 1 && v.i <= kMaxSamples) {
        samples_ = static_cast<std::uint32_t>(v.i);
        return true;
      }
      return type_error(field, "an integer in [1, " + std::to_string(kMaxSamples) + "]", v);
    case Slot::kSamplePattern:
      if (v.kind == Kind::kString && v.text == name_of(PatternKind::kStandard)) {
        pattern_kind_ = PatternKind::kStandard;
        return true;
      }
      if (v.kind == Kind::kString && v.text == name_of(PatternKind::kCenter)) {
        pattern_kind_ = PatternKind::kCenter;
        return true;
      }
      if (v.kind == Kind::kArray) {
        pattern_kind_ = PatternKind::kCustom;
        return push(Ctx::kPatternArray, field);
      }
      return type_error(field, "\"standard\", \"center\" or an array of [i, j] offsets", v);
    case Slot::kPatternEntry:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array [i, j]", v);
      custom_.push_back(SampleOffset{});
      return push(Ctx::kPatternPair, field);
    case Slot::kPatternCoord: {
      // rule: MSAA.PATTERN.GRID
      const bool on_grid = v.kind == Kind::kInt && v.i >= kSampleGridMin && v.i <= kSampleGridMax;
      if (!on_grid) {
        return type_error(field,
                          "an integer in [" + std::to_string(kSampleGridMin) + ", " +
                              std::to_string(kSampleGridMax) + "]",
                          v);
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
      return enumeration(field, v, Names<CentroidRule>::table, scene_.conventions.centroid);
    case Slot::kShading:
      return enumeration(field, v, Names<ShadingRate>::table, scene_.msaa.shading);
    case Slot::kMultisampleEnable:
      // rule: MSAA.LINE.MODE
      if (v.kind != Kind::kBool)
        return type_error(field, "true or false", v);
      scene_.conventions.multisample_enable = v.b;
      return true;
    case Slot::kQuads:
      if (v.kind != Kind::kBool)
        return type_error(field, "true or false", v);
      scene_.msaa.quads = v.b;
      return true;
    case Slot::kDerivatives:
      return enumeration(field, v, kDerivativeNames, scene_.msaa.derivatives);
    case Slot::kClearColor:
    case Slot::kColor:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array [r, g, b, a]", v);
      color_ = slot == Slot::kClearColor ? &scene_.clear_color : &current_.color;
      return push(Ctx::kColorArray, field);
    case Slot::kColorChannel:
      if (v.kind == Kind::kInt && v.i >= 0 && v.i <= 255) {
        (*color_)[coord_] = static_cast<std::uint8_t>(v.i);
        return true;
      }
      return type_error(field, "an integer in [0, 255]", v);
    default:
      return std::nullopt;
    }
  }

  // The pipeline keys of the scene (SCENE.PIPELINE): viewport, transform, depth, attributes,
  // provoking vertex. Returns nullopt for a slot of another group.
  std::optional<bool> pipeline_value(Slot slot, const std::string& field, const Value& v) {
    switch (slot) {
    // rule: SCENE.PIPELINE
    case Slot::kViewport:
      if (v.kind != Kind::kObject) {
        return type_error(
            field, "an object {\"x\", \"y\", \"width\", \"height\", \"min_depth\", \"max_depth\"}",
            v);
      }
      pipe_.viewport.emplace();
      return push(Ctx::kViewportObject, field);
    case Slot::kViewportX:
      return finite_number(field, v, pipe_.viewport->x);
    case Slot::kViewportY:
      return finite_number(field, v, pipe_.viewport->y);
    case Slot::kViewportWidth:
      return finite_number(field, v, pipe_.viewport->width);
    case Slot::kViewportHeight:
      return finite_number(field, v, pipe_.viewport->height);
    case Slot::kViewportMinDepth:
      return finite_number(field, v, pipe_.viewport->min_depth);
    case Slot::kViewportMaxDepth:
      return finite_number(field, v, pipe_.viewport->max_depth);
    case Slot::kTransform:
      if (v.kind != Kind::kObject) {
        return type_error(field, "an object {\"model\", \"view\", \"projection\"}", v);
      }
      return push(Ctx::kTransformObject, field);
    case Slot::kModel:
    case Slot::kView:
    case Slot::kProjection: {
      if (v.kind != Kind::kArray) {
        return type_error(field, "an array of 16 numbers (a row-major 4x4 matrix)", v);
      }
      std::optional<pipe::Mat4f>& m = slot == Slot::kModel  ? pipe_.model
                                      : slot == Slot::kView ? pipe_.view
                                                            : pipe_.projection;
      matrix_ = &m.emplace();
      return push(Ctx::kMatrixArray, field);
    }
    case Slot::kMatrixEntry:
      return finite_number(field, v, (*matrix_)[coord_]);
    case Slot::kDepth:
      if (v.kind != Kind::kObject)
        return type_error(field, "an object", v);
      pipe_.depth.emplace();
      return push(Ctx::kDepthObject, field);
    case Slot::kDepthFormat:
      return enumeration(field, v, Names<pipe::DepthFormat>::table, pipe_.conventions.depth);
    case Slot::kDepthFunc:
      return enumeration(field, v, Names<pipe::CompareFunc>::table, pipe_.depth->func);
    case Slot::kDepthWrite:
    case Slot::kDepthClip:
      if (v.kind != Kind::kBool)
        return type_error(field, "true or false", v);
      (slot == Slot::kDepthWrite ? pipe_.depth->write : pipe_.depth->clip) = v.b;
      return true;
    case Slot::kDepthClear:
      // rule: PIPE.DEPTH.FORMAT
      if (!finite_number(field, v, pipe_.depth->clear))
        return false;
      if (pipe_.depth->clear >= 0.0f && pipe_.depth->clear <= 1.0f)
        return true;
      return type_error(field, "a number in [0, 1]", v);
    case Slot::kDepthBias:
      if (v.kind == Kind::kInt && v.i >= std::numeric_limits<std::int32_t>::min() &&
          v.i <= std::numeric_limits<std::int32_t>::max()) {
        pipe_.depth->bias.bias = static_cast<std::int32_t>(v.i);
        return true;
      }
      return type_error(field, "an integer in [-2147483648, 2147483647]", v);
    case Slot::kDepthSlopeBias:
      return finite_number(field, v, pipe_.depth->bias.slope_scaled);
    case Slot::kDepthBiasClamp:
      return finite_number(field, v, pipe_.depth->bias.clamp);
    case Slot::kAttributes:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array of attributes", v);
      return push(Ctx::kAttributesArray, field);
    case Slot::kAttribute:
      if (v.kind != Kind::kObject) {
        return type_error(field, "an object {\"name\", \"interpolation\", \"location\"}", v);
      }
      attribute_ = pipe::AttributeDecl{};
      return push(Ctx::kAttributeObject, field);
    case Slot::kAttributeName:
      if (v.kind != Kind::kString || v.text.empty())
        return type_error(field, "a non-empty string", v);
      attribute_.name = std::string(v.text);
      return true;
    case Slot::kAttributeInterpolation:
      return enumeration(field, v, Names<pipe::Interpolation>::table, attribute_.interpolation);
    case Slot::kAttributeLocation:
      return enumeration(field, v, Names<pipe::Location>::table, attribute_.location);
    case Slot::kProvoking:
      return enumeration(field, v, Names<pipe::Provoking>::table, pipe_.conventions.provoking);
    default:
      return std::nullopt;
    }
  }

  // The pipeline keys of a primitive (SCENE.PIPELINE): z, w, pos and attr. Returns nullopt for
  // a slot of another group.
  std::optional<bool> primitive_pipeline_value(Slot slot, const std::string& field,
                                               const Value& v) {
    switch (slot) {
    case Slot::kZ:
    case Slot::kW:
      if (v.kind != Kind::kArray) {
        return type_error(field,
                          slot == Slot::kZ ? "an array of one depth per vertex"
                                           : "an array of one positive w per vertex",
                          v);
      }
      list_is_w_ = slot == Slot::kW;
      return push(Ctx::kNumberList, field);
    case Slot::kListNumber: {
      float x = 0.0f;
      if (!finite_number(field, v, x))
        return false;
      // rule: PIPE.INPUT.POSITION
      if (list_is_w_ && !(x > 0.0f))
        return type_error(field, "a positive number (a clip w)", v);
      (list_is_w_ ? extras_.w : extras_.z).push_back(x);
      return true;
    }
    case Slot::kPos:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array of positions [x, y, z(, w)]", v);
      return push(Ctx::kPosArray, field);
    case Slot::kPosVertex:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array [x, y, z] or [x, y, z, w]", v);
      extras_.pos.push_back(pipe::Vec4f{0.0f, 0.0f, 0.0f, 1.0f});
      return push(Ctx::kPosCoords, field);
    case Slot::kPosCoord:
      return finite_number(field, v, extras_.pos.back()[coord_]);
    case Slot::kAttr:
      if (v.kind != Kind::kArray) {
        return type_error(field, "an array of one list of attribute values per vertex", v);
      }
      return push(Ctx::kAttrArray, field);
    case Slot::kAttrVertex:
      if (v.kind != Kind::kArray) {
        return type_error(field, "an array of one number per declared attribute", v);
      }
      extras_.attr.emplace_back();
      return push(Ctx::kAttrValues, field);
    case Slot::kAttrValue: {
      float x = 0.0f;
      if (!finite_number(field, v, x))
        return false;
      extras_.attr.back().push_back(x);
      return true;
    }
    default:
      return std::nullopt;
    }
  }

  // The keys of a path primitive (SCENE.PRIM.PATH): "d", "contours" and its commands,
  // "fill_rule", "coverage". Returns nullopt for a slot of another group.
  std::optional<bool> path_value(Slot slot, const std::string& field, const Value& v) {
    switch (slot) {
    case Slot::kPathData:
      if (v.kind != Kind::kString)
        return type_error(field, "a string of SVG path data", v);
      d_text_ = std::string(v.text);
      return true;
    case Slot::kFillRule:
      return enumeration(field, v, Names<path::FillRule>::table, path_.fill_rule);
    case Slot::kPathCoverage:
      return enumeration(field, v, Names<path::Coverage>::table, path_.coverage);
    case Slot::kContours:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array of contours", v);
      return push(Ctx::kContourList, field);
    case Slot::kContourEntry:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array of commands [\"M\", x, y], [\"L\", x, y], ...", v);
      path_.contours.emplace_back();
      return push(Ctx::kContour, field);
    case Slot::kCommandEntry:
      if (v.kind != Kind::kArray)
        return type_error(field, "an array [\"M\" | \"L\" | \"Q\" | \"C\", x, y, ...]", v);
      command_index_ = coord_;
      command_op_ = '\0';
      return push(Ctx::kCommand, field);
    case Slot::kCommandItem:
      if (coord_ == 0) {
        static constexpr std::string_view kOps = "MLQC";
        if (v.kind != Kind::kString || v.text.size() != 1 ||
            kOps.find(v.text[0]) == std::string_view::npos)
          return type_error(field, "one of \"M\", \"L\", \"Q\", \"C\"", v);
        command_op_ = v.text[0];
        if (command_index_ == 0 && command_op_ != 'M')
          return fail(field, "a contour starts with \"M\", got \"" + std::string(v.text) + "\"");
        if (command_index_ != 0 && command_op_ == 'M') {
          return fail(field, "\"M\" only starts a contour (a new contour is a new array in "
                             "\"contours\")");
        }
        return true;
      } else {
        const std::optional<float> f =
            float32_value(field, v, "a number, \"NaN\", \"Infinity\" or \"-Infinity\"");
        if (!f)
          return false;
        command_values_[coord_ - 1] = *f;
        return true;
      }
    default:
      return std::nullopt;
    }
  }

  // Returns the number of coordinates a command takes: 2 for "M" and "L", 4 for "Q", 6 for "C".
  static std::size_t command_arity(char op) { return op == 'Q' ? 4 : op == 'C' ? 6 : 2; }

  // One command read ([op, numbers...] complete): the contour's start or a segment.
  // rule: SCENE.PRIM.PATH
  bool finish_command(const std::string& at, std::size_t count) {
    if (count == 0)
      return fail(at, "must be [\"M\" | \"L\" | \"Q\" | \"C\", x, y, ...], got an empty array");
    const std::size_t need = command_arity(command_op_);
    if (count - 1 != need) {
      return fail(at, "\"" + std::string(1, command_op_) + "\" takes " + std::to_string(need) +
                          " numbers, got " + std::to_string(count - 1));
    }
    FloatContour& c = path_.contours.back();
    const auto pt = [&](std::size_t k) {
      return FloatPoint{command_values_[2 * k], command_values_[2 * k + 1]};
    };
    if (command_op_ == 'M') {
      c.start = pt(0);
      return true;
    }
    FloatPathSegment seg;
    seg.kind = command_op_ == 'L'   ? path::SegmentKind::kLine
               : command_op_ == 'Q' ? path::SegmentKind::kQuadratic
                                    : path::SegmentKind::kCubic;
    for (std::size_t k = 0; k < need / 2; ++k)
      seg.p[k] = pt(k);
    c.segments.push_back(seg);
    return true;
  }

  // The keys of a path once its primitive ends (the type may come after them): a path has "d"
  // or "contours" and no "v"; other primitives have none of the path keys. "d" is read here
  // into contours (SCENE.PATH.DATA), each point's character offset kept for messages.
  // rule: SCENE.PRIM.PATH, SCENE.PATH.DATA
  bool finish_path(const std::string& at, bool v_given, bool d_given, bool contours_given,
                   bool fill_rule_given, bool coverage_given) {
    if (current_.type != PrimitiveType::kPath) {
      const char* key = d_given           ? "d"
                        : contours_given  ? "contours"
                        : fill_rule_given ? "fill_rule"
                        : coverage_given  ? "coverage"
                                          : nullptr;
      if (key == nullptr)
        return true;
      return fail(at + "." + key, "only a path takes \"" + std::string(key) + "\", not a " +
                                      std::string(to_string(current_.type)));
    }
    if (v_given) {
      return fail(at + ".v", "a path takes no \"v\" (its points are in \"d\" or \"contours\")");
    }
    if (d_given && contours_given) {
      return fail(at + ".contours",
                  "a path has either \"d\" (SVG path data) or \"contours\", not both");
    }
    if (!d_given && !contours_given)
      return fail(at + ".d", "is missing: a path needs \"d\" (SVG path data) or \"contours\"");
    if (d_given) {
      auto read = parse_svg_path(d_text_, kMaxPathSegments);
      if (const auto* bad = std::get_if<SvgPathError>(&read))
        return fail(at + ".d", bad->what());
      for (const SvgContour& sc : std::get<std::vector<SvgContour>>(read)) {
        FloatContour c;
        c.start = FloatPoint{sc.start.x, sc.start.y};
        path_.d_offsets.push_back(sc.start.at);
        for (const SvgSegment& ss : sc.segments) {
          FloatPathSegment seg;
          seg.kind = ss.kind == SvgSegmentKind::kLine        ? path::SegmentKind::kLine
                     : ss.kind == SvgSegmentKind::kQuadratic ? path::SegmentKind::kQuadratic
                                                             : path::SegmentKind::kCubic;
          for (std::size_t k = 0; k < path::point_count(seg.kind); ++k) {
            seg.p[k] = FloatPoint{ss.p[k].x, ss.p[k].y};
            path_.d_offsets.push_back(ss.p[k].at);
          }
          c.segments.push_back(seg);
        }
        path_.contours.push_back(std::move(c));
      }
    }
    current_.path = std::move(path_);
    return true;
  }

  // The most elements an array of this context holds; one more is an error (overflow_message).
  // rule: SCENE.INPUT.LIMITS
  std::size_t element_limit(Ctx ctx) const {
    switch (ctx) {
    case Ctx::kPrimitiveArray:
      return kMaxScenePrimitives;
    case Ctx::kVertexArray: // "v", and "z", "w", "pos" and "attr": one entry per vertex
    case Ctx::kNumberList:
    case Ctx::kPosArray:
    case Ctx::kAttrArray:
      return kMaxStripVertices;
    case Ctx::kCoordArray:
    case Ctx::kPatternPair:
      return 2;
    case Ctx::kColorArray:
    case Ctx::kPosCoords:
      return 4;
    case Ctx::kPatternArray:
      return kMaxSamples;
    case Ctx::kMatrixArray:
      return 16;
    case Ctx::kAttributesArray:
      return pipe::kMaxAttributes;
    case Ctx::kAttrValues:
      return pipe::kMaxAttributes;
    case Ctx::kContourList:
      return kMaxPathSegments;
    case Ctx::kContour:
      return kMaxPathSegments + 1;
    case Ctx::kCommand:
      return 7;
    default:
      return 0;
    }
  }

  std::string overflow_message(Ctx ctx) const {
    switch (ctx) {
    case Ctx::kPrimitiveArray:
      return "more than " + std::to_string(kMaxScenePrimitives) +
             " primitives (limit SCENE.INPUT.LIMITS)";
    case Ctx::kVertexArray:
    case Ctx::kNumberList:
    case Ctx::kPosArray:
    case Ctx::kAttrArray:
      return "more than " + std::to_string(kMaxStripVertices) +
             " vertices in one primitive (limit SCENE.INPUT.LIMITS)";
    case Ctx::kCoordArray:
      return "must have exactly 2 coordinates [x, y], got more";
    case Ctx::kPatternPair:
      return "must have exactly 2 offsets [i, j], got more";
    case Ctx::kColorArray:
      return "must have exactly 4 channels [r, g, b, a], got more";
    case Ctx::kPosCoords:
      return "must have 3 or 4 coordinates [x, y, z] or [x, y, z, w], got more";
    case Ctx::kPatternArray:
      return "must have 1 to " + std::to_string(kMaxSamples) + " positions [i, j], got more";
    case Ctx::kMatrixArray:
      return "must have exactly 16 numbers (a row-major 4x4 matrix), got more";
    case Ctx::kAttributesArray:
      return "must have at most " + std::to_string(pipe::kMaxAttributes) +
             " attributes (PIPE.INPUT.ATTRIBUTES), got more";
    case Ctx::kAttrValues:
      return "must have one value per declared attribute (at most " +
             std::to_string(pipe::kMaxAttributes) + "), got more";
    case Ctx::kContourList:
      return "more than " + std::to_string(kMaxPathSegments) +
             " contours in one path (limit SCENE.INPUT.LIMITS)";
    case Ctx::kContour:
      return "more than " + std::to_string(kMaxPathSegments) +
             " segments in one contour (limit SCENE.INPUT.LIMITS)";
    case Ctx::kCommand:
      return "must be [\"M\" | \"L\" | \"Q\" | \"C\", x, y, ...] with at most 6 numbers, got more";
    default:
      return "internal error: not an array";
    }
  }

  static Slot element_slot(Ctx ctx) {
    switch (ctx) {
    case Ctx::kPrimitiveArray:
      return Slot::kPrimitive;
    case Ctx::kVertexArray:
      return Slot::kVertex;
    case Ctx::kCoordArray:
      return Slot::kCoord;
    case Ctx::kPatternArray:
      return Slot::kPatternEntry;
    case Ctx::kPatternPair:
      return Slot::kPatternCoord;
    case Ctx::kColorArray:
      return Slot::kColorChannel;
    case Ctx::kMatrixArray:
      return Slot::kMatrixEntry;
    case Ctx::kAttributesArray:
      return Slot::kAttribute;
    case Ctx::kNumberList:
      return Slot::kListNumber;
    case Ctx::kPosArray:
      return Slot::kPosVertex;
    case Ctx::kPosCoords:
      return Slot::kPosCoord;
    case Ctx::kAttrArray:
      return Slot::kAttrVertex;
    case Ctx::kAttrValues:
      return Slot::kAttrValue;
    case Ctx::kContourList:
      return Slot::kContourEntry;
    case Ctx::kContour:
      return Slot::kCommandEntry;
    case Ctx::kCommand:
      return Slot::kCommandItem;
    default:
      return Slot::kRoot;
    }
  }

  // rule: SCENE.PIPELINE, PIPE.INPUT.ATTRIBUTES
  // A number read as float32 like a coordinate (SCENE.NUMBER.FLOAT32) that must be finite: the
  // strings "NaN", "Infinity" and "-Infinity" and numbers beyond float32 are named as such.
  bool finite_number(const std::string& field, const Value& v, float& out) {
    const std::optional<float> f = float32_value(field, v, "a number");
    if (!f)
      return false;
    if (std::isnan(*f))
      return fail(field, "is NaN");
    if (std::isinf(*f)) {
      return fail(field, v.kind == Kind::kString
                             ? std::string("is infinite")
                             : "is infinite (beyond float32: " + printable(v.text) + ")");
    }
    out = *f;
    return true;
  }

  // rule: SCENE.PIPELINE
  // Once the root object is complete: the viewport's defaults (the target may come after it)
  // and the pipeline scene itself.
  bool finish_pipeline() {
    if (pipeline_key_.empty())
      return true;
    if (pipe_.viewport) {
      pipe::Viewport& vp = *pipe_.viewport;
      // Missing keys take the default viewport's values: the whole target, depth [0, 1].
      const pipe::Viewport whole{
          0.0f, 0.0f, static_cast<float>(scene_.width), static_cast<float>(scene_.height),
          0.0f, 1.0f};
      float* fields[] = {&vp.x, &vp.y, &vp.width, &vp.height, &vp.min_depth, &vp.max_depth};
      const float defaults[] = {whole.x,      whole.y,         whole.width,
                                whole.height, whole.min_depth, whole.max_depth};
      for (std::size_t k = 0; k < 6; ++k) {
        if ((viewport_seen_ & (1u << k)) == 0)
          *fields[k] = defaults[k];
      }
    }
    extras_of_.resize(scene_.primitives.size());
    for (std::size_t p = 0; p < scene_.primitives.size(); ++p) {
      Primitive& prim = scene_.primitives[p];
      PipeExtras& e = extras_of_[p];
      if (!e.pos.empty())
        prim.v.clear();
      prim.pos = std::move(e.pos);
      prim.z = std::move(e.z);
      prim.w = std::move(e.w);
      prim.attr = std::move(e.attr);
    }
    extras_of_.clear();
    scene_.viewport = pipe_.viewport;
    scene_.model = pipe_.model;
    scene_.view = pipe_.view;
    scene_.projection = pipe_.projection;
    scene_.depth = pipe_.depth;
    scene_.attributes = std::move(pipe_.attributes);
    scene_.conventions.provoking = pipe_.conventions.provoking;
    scene_.conventions.depth = pipe_.conventions.depth;
    return true;
  }

  // Builds the sample pattern from "samples" and "sample_pattern", which may come in either
  // order, once the root object is complete.
  // rule: SCENE.MSAA, MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM
  bool finish_pattern() {
    if (pattern_kind_ == PatternKind::kCustom) {
      if (samples_ && *samples_ != custom_.size()) {
        return fail("samples", std::to_string(*samples_) + " does not match the " +
                                   std::to_string(custom_.size()) + " positions of sample_pattern");
      }
      scene_.msaa.pattern = custom_pattern(std::move(custom_));
      scene_.conventions.pattern = PatternKind::kCustom;
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
    scene_.conventions.pattern = scene_.msaa.pattern.kind;
    return check_explicit_all_ones_mask();
  }

  // In memory, 0xFFFFFFFF is the default "all samples" and prepare() accepts it whatever the
  // count; in a file the key holds at most the pattern's bits (MSAA.LIMITS), so the all-ones
  // value written out is refused here, with prepare()'s message for any wider mask.
  // rule: MSAA.LIMITS
  bool check_explicit_all_ones_mask() {
    const std::uint32_t n = scene_.msaa.pattern.count();
    if (!sample_mask_given_ || scene_.msaa.sample_mask != 0xFFFFFFFFu || n >= 32)
      return true;
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
    if (v.kind != Kind::kString)
      return type_error(field, expected, v);
    for (const auto& [name, e] : names) {
      if (v.text == name) {
        out = e;
        return true;
      }
    }
    return type_error(field, expected, v);
  }

  // rule: SCENE.NUMBER.FLOAT32
  // Returns the JSON number as the nearest float32, converted once from its text (integers
  // rounded once); the strings "NaN", "Infinity" and "-Infinity" give those values. Anything
  // else fails (expected says what is allowed) and returns nullopt.
  std::optional<float> float32_value(const std::string& field, const Value& v,
                                     std::string_view expected) {
    if (const std::optional<float> f = json_float32(v))
      return f;
    if (v.kind == Kind::kFloat)
      fail(field, "is not a number: " + printable(v.text));
    else
      type_error(field, expected, v);
    return std::nullopt;
  }

  // rule: SCENE.NUMBER.FLOAT32
  bool coordinate(const std::string& field, const Value& v) {
    const std::optional<float> f =
        float32_value(field, v, "a number, \"NaN\", \"Infinity\" or \"-Infinity\"");
    if (!f)
      return false;
    current_.v.back()[coord_] = *f;
    return true;
  }

  std::vector<Frame> stack_;
  Scene scene_;
  Primitive current_;
  std::size_t coord_ = 0;
  std::optional<std::uint32_t> samples_; // "samples", when given
  PatternKind pattern_kind_ = PatternKind::kStandard;
  std::vector<SampleOffset> custom_; // the positions of a custom "sample_pattern"
  Rgba8* color_ = nullptr;           // the colour being read
  bool sample_mask_given_ = false;
  // Pipeline scenes (SCENE.PIPELINE).
  std::string pipeline_key_;          // the first pipeline key read; empty: a plain scene
  Scene pipe_;                        // its root keys, moved into scene_ at the end
  unsigned viewport_seen_ = 0;        // the viewport keys given (kViewportKeys order)
  pipe::Mat4f* matrix_ = nullptr;     // the matrix being read
  pipe::AttributeDecl attribute_;     // the attribute being read
  bool list_is_w_ = false;            // the number list being read is "w" (else "z")
  PipeExtras extras_;                 // the current primitive's pipeline keys
  std::vector<PipeExtras> extras_of_; // per primitive, up to the last one that has any
  // Path primitives (SCENE.PRIM.PATH).
  FloatPath path_;                        // the current primitive's path keys
  std::string d_text_;                    // its "d", read when the primitive ends
  std::size_t command_index_ = 0;         // the command being read: its index in its contour
  char command_op_ = '\0';                // and its letter
  std::array<float, 6> command_values_{}; // and its numbers
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

} // namespace

std::string_view line_mode_name(LineMode m) {
  return name_of(m);
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
  if (text.empty() || !(text[0] == '-' || (text[0] >= '0' && text[0] <= '9')))
    return std::nullopt;
  float f = 0.0f;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  // std::from_chars is correctly rounded (round to nearest, ties to even) from the text.
  const std::from_chars_result r = std::from_chars(first, last, f, std::chars_format::general);
  if (r.ptr != last)
    return std::nullopt;
  if (r.ec == std::errc::result_out_of_range) {
    const bool negative = text[0] == '-';
    if (magnitude_at_least_one(text)) {
      return negative ? -std::numeric_limits<float>::infinity()
                      : std::numeric_limits<float>::infinity();
    }
    return negative ? -0.0f : 0.0f;
  }
  if (r.ec != std::errc{})
    return std::nullopt;
  return f;
}

std::string format_float(float v) {
  if (std::isnan(v))
    return "NaN";
  if (std::isinf(v))
    return v > 0 ? "Infinity" : "-Infinity";
  // "-0" would read back as the integer 0, that is +0.0; "-0.0" is a float and keeps the sign.
  if (v == 0.0f && std::signbit(v))
    return "-0.0";
  std::array<char, 64> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

// rule: SCENE.INPUT.FAST_READER
std::variant<Scene, SceneError> read_scene(std::string_view json_text) {
  if (std::optional<Scene> fast = read_scene_fast(json_text))
    return std::move(*fast);
  return read_scene_general(json_text);
}

std::variant<Scene, SceneError> read_scene_general(std::string_view json_text) {
  if (auto nul = nul_byte_problem(json_text))
    return SceneError{"", std::move(*nul)};
  SceneReader reader;
  return reader.result(parse_json(json_text, reader).ok);
}

std::string_view interpolation_name(pipe::Interpolation i) {
  return name_of(i);
}
std::string_view location_name(pipe::Location l) {
  return name_of(l);
}
std::string_view depth_format_name(pipe::DepthFormat f) {
  return name_of(f);
}
std::string_view compare_func_name(pipe::CompareFunc f) {
  return name_of(f);
}
std::string_view provoking_name(pipe::Provoking p) {
  return name_of(p);
}

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\u00";
      out += kHex[c >> 4];
      out += kHex[c & 15u];
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
std::variant<std::string, SceneError> read_scene_file(const std::string& path) {
  const bool is_stdin = path == "-";
  const std::string name = is_stdin ? "<stdin>" : path;
  std::FILE* file = is_stdin ? stdin : std::fopen(path.c_str(), "rb");
  if (file == nullptr)
    return SceneError{name, std::string("cannot open: ") + std::strerror(errno)};
  std::string text;
  // A regular file's size is reserved at once (growing the string copied a 56 MB scene about
  // ten times, each copy to fresh pages); the loop below still stops after kMaxSceneBytes.
  struct stat st {};
  if (::fstat(::fileno(file), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
    text.reserve(static_cast<std::size_t>(
        std::min<std::uint64_t>(static_cast<std::uint64_t>(st.st_size), kMaxSceneBytes + 1)));
  std::array<char, 1 << 16> buf{};
  bool too_large = false;
  for (;;) {
    const std::size_t n = std::fread(buf.data(), 1, buf.size(), file);
    text.append(buf.data(), n);
    if (text.size() > kMaxSceneBytes) {
      too_large = true;
      break;
    }
    if (n < buf.size())
      break;
  }
  const bool failed = std::ferror(file) != 0;
  const int err = errno;
  if (!is_stdin)
    std::fclose(file);
  if (too_large) {
    return SceneError{name, "is larger than " + std::to_string(kMaxSceneBytes >> 20) +
                                " MiB, the largest scene file accepted (limit SCENE.INPUT.LIMITS)"};
  }
  if (failed)
    return SceneError{name, std::string("cannot read: ") + std::strerror(err)};
  return text;
}

SceneText::SceneText(SceneText&& other) noexcept
    : owned_(std::move(other.owned_)), map_(std::exchange(other.map_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}

SceneText& SceneText::operator=(SceneText&& other) noexcept {
  if (this != &other) {
    SceneText old(std::move(*this));
    owned_ = std::move(other.owned_);
    map_ = std::exchange(other.map_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

SceneText::~SceneText() {
  if (map_ != nullptr)
    ::munmap(const_cast<char*>(map_), size_);
}

// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
std::variant<SceneText, SceneError> open_scene_file(const std::string& path) {
  if (path != "-") {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      struct stat st {};
      const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
                           static_cast<std::uint64_t>(st.st_size) <= kMaxSceneBytes;
      void* map = regular ? ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ,
                                   MAP_PRIVATE | MAP_POPULATE, fd, 0)
                          : MAP_FAILED;
      ::close(fd);
      if (map != MAP_FAILED) {
        SceneText text;
        text.map_ = static_cast<const char*>(map);
        text.size_ = static_cast<std::size_t>(st.st_size);
        return text;
      }
    }
  }
  // Standard input, pipes, empty or oversized files, and every error (named by
  // read_scene_file).
  auto text = read_scene_file(path);
  if (auto* err = std::get_if<SceneError>(&text))
    return *err;
  return SceneText(std::get<std::string>(std::move(text)));
}

namespace {
// "[r, g, b, a]".
std::string color_text(const Rgba8& c) {
  return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
         ", " + std::to_string(c[3]) + "]";
}

// A float as the reader takes it back: NaN and infinities as quoted strings.
std::string float_text(float f) {
  const bool quoted = std::isnan(f) || std::isinf(f);
  return quoted ? "\"" + format_float(f) + "\"" : format_float(f);
}

// "[a, b, ...]" of n floats.
std::string floats_text(const float* f, std::size_t n) {
  std::string out = "[";
  for (std::size_t k = 0; k < n; ++k)
    out += (k == 0 ? "" : ", ") + float_text(f[k]);
  return out + "]";
}

// Every key of a plain scene before "primitives", from "{" on.
// rule: SCENE.FORMAT.V1
std::string scene_head(const Scene& scene) {
  std::string out;
  out += "{\n  \"version\": 1,\n";
  out += "  \"target\": {\"width\": " + std::to_string(scene.width) +
         ", \"height\": " + std::to_string(scene.height) + "},\n";
  const Conventions& c = scene.conventions;
  out += "  \"cull\": \"" + std::string(to_string(scene.cull)) + "\",\n";
  out += "  \"front_face\": \"" + std::string(to_string(c.front_face)) + "\",\n";
  out += "  \"fill\": \"" + std::string(to_string(c.fill)) + "\",\n";
  if (c.line_mode != LineMode::kD3DDiamond)
    out += "  \"line_mode\": \"" + std::string(line_mode_name(c.line_mode)) + "\",\n";
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
    if (ms.pattern.count() != 1)
      out += "  \"samples\": " + std::to_string(ms.pattern.count()) + ",\n";
    if (ms.pattern.kind == PatternKind::kCenter)
      out += "  \"sample_pattern\": \"center\",\n";
  }
  if (ms.sample_mask != MultisampleState{}.sample_mask) {
    out += "  \"sample_mask\": " + std::to_string(ms.sample_mask) + ",\n";
  }
  if (ms.has_centroid)
    out += "  \"centroid\": \"" + std::string(to_string(c.centroid)) + "\",\n";
  if (ms.shading != ShadingRate::kPixel)
    out += "  \"shading\": \"" + std::string(to_string(ms.shading)) + "\",\n";
  if (c.multisample_enable)
    out += "  \"multisample_enable\": true,\n";
  if (ms.quads)
    out += "  \"quads\": true,\n";
  if (ms.derivatives != DerivativeMode::kNone) {
    out += "  \"derivatives\": \"" + std::string(to_string(ms.derivatives)) + "\",\n";
  }
  if (scene.clear_color != Rgba8{0, 0, 0, 0})
    out += "  \"clear_color\": " + color_text(scene.clear_color) + ",\n";
  return out;
}

// The start of one primitive's object: type, aa and color (when not the default).
std::string primitive_head(const Primitive& prim) {
  std::string out = "    {\"type\": \"" + std::string(to_string(prim.type)) + "\", ";
  if (prim.aa)
    out += "\"aa\": true, ";
  if (prim.color != Primitive{}.color)
    out += "\"color\": " + color_text(prim.color) + ", ";
  return out;
}

// "\"v\": [[x, y], ...]".
std::string vertices_text(const std::vector<FloatPoint>& v) {
  std::string out = "\"v\": [";
  for (std::size_t i = 0; i < v.size(); ++i)
    out += (i == 0 ? "" : ", ") + floats_text(v[i].data(), 2);
  return out + "]";
}

// "\"fill_rule\": ..., \"coverage\": ..., \"contours\": [[[\"M\", x, y], [\"L\", x, y], ...],
// ...]": a path in the JSON contour form, whatever form it was read from (SCENE.PRIM.PATH).
std::string path_text(const FloatPath& path) {
  std::string out = "\"fill_rule\": \"" + std::string(to_string(path.fill_rule)) +
                    "\", \"coverage\": \"" + std::string(to_string(path.coverage)) +
                    "\", \"contours\": [";
  for (std::size_t c = 0; c < path.contours.size(); ++c) {
    const FloatContour& contour = path.contours[c];
    out += (c == 0 ? "[[\"M\", " : ", [[\"M\", ") + float_text(contour.start[0]) + ", " +
           float_text(contour.start[1]) + "]";
    for (const FloatPathSegment& seg : contour.segments) {
      static constexpr const char* kOps[] = {"L", "Q", "C"};
      out += ", [\"" + std::string(kOps[static_cast<int>(seg.kind)]) + "\"";
      for (std::size_t k = 0; k < path::point_count(seg.kind); ++k)
        out += ", " + float_text(seg.p[k][0]) + ", " + float_text(seg.p[k][1]);
      out += "]";
    }
    out += "]";
  }
  return out + "]";
}

// Whether two floats are the same value bit for bit, any NaN equal to any NaN.
bool same_float(float x, float y) {
  if (std::isnan(x) && std::isnan(y))
    return true;
  return std::bit_cast<std::uint32_t>(x) == std::bit_cast<std::uint32_t>(y);
}

bool same_floats(const float* a, const float* b, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    if (!same_float(a[k], b[k]))
      return false;
  }
  return true;
}

bool same_float_vector(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && same_floats(a.data(), b.data(), a.size());
}

// Whether two paths are the same, their points bit for bit (where "d" put them is no part of a
// path).
bool same_path(const std::optional<FloatPath>& a, const std::optional<FloatPath>& b) {
  if (a.has_value() != b.has_value())
    return false;
  if (!a)
    return true;
  if (a->fill_rule != b->fill_rule || a->coverage != b->coverage ||
      a->contours.size() != b->contours.size())
    return false;
  for (std::size_t c = 0; c < a->contours.size(); ++c) {
    const FloatContour& ca = a->contours[c];
    const FloatContour& cb = b->contours[c];
    if (!same_floats(ca.start.data(), cb.start.data(), 2) ||
        ca.segments.size() != cb.segments.size())
      return false;
    for (std::size_t k = 0; k < ca.segments.size(); ++k) {
      const FloatPathSegment& sa = ca.segments[k];
      const FloatPathSegment& sb = cb.segments[k];
      if (sa.kind != sb.kind)
        return false;
      for (std::size_t i = 0; i < path::point_count(sa.kind); ++i) {
        if (!same_floats(sa.p[i].data(), sb.p[i].data(), 2))
          return false;
      }
    }
  }
  return true;
}

bool same_primitive(const Primitive& pa, const Primitive& pb) {
  if (pa.type != pb.type || pa.aa != pb.aa || pa.color != pb.color || pa.v.size() != pb.v.size() ||
      !same_path(pa.path, pb.path)) {
    return false;
  }
  for (std::size_t i = 0; i < pa.v.size(); ++i) {
    if (!same_floats(pa.v[i].data(), pb.v[i].data(), 2))
      return false;
  }
  if (pa.pos.size() != pb.pos.size() || !same_float_vector(pa.z, pb.z) ||
      !same_float_vector(pa.w, pb.w) || pa.attr.size() != pb.attr.size()) {
    return false;
  }
  for (std::size_t i = 0; i < pa.pos.size(); ++i) {
    if (!same_floats(pa.pos[i].data(), pb.pos[i].data(), 4))
      return false;
  }
  for (std::size_t i = 0; i < pa.attr.size(); ++i) {
    if (!same_float_vector(pa.attr[i], pb.attr[i]))
      return false;
  }
  return true;
}

// Everything of two scenes but their primitives.
bool same_state(const Scene& a, const Scene& b) {
  const Conventions& ca = a.conventions;
  const Conventions& cb = b.conventions;
  if (a.width != b.width || a.height != b.height || a.cull != b.cull ||
      ca.front_face != cb.front_face || ca.fill != cb.fill || ca.line_mode != cb.line_mode ||
      ca.pattern != cb.pattern || ca.multisample_enable != cb.multisample_enable) {
    return false;
  }
  const MultisampleState& ma = a.msaa;
  const MultisampleState& mb = b.msaa;
  return ma.pattern == mb.pattern && ma.sample_mask == mb.sample_mask &&
         ma.has_centroid == mb.has_centroid && (!ma.has_centroid || ca.centroid == cb.centroid) &&
         ma.shading == mb.shading && ma.quads == mb.quads && ma.derivatives == mb.derivatives &&
         a.clear_color == b.clear_color;
}

bool same_matrix(const std::optional<pipe::Mat4f>& a, const std::optional<pipe::Mat4f>& b) {
  if (a.has_value() != b.has_value())
    return false;
  return !a || same_floats(a->data(), b->data(), 16);
}
} // namespace

// rule: SCENE.FORMAT.V1

// rule: SCENE.PIPELINE
std::string write_scene(const Scene& s) {
  std::string out = scene_head(s);
  const pipe::Provoking provoking = s.conventions.provoking;
  if (provoking != pipe::Provoking::kFirst)
    out += "  \"provoking_vertex\": \"" + std::string(provoking_name(provoking)) + "\",\n";
  if (s.viewport) {
    const pipe::Viewport& vp = *s.viewport;
    out += "  \"viewport\": {\"x\": " + float_text(vp.x) + ", \"y\": " + float_text(vp.y) +
           ", \"width\": " + float_text(vp.width) + ", \"height\": " + float_text(vp.height) +
           ", \"min_depth\": " + float_text(vp.min_depth) +
           ", \"max_depth\": " + float_text(vp.max_depth) + "},\n";
  }
  if (s.model || s.view || s.projection) {
    std::string matrices;
    for (const auto& [name, m] : {std::pair{"model", &s.model}, std::pair{"view", &s.view},
                                  std::pair{"projection", &s.projection}}) {
      if (!*m)
        continue;
      matrices += (matrices.empty() ? "\"" : ",\n                \"") + std::string(name) +
                  "\": " + floats_text((*m)->data(), 16);
    }
    out += "  \"transform\": {" + matrices + "},\n";
  }
  if (s.depth) {
    const pipe::DepthState& d = *s.depth;
    out += "  \"depth\": {\"format\": \"" + std::string(depth_format_name(s.conventions.depth)) +
           "\", \"func\": \"" + std::string(compare_func_name(d.func)) +
           "\", \"write\": " + (d.write ? "true" : "false") +
           ", \"clear\": " + float_text(d.clear) + ", \"clip\": " + (d.clip ? "true" : "false") +
           ", \"bias\": " + std::to_string(d.bias.bias) +
           ", \"slope_scaled_bias\": " + float_text(d.bias.slope_scaled) +
           ", \"bias_clamp\": " + float_text(d.bias.clamp) + "},\n";
  }
  if (!s.attributes.empty()) {
    out += "  \"attributes\": [";
    for (std::size_t k = 0; k < s.attributes.size(); ++k) {
      const pipe::AttributeDecl& a = s.attributes[k];
      out += (k == 0 ? "" : ", ") + std::string("{\"name\": ") + json_string(a.name) +
             ", \"interpolation\": \"" + std::string(interpolation_name(a.interpolation)) +
             "\", \"location\": \"" + std::string(location_name(a.location)) + "\"}";
    }
    out += "],\n";
  }
  out += "  \"primitives\": [";
  for (std::size_t p = 0; p < s.primitives.size(); ++p) {
    const Primitive& prim = s.primitives[p];
    out += p == 0 ? "\n" : ",\n";
    out += primitive_head(prim);
    if (prim.path) {
      out += path_text(*prim.path);
      if (!prim.v.empty())
        out += ", " + vertices_text(prim.v);
    } else if (!prim.pos.empty()) {
      out += "\"pos\": [";
      for (std::size_t i = 0; i < prim.pos.size(); ++i) {
        out += (i == 0 ? "" : ", ") + floats_text(prim.pos[i].data(), 4);
      }
      out += "]";
    } else {
      out += vertices_text(prim.v);
    }
    // Written as held, also beside "pos" (which the kernel's validator refuses): the text reads
    // back to the same scene whatever it holds.
    if (!prim.z.empty())
      out += ", \"z\": " + floats_text(prim.z.data(), prim.z.size());
    if (!prim.w.empty())
      out += ", \"w\": " + floats_text(prim.w.data(), prim.w.size());
    if (!prim.attr.empty()) {
      out += ", \"attr\": [";
      for (std::size_t i = 0; i < prim.attr.size(); ++i) {
        out += (i == 0 ? "" : ", ") + floats_text(prim.attr[i].data(), prim.attr[i].size());
      }
      out += "]";
    }
    out += "}";
  }
  out += s.primitives.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

bool same_scene(const Scene& a, const Scene& b) {
  if (!same_state(a, b) || a.conventions.provoking != b.conventions.provoking ||
      a.viewport.has_value() != b.viewport.has_value() || !same_matrix(a.model, b.model) ||
      !same_matrix(a.view, b.view) || !same_matrix(a.projection, b.projection) ||
      a.depth.has_value() != b.depth.has_value() || a.attributes.size() != b.attributes.size() ||
      a.primitives.size() != b.primitives.size()) {
    return false;
  }
  if (a.viewport) {
    const pipe::Viewport& va = *a.viewport;
    const pipe::Viewport& vb = *b.viewport;
    const float fa[] = {va.x, va.y, va.width, va.height, va.min_depth, va.max_depth};
    const float fb[] = {vb.x, vb.y, vb.width, vb.height, vb.min_depth, vb.max_depth};
    if (!same_floats(fa, fb, 6))
      return false;
  }
  if (a.depth) {
    const pipe::DepthState& da = *a.depth;
    const pipe::DepthState& db = *b.depth;
    if (a.conventions.depth != b.conventions.depth || da.func != db.func || da.write != db.write ||
        da.clip != db.clip || da.bias.bias != db.bias.bias || !same_float(da.clear, db.clear) ||
        !same_float(da.bias.slope_scaled, db.bias.slope_scaled) ||
        !same_float(da.bias.clamp, db.bias.clamp)) {
      return false;
    }
  }
  for (std::size_t k = 0; k < a.attributes.size(); ++k) {
    const pipe::AttributeDecl& x = a.attributes[k];
    const pipe::AttributeDecl& y = b.attributes[k];
    if (x.name != y.name || x.interpolation != y.interpolation || x.location != y.location)
      return false;
  }
  for (std::size_t p = 0; p < a.primitives.size(); ++p) {
    if (!same_primitive(a.primitives[p], b.primitives[p]))
      return false;
  }
  return true;
}

} // namespace rastrules::io
