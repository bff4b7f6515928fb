// SPDX-License-Identifier: MIT
// Shrinking a mismatch to a minimal scene: greedy, deterministic, each step kept only when the
// scene still differs.
// Implements: FUZZ.SHRINK

#include <algorithm>
#include <cmath>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {
namespace {

constexpr int kMaxRounds = 16;
constexpr int kMaxCoordinatePasses = 64;

using Pred = std::function<bool(const Scene&)>;

bool delete_primitives(Scene& s, const Pred& differs) {
  bool changed = false;
  for (std::size_t i = 0; i < s.primitives.size();) {
    Scene t = s;
    t.primitives.erase(t.primitives.begin() + static_cast<std::ptrdiff_t>(i));
    if (!t.primitives.empty() && differs(t)) {
      s = std::move(t);
      changed = true;
    } else {
      ++i;
    }
  }
  return changed;
}

bool delete_vertices(Scene& s, const Pred& differs) {
  bool changed = false;
  for (std::size_t p = 0; p < s.primitives.size(); ++p) {
    if (s.primitives[p].type != PrimitiveType::kLineStrip)
      continue;
    const auto count = [&] {
      return std::max(s.primitives[p].v.size(), s.primitives[p].pos.size());
    };
    for (std::size_t i = 0; i < count() && count() > 2;) {
      Scene t = s;
      // The vertex and its per-vertex pipeline inputs (SCENE.PIPELINE), where given.
      Primitive& tp = t.primitives[p];
      const auto at = static_cast<std::ptrdiff_t>(i);
      if (!tp.v.empty())
        tp.v.erase(tp.v.begin() + at);
      if (!tp.pos.empty())
        tp.pos.erase(tp.pos.begin() + at);
      if (!tp.z.empty())
        tp.z.erase(tp.z.begin() + at);
      if (!tp.w.empty())
        tp.w.erase(tp.w.begin() + at);
      if (!tp.attr.empty())
        tp.attr.erase(tp.attr.begin() + at);
      if (differs(t)) {
        s = std::move(t);
        changed = true;
      } else {
        ++i;
      }
    }
    if (count() == 2) {
      Scene t = s;
      t.primitives[p].type = PrimitiveType::kLine;
      if (differs(t)) {
        s = std::move(t);
        changed = true;
      }
    }
  }
  return changed;
}

// The simpler values tried for a coordinate, simplest first.
std::vector<float> candidates(float c) {
  const double v = c;
  std::vector<double> out = {0.0};
  if (std::fabs(v) >= 2)
    out.push_back(std::trunc(v / 2));
  out.push_back(std::trunc(v));
  out.push_back(std::floor(v + 0.5));
  // Fewer fraction bits: halves, quarters, ..., 1/128.
  for (int bits = 1; bits <= 7; ++bits) {
    const double scale = std::ldexp(1.0, bits);
    out.push_back(std::floor(v * scale + 0.5) / scale);
  }
  if (std::fabs(v) >= 1)
    out.push_back(v > 0 ? v - 1 : v + 1);
  std::vector<float> f;
  for (const double d : out) {
    const auto x = static_cast<float>(d);
    if (x != c && std::find(f.begin(), f.end(), x) == f.end())
      f.push_back(x);
  }
  return f;
}

bool simplify_coordinates(Scene& s, const Pred& differs) {
  bool changed = false;
  for (int pass = 0; pass < kMaxCoordinatePasses; ++pass) {
    bool any = false;
    for (std::size_t p = 0; p < s.primitives.size(); ++p) {
      for (std::size_t i = 0; i < s.primitives[p].v.size(); ++i) {
        for (std::size_t k = 0; k < 2; ++k) {
          for (const float c : candidates(s.primitives[p].v[i][k])) {
            Scene t = s;
            t.primitives[p].v[i][k] = c;
            if (differs(t)) {
              s = std::move(t);
              any = true;
              break;
            }
          }
        }
      }
    }
    if (!any)
      break;
    changed = true;
  }
  return changed;
}

bool fewer_samples(Scene& s, const Pred& differs) {
  if (s.msaa.count() == 1)
    return false;
  Scene t = s;
  t.msaa = MultisampleState{};
  if (!differs(t))
    return false;
  s = std::move(t);
  return true;
}

Scene translated(const Scene& s, float dx, float dy) {
  Scene t = s;
  for (Primitive& p : t.primitives) {
    for (FloatPoint& v : p.v) {
      v[0] -= dx;
      v[1] -= dy;
    }
  }
  return t;
}

bool toward_origin(Scene& s, const Pred& differs) {
  float min_x = INFINITY, min_y = INFINITY;
  for (const Primitive& p : s.primitives) {
    for (const FloatPoint& v : p.v) {
      min_x = std::min(min_x, v[0]);
      min_y = std::min(min_y, v[1]);
    }
  }
  const float dx = std::max(0.0f, std::floor(min_x)), dy = std::max(0.0f, std::floor(min_y));
  for (const auto& [tx, ty] : {std::pair{dx, dy}, std::pair{dx, 0.0f}, std::pair{0.0f, dy}}) {
    if (tx == 0 && ty == 0)
      continue;
    Scene t = translated(s, tx, ty);
    if (differs(t)) {
      s = std::move(t);
      return true;
    }
  }
  return false;
}

bool smaller_target(Scene& s, const Pred& differs) {
  bool changed = false;
  for (std::int32_t* side : {&s.width, &s.height}) {
    // Halve while it still differs, then step down by one.
    while (*side > 1) {
      Scene t = s;
      std::int32_t& ts = side == &s.width ? t.width : t.height;
      ts = *side / 2;
      if (!differs(t))
        break;
      s = std::move(t);
      changed = true;
    }
    for (int step = 0; step < 64 && *side > 1; ++step) {
      Scene t = s;
      std::int32_t& ts = side == &s.width ? t.width : t.height;
      ts = *side - 1;
      if (!differs(t))
        break;
      s = std::move(t);
      changed = true;
    }
  }
  return changed;
}

// Rotates each triangle's vertices to start at its first vertex in (y, x) order: the same
// triangle with the same winding, so equal findings get equal scenes.
bool canonical_order(Scene& s, const Pred& differs) {
  Scene t = s;
  bool moved = false;
  for (Primitive& p : t.primitives) {
    if (p.type != PrimitiveType::kTriangle || p.v.size() != 3)
      continue;
    const auto first =
        std::min_element(p.v.begin(), p.v.end(), [](const FloatPoint& a, const FloatPoint& b) {
          return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0];
        });
    if (first == p.v.begin())
      continue;
    std::rotate(p.v.begin(), first, p.v.end());
    moved = true;
  }
  if (!moved || !differs(t))
    return false;
  s = std::move(t);
  return true;
}

} // namespace

// rule: FUZZ.SHRINK
Scene shrink(const Scene& scene, const std::function<bool(const Scene&)>& still_differs) {
  Scene s = scene;
  for (int round = 0; round < kMaxRounds; ++round) {
    bool changed = delete_primitives(s, still_differs);
    changed = delete_vertices(s, still_differs) || changed;
    changed = fewer_samples(s, still_differs) || changed;
    changed = simplify_coordinates(s, still_differs) || changed;
    changed = toward_origin(s, still_differs) || changed;
    changed = smaller_target(s, still_differs) || changed;
    changed = canonical_order(s, still_differs) || changed;
    if (!changed)
      break;
  }
  return s;
}

} // namespace rastrules::fuzzer
