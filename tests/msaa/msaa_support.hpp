// SPDX-License-Identifier: MIT
// Helpers for the multisampling examples: scenes in pixels with a multisample state, and the
// fragments of a render by pixel. Every helper goes through the kernel's public API.

#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <utility>
#include <variant>
#include <vector>

#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {

// Returns a width x height scene with the given multisample state and primitives.
inline Scene msaa_scene(std::int32_t width, std::int32_t height, MultisampleState ms,
                        std::vector<Primitive> prims) {
  Scene s;
  s.width = width;
  s.height = height;
  s.msaa = std::move(ms);
  s.conventions.pattern = s.msaa.pattern.kind;
  s.primitives = std::move(prims);
  return s;
}

// Returns a multisample state with this pattern and everything else at its default.
inline MultisampleState with_pattern(SamplePattern p) {
  MultisampleState ms;
  ms.pattern = std::move(p);
  return ms;
}

// Returns the fragments of a valid scene (a test failure if prepare() rejects it).
inline std::vector<Fragment> frags_of(const Scene& s) {
  auto r = render(s);
  if (const auto* e = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << "scene rejected: " << e->what();
    return {};
  }
  return std::get<std::vector<Fragment>>(r);
}

// Returns the error of a scene prepare() must reject (an empty error if it accepts it).
inline SceneError error_of(const Scene& s) {
  auto r = prepare(s);
  if (const auto* e = std::get_if<SceneError>(&r))
    return *e;
  ADD_FAILURE() << "scene accepted";
  return SceneError{};
}

// (x, y) -> mask of the non-helper fragments of primitive `prim` (pixel-frequency shading).
inline std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>
masks_of(const std::vector<Fragment>& frags, std::uint32_t prim = 0) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t> out;
  for (const Fragment& f : frags) {
    if (f.prim == prim && !f.helper)
      out[{f.x, f.y}] |= f.mask;
  }
  return out;
}

using MaskMap = std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>;

} // namespace rastrules::test
