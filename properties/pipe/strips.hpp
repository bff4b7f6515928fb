// SPDX-License-Identifier: MIT
// A pipeline scene with every line strip replaced by its independent lines, in order
// (LINE.STRIP.SEQUENCE): what each strip segment must equal. Kernel types only, so that the
// example tests (tests/pipe) and the properties share it.

#pragma once

#include <cstddef>
#include <type_traits>

#include "rastrules/pipeline.hpp"

namespace rastrules::pipe_gen {

// rule: LINE.STRIP.SEQUENCE
inline rastrules::Scene strips_as_lines(const rastrules::Scene& s) {
  rastrules::Scene out = s;
  out.primitives.clear();
  for (const rastrules::Primitive& p : s.primitives) {
    if (p.type != PrimitiveType::kLineStrip) {
      out.primitives.push_back(p);
      continue;
    }
    const std::size_t nv = p.pos.empty() ? p.v.size() : p.pos.size();
    for (std::size_t k = 0; k + 1 < nv; ++k) {
      rastrules::Primitive l = p;
      l.type = PrimitiveType::kLine;
      const auto pick = [k](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        return v.empty() ? V{} : V{v[k], v[k + 1]};
      };
      if (p.pos.empty()) // window space; in clip space base.v is unused (and may be the default)
        l.v = pick(p.v);
      l.pos = pick(p.pos);
      l.z = pick(p.z);
      l.w = pick(p.w);
      l.attr = pick(p.attr);
      out.primitives.push_back(l);
    }
  }
  return out;
}

} // namespace rastrules::pipe_gen
