// SPDX-License-Identifier: MIT
// One spelling per enumerator of every convention a scene names: the word spec/scene.md uses
// for it. to_string() returns it, the scene reader accepts it and the writer writes it, the
// command line parses it and the driver adapters print it, all from the tables below, so that
// no two places can spell a value differently. The exact oracle keeps words of its own
// (independence); tests/names checks that they are these and that spec/scene.md uses them.
// Implements: SCENE.FORMAT.V1 (the enumeration words)
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "rastrules/isa.hpp"
#include "rastrules/line.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// Names<E>::table: every enumerator of E with its word, in the order error messages list them.
template <class E> struct Names;

template <std::size_t N, class E> using NameTable = std::array<std::pair<std::string_view, E>, N>;

template <> struct Names<PrimitiveType> {
  static constexpr NameTable<4, PrimitiveType> table{{{"triangle", PrimitiveType::kTriangle},
                                                      {"point", PrimitiveType::kPoint},
                                                      {"line", PrimitiveType::kLine},
                                                      {"line_strip", PrimitiveType::kLineStrip}}};
};
template <> struct Names<CullMode> {
  static constexpr NameTable<3, CullMode> table{
      {{"none", CullMode::kNone}, {"back", CullMode::kBack}, {"front", CullMode::kFront}}};
};
template <> struct Names<FrontFace> {
  static constexpr NameTable<2, FrontFace> table{
      {{"cw", FrontFace::kClockwise}, {"ccw", FrontFace::kCounterClockwise}}};
};
template <> struct Names<FillConvention> {
  static constexpr NameTable<4, FillConvention> table{
      {{"top-left", FillConvention::kTopLeft},
       {"top-right", FillConvention::kTopRight},
       {"bottom-left", FillConvention::kBottomLeft},
       {"bottom-right", FillConvention::kBottomRight}}};
};
template <> struct Names<LineMode> {
  static constexpr NameTable<4, LineMode> table{{{"d3d", LineMode::kD3DDiamond},
                                                 {"vulkan-bresenham", LineMode::kVulkanBresenham},
                                                 {"quad-wide", LineMode::kQuadWide},
                                                 {"quad-narrow", LineMode::kQuadNarrow}}};
};
template <> struct Names<PatternKind> {
  static constexpr NameTable<3, PatternKind> table{{{"standard", PatternKind::kStandard},
                                                    {"center", PatternKind::kCenter},
                                                    {"custom", PatternKind::kCustom}}};
};
template <> struct Names<CentroidRule> {
  static constexpr NameTable<2, CentroidRule> table{
      {{"d3d11", CentroidRule::kD3D11}, {"d3d10", CentroidRule::kD3D10}}};
};
template <> struct Names<ShadingRate> {
  static constexpr NameTable<2, ShadingRate> table{
      {{"pixel", ShadingRate::kPixel}, {"sample", ShadingRate::kSample}}};
};
template <> struct Names<DerivativeMode> {
  static constexpr NameTable<3, DerivativeMode> table{{{"none", DerivativeMode::kNone},
                                                       {"fine", DerivativeMode::kFine},
                                                       {"coarse", DerivativeMode::kCoarse}}};
};
template <> struct Names<Isa> {
  static constexpr NameTable<3, Isa> table{
      {{"scalar", Isa::kScalar}, {"avx2", Isa::kAvx2}, {"avx512", Isa::kAvx512}}};
};
template <> struct Names<Traversal> {
  static constexpr NameTable<2, Traversal> table{
      {{"plain", Traversal::kPlain}, {"fast", Traversal::kFast}}};
};
template <> struct Names<pipe::Interpolation> {
  static constexpr NameTable<3, pipe::Interpolation> table{
      {{"perspective", pipe::Interpolation::kPerspective},
       {"linear", pipe::Interpolation::kLinear},
       {"flat", pipe::Interpolation::kFlat}}};
};
template <> struct Names<pipe::Location> {
  static constexpr NameTable<3, pipe::Location> table{{{"center", pipe::Location::kCenter},
                                                       {"centroid", pipe::Location::kCentroid},
                                                       {"sample", pipe::Location::kSample}}};
};
template <> struct Names<pipe::DepthFormat> {
  static constexpr NameTable<3, pipe::DepthFormat> table{{{"d16", pipe::DepthFormat::kD16},
                                                          {"d24", pipe::DepthFormat::kD24},
                                                          {"d32f", pipe::DepthFormat::kD32F}}};
};
template <> struct Names<pipe::CompareFunc> {
  static constexpr NameTable<8, pipe::CompareFunc> table{
      {{"never", pipe::CompareFunc::kNever},
       {"less", pipe::CompareFunc::kLess},
       {"equal", pipe::CompareFunc::kEqual},
       {"less_equal", pipe::CompareFunc::kLessEqual},
       {"greater", pipe::CompareFunc::kGreater},
       {"not_equal", pipe::CompareFunc::kNotEqual},
       {"greater_equal", pipe::CompareFunc::kGreaterEqual},
       {"always", pipe::CompareFunc::kAlways}}};
};
template <> struct Names<pipe::Provoking> {
  static constexpr NameTable<2, pipe::Provoking> table{
      {{"first", pipe::Provoking::kFirst}, {"last", pipe::Provoking::kLast}}};
};

// Returns the word of e ("unknown" for a value outside the enumeration).
template <class E> [[nodiscard]] constexpr std::string_view name_of(E e) {
  for (const auto& [name, value] : Names<E>::table)
    if (value == e)
      return name;
  return "unknown";
}

// Returns the enumerator spelled `word`, or nothing.
template <class E> [[nodiscard]] constexpr std::optional<E> from_name(std::string_view word) {
  for (const auto& [name, value] : Names<E>::table)
    if (name == word)
      return value;
  return std::nullopt;
}

} // namespace rastrules
