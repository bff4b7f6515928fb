// SPDX-License-Identifier: MIT
// Kernel against oracle (check.hpp).
#include "rastrules/check/check.hpp"

#include "checker.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

#include "rastrules/msaa.hpp"
#include "rastrules/names.hpp"
#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/line_aa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/oracle/point.hpp"

namespace rastrules::check {

oracle::State oracle_state(const RasterState& state) {
  oracle::State o;
  o.cull = std::string(name_of(state.cull));
  o.front_face = std::string(name_of(state.front_face));
  o.fill = std::string(name_of(state.fill));
  return o;
}

std::array<std::int64_t, 2> oracle_raw(const FloatPoint& v) {
  const auto x = oracle::snap(v[0]);
  const auto y = oracle::snap(v[1]);
  if (!x || !y)
    throw std::invalid_argument("the oracle cannot snap a vertex the kernel accepted");
  return {*x, *y};
}

oracle::msaa::Input oracle_msaa_input(const Scene& scene) {
  oracle::msaa::Input in;
  in.width = scene.width;
  in.height = scene.height;
  in.state = oracle_state(raster_state(scene));
  in.line_mode = std::string(name_of(scene.conventions.line_mode));
  in.multisample_enable = scene.conventions.multisample_enable;
  in.pattern.clear();
  for (const SampleOffset& o : scene.msaa.pattern.positions)
    in.pattern.push_back({o.x, o.y});
  in.sample_mask = scene.msaa.sample_mask;
  if (scene.msaa.has_centroid)
    in.centroid = std::string(name_of(scene.conventions.centroid));
  in.shading = std::string(name_of(scene.msaa.shading));
  in.quads = scene.msaa.quads;
  in.derivatives = std::string(name_of(scene.msaa.derivatives));
  in.clear_color = scene.clear_color;
  for (const Primitive& prim : scene.primitives) {
    oracle::msaa::Primitive op;
    op.type = std::string(name_of(prim.type));
    for (const FloatPoint& v : prim.v)
      op.v.push_back(oracle_raw(v));
    op.aa = prim.aa;
    op.color = prim.color;
    in.primitives.push_back(std::move(op));
  }
  return in;
}

bool multisampled(const Scene& scene) {
  const MultisampleState& ms = scene.msaa;
  return ms.count() > 1 || ms.pattern.kind != PatternKind::kStandard || ms.has_centroid ||
         ms.wants_quads() || ms.shading != ShadingRate::kPixel ||
         ms.sample_mask != MultisampleState{}.sample_mask;
}

namespace {

using Raw = std::array<std::int64_t, 2>;
using Key = std::tuple<std::int32_t, std::int32_t, std::int64_t>; // (y, x, seg or -1)

std::string key_text(std::size_t prim, const Key& k) {
  return "prim " + std::to_string(prim) + " pixel (" + std::to_string(std::get<1>(k)) + ", " +
         std::to_string(std::get<0>(k)) + ")" +
         (std::get<2>(k) >= 0 ? " seg " + std::to_string(std::get<2>(k)) : std::string());
}

using detail::centre_raw;

__extension__ using Int128 = __int128;

// Returns whether point c lies within distance r of the segment a -> b's bounding box grown by
// r and within distance r of its supporting line (all raw 16.8, exact): a superset of the
// pixels within distance r of the segment. The oracles are exact but slow, so only these
// candidates are asked. Sound because every pixel an oracle can cover is a candidate: an
// aliased line covers a pixel only when it meets the pixel's diamond (LINE.D3D.EXIT,
// LINE.VK.EXIT: within 1/2 px of its centre, the Vulkan endpoint shift is below 1 raw); an
// antialiased line is a rectangle within 1/2 px of its segment (LINE.AA.RECT), so a pixel
// square meeting it has its centre within 1/2 + sqrt(2)/2 < 3/2 px; a quadrilateral line's
// corners lie within 0.7 px + 1 raw of its endpoints (LINE.QUAD.CORNERS), so a covered centre
// lies within 3/2 px; a point's square lies within sqrt(2)/2 px of its centre.
bool near_segment(const Raw& a, const Raw& b, const Raw& c, std::int64_t r) {
  if (c[0] < std::min(a[0], b[0]) - r || c[0] > std::max(a[0], b[0]) + r ||
      c[1] < std::min(a[1], b[1]) - r || c[1] > std::max(a[1], b[1]) + r) {
    return false;
  }
  const std::int64_t dx = b[0] - a[0];
  const std::int64_t dy = b[1] - a[1];
  const Int128 cross = Int128{dx} * (c[1] - a[1]) - Int128{dy} * (c[0] - a[0]);
  const Int128 len2 = Int128{dx} * dx + Int128{dy} * dy;
  return cross * cross <= Int128{r} * r * len2;
}

// 3/2 px in raw units: the candidate radius of near_segment.
constexpr std::int64_t kNearRaw = 384;

using detail::Checker;

// Calls fn(x, y) for every pixel of the target whose centre is within 3/2 px of a -> b.
template <class Fn> void for_candidates(const Scene& scene, const Raw& a, const Raw& b, Fn&& fn) {
  for (std::int32_t y = 0; y < scene.height; ++y)
    for (std::int32_t x = 0; x < scene.width; ++x)
      if (near_segment(a, b, centre_raw(x, y), kNearRaw))
        fn(x, y);
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE
// The fragment list itself: inside the target, sorted, mask 1, seg and coverage where due.
void check_fragment_list(const Scene& scene, const std::vector<Fragment>& kernel, Checker& c) {
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    const Fragment& f = kernel[i];
    const std::string at = "fragment " + std::to_string(i) + " (prim " + std::to_string(f.prim) +
                           ", x " + std::to_string(f.x) + ", y " + std::to_string(f.y) + ")";
    if (f.prim >= scene.primitives.size()) {
      c.note(at + ": no such primitive");
      return;
    }
    const Primitive& prim = scene.primitives[f.prim];
    if (f.x < 0 || f.y < 0 || f.x >= scene.width || f.y >= scene.height)
      c.note(at + ": outside the target");
    if (f.mask != 1u)
      c.note(at + ": mask " + std::to_string(f.mask));
    if (f.seg.has_value() != (prim.type == PrimitiveType::kLineStrip))
      c.note(at + ": seg on a non-strip or missing");
    if (f.seg && *f.seg + 1 >= prim.v.size())
      c.note(at + ": seg beyond the strip");
    if (f.coverage_q16.has_value() != prim.aa)
      c.note(at + ": coverage on an aliased fragment or missing");
    if (f.coverage_q16 && (*f.coverage_q16 < 1 || *f.coverage_q16 > 65536))
      c.note(at + ": coverage out of [1, 65536]");
    if (i > 0 && !fragment_before(kernel[i - 1], f))
      c.note(at + ": out of (prim, y, x, seg) order or duplicated");
  }
}

// The exact pixels of segment a -> b of line primitive p (seg: its index in a strip, or -1).
void line_keys(const Scene& scene, const PreparedScene& ps, const std::vector<Fragment>& kernel,
               std::size_t p, std::size_t s, std::int64_t seg, std::vector<Key>& exact,
               Checker& c) {
  const Primitive& prim = scene.primitives[p];
  const Raw a = oracle_raw(prim.v[s]), b = oracle_raw(prim.v[s + 1]);
  const std::string fill(name_of(scene.conventions.fill));
  if (prim.aa) {
    // aa_pixels' set (exact coverage > 0), asked only of candidates: aa_check for the kernel's
    // own fragments (positive and coverage in one go), aa_compare with 0 for the others.
    c.used("AA-line oracle (aa_pixels, aa_check within 1/65536)");
    std::vector<std::pair<std::int32_t, std::int32_t>> checked; // (y, x) of kernel fragments
    for (const Fragment& f : kernel) {
      if (f.prim != p || f.seg.value_or(0) != s || !f.coverage_q16)
        continue;
      checked.emplace_back(f.y, f.x);
      const oracle::AACheck r = oracle::aa_check(a, b, f.x, f.y, *f.coverage_q16);
      if (r.positive)
        exact.push_back(Key{f.y, f.x, seg});
      if (r.positive && !r.within_bound)
        c.note("coverage " + std::to_string(*f.coverage_q16) + "/65536 at " +
               key_text(p, Key{f.y, f.x, seg}) + " is not within 1/65536 of the exact " +
               std::to_string(r.approx));
    }
    std::sort(checked.begin(), checked.end());
    for_candidates(scene, a, b, [&](std::int32_t x, std::int32_t y) {
      if (!std::binary_search(checked.begin(), checked.end(), std::make_pair(y, x)) &&
          oracle::aa_compare(a, b, x, y, 0, 1) > 0)
        exact.push_back(Key{y, x, seg});
    });
  } else if (ps.conventions.line_mode == LineMode::kQuadWide ||
             ps.conventions.line_mode == LineMode::kQuadNarrow) {
    // rule: SCENE.LINE_MODE
    c.used("quad-line oracle (quad_line_covers)");
    const std::string name(name_of(ps.conventions.line_mode));
    for_candidates(scene, a, b, [&](std::int32_t x, std::int32_t y) {
      if (oracle::quad_line_covers(a, b, name, centre_raw(x, y), fill))
        exact.push_back(Key{y, x, seg});
    });
  } else {
    // aliased_line_pixels' set, asked only of candidates: it tests the whole bounding box grown
    // by 2 px, which for a long diagonal line is the whole target (20x the candidates).
    c.used("line oracle (aliased_line_pixels)");
    const std::string name(name_of(ps.conventions.line_mode));
    for_candidates(scene, a, b, [&](std::int32_t x, std::int32_t y) {
      if (oracle::aliased_line_covers(a, b, name, x, y))
        exact.push_back(Key{y, x, seg});
    });
  }
}

// Compares one primitive's kernel pixels with the oracle's.
void compare_keys(std::size_t prim, std::vector<Key> mine, std::vector<Key> exact, Checker& c) {
  std::sort(mine.begin(), mine.end());
  std::sort(exact.begin(), exact.end());
  std::size_t i = 0, j = 0;
  while (i < mine.size() || j < exact.size()) {
    if (j == exact.size() || (i < mine.size() && mine[i] < exact[j])) {
      c.note("only the kernel covers " + key_text(prim, mine[i++]));
    } else if (i == mine.size() || exact[j] < mine[i]) {
      c.note("only the oracle covers " + key_text(prim, exact[j++]));
    } else {
      ++i;
      ++j;
    }
  }
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.COVERAGE
void check_single_sample(const Scene& scene, const PreparedScene& ps,
                         const std::vector<Fragment>& kernel, Checker& c) {
  check_fragment_list(scene, kernel, c);
  std::vector<std::vector<Key>> mine(scene.primitives.size()), exact(scene.primitives.size());
  for (const Fragment& f : kernel)
    if (f.prim < scene.primitives.size())
      mine[f.prim].push_back(Key{f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1});
  // Triangles: one oracle scene holding every triangle primitive.
  oracle::Scene tris;
  tris.width = scene.width;
  tris.height = scene.height;
  tris.state = oracle_state(raster_state(scene));
  std::vector<std::size_t> tri_prim;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    if (prim.type != PrimitiveType::kTriangle)
      continue;
    tris.triangles.push_back({prim.v[0], prim.v[1], prim.v[2]});
    tri_prim.push_back(p);
  }
  if (!tris.triangles.empty()) {
    c.used("triangle oracle (render)");
    for (const oracle::Fragment& f : oracle::render(tris))
      exact[tri_prim[f.prim]].push_back(Key{f.y, f.x, -1});
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    if (prim.type == PrimitiveType::kPoint) {
      // The exact half-open square around the oracle's own snapped centre.
      c.used("point oracle (point_covers)");
      const Raw centre = oracle_raw(prim.v[0]);
      if (!oracle::point_in_range(centre))
        throw std::invalid_argument("the kernel accepted a point outside POINT.RANGE");
      const std::string fill(name_of(scene.conventions.fill));
      for_candidates(scene, centre, centre, [&](std::int32_t x, std::int32_t y) {
        if (oracle::point_covers(centre, centre_raw(x, y), fill))
          exact[p].push_back(Key{y, x, -1});
      });
    } else if (prim.type != PrimitiveType::kTriangle) {
      const bool strip = prim.type == PrimitiveType::kLineStrip;
      for (std::size_t s = 0; s + 1 < prim.v.size(); ++s)
        line_keys(scene, ps, kernel, p, s, strip ? static_cast<std::int64_t>(s) : -1, exact[p], c);
    }
    compare_keys(p, mine[p], exact[p], c);
  }
}

std::string opt_text(const std::optional<std::uint32_t>& v) {
  return v ? std::to_string(*v) : "-";
}

// One fragment as text, the same for the kernel's and the oracle's.
template <class F> std::string msaa_text(const F& f) {
  std::string t = "prim " + std::to_string(f.prim) + " pixel (" + std::to_string(f.x) + ", " +
                  std::to_string(f.y) + ") seg " + opt_text(f.seg) + " sample " +
                  opt_text(f.sample) + " mask " + std::to_string(f.mask) +
                  (f.helper ? " helper" : "");
  if (f.centroid)
    t += " centroid (" + std::to_string(f.centroid->offset.x) + ", " +
         std::to_string(f.centroid->offset.y) + ")/16";
  if (f.derivatives) {
    const auto& d = *f.derivatives;
    t += " ddx (" + std::to_string(d.ddx_x) + ", " + std::to_string(d.ddx_y) + ") ddy (" +
         std::to_string(d.ddy_x) + ", " + std::to_string(d.ddy_y) + ")/16";
  }
  return t;
}

// rule: SCENE.OUTPUT.MSAA, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11
// rule: MSAA.CENTROID.D3D10, MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE
// rule: MSAA.RESOLVE.AVERAGE
void check_multisampled(const Scene& scene, const PreparedScene& ps,
                        const std::vector<Fragment>& kernel, Checker& c) {
  c.used("multisampling oracle (msaa::render, msaa::resolve)");
  const oracle::msaa::Input in = oracle_msaa_input(scene);
  const std::vector<oracle::msaa::Fragment> exact = oracle::msaa::render(in);
  std::vector<std::string> mine, theirs;
  for (const Fragment& f : kernel) {
    // Only an antialiased d3d line without MultisampleEnable keeps its coverage on a
    // multisampled target (MSAA.LINE.MODE): the single-sample line's, within its bound.
    const bool aa_line = f.prim < scene.primitives.size() && scene.primitives[f.prim].aa &&
                         scene.conventions.line_mode == LineMode::kD3DDiamond &&
                         !(scene.msaa.count() > 1 && scene.conventions.multisample_enable);
    if (f.coverage_q16.has_value() != (aa_line && !f.helper))
      c.note("a coverage " + std::string(f.coverage_q16 ? "on" : "missing from") +
             " a multisampled fragment at " + msaa_text(f));
    if (f.coverage_q16 && aa_line) {
      c.used("AA-line oracle (aa_check within 1/65536)");
      const Primitive& prim = scene.primitives[f.prim];
      const std::size_t s = f.seg.value_or(0);
      const oracle::AACheck r = oracle::aa_check(
          oracle_raw(prim.v.at(s)), oracle_raw(prim.v.at(s + 1)), f.x, f.y, *f.coverage_q16);
      if (!r.positive || !r.within_bound)
        c.note("coverage " + std::to_string(*f.coverage_q16) + "/65536 at " + msaa_text(f) +
               " is not within 1/65536 of the exact " + std::to_string(r.approx));
    }
    mine.push_back(msaa_text(f));
  }
  for (const oracle::msaa::Fragment& f : exact)
    theirs.push_back(msaa_text(f));
  // The lists are in the same order (SCENE.OUTPUT.MSAA); report where they part.
  for (std::size_t i = 0; i < std::max(mine.size(), theirs.size()); ++i) {
    const std::string a = i < mine.size() ? mine[i] : "(nothing)";
    const std::string b = i < theirs.size() ? theirs[i] : "(nothing)";
    if (a != b)
      c.note("fragment " + std::to_string(i) + ": kernel " + a + ", oracle " + b);
  }
  // The resolved target.
  const auto resolved = resolve(ps, kernel);
  if (const auto* err = std::get_if<SceneError>(&resolved)) {
    c.note("resolve failed: " + err->what());
    return;
  }
  const std::vector<oracle::msaa::Rgba> exact_pixels = oracle::msaa::resolve(in, exact);
  const std::vector<Rgba8>& pixels = std::get<ResolvedImage>(resolved).pixels;
  if (pixels.size() != exact_pixels.size()) {
    c.note("resolve: " + std::to_string(pixels.size()) + " pixels, the oracle " +
           std::to_string(exact_pixels.size()));
    return;
  }
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (pixels[i] != exact_pixels[i]) {
      c.note("resolve differs at pixel (" +
             std::to_string(i % static_cast<std::size_t>(scene.width)) + ", " +
             std::to_string(i / static_cast<std::size_t>(scene.width)) + ")");
    }
  }
}

} // namespace

// rule: SCENE.PRIM.PATH
Mismatches check_against_oracle(const Scene& scene, const PreparedScene& ps,
                                const std::vector<Fragment>& kernel, const CheckOptions& options) {
  Checker c(options);
  const bool has_paths =
      std::any_of(scene.primitives.begin(), scene.primitives.end(),
                  [](const Primitive& p) { return p.type == PrimitiveType::kPath; });
  if (!has_paths) {
    if (multisampled(scene))
      check_multisampled(scene, ps, kernel, c);
    else
      check_single_sample(scene, ps, kernel, c);
    return c.take();
  }
  // Paths against the path oracle; the rest as a scene of its own, its primitives renumbered.
  std::vector<std::vector<const Fragment*>> of_path(scene.primitives.size());
  Scene rest = target_of(scene);
  std::vector<std::uint32_t> index(scene.primitives.size(), 0);
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    if (scene.primitives[p].type == PrimitiveType::kPath)
      continue;
    index[p] = static_cast<std::uint32_t>(rest.primitives.size());
    rest.primitives.push_back(scene.primitives[p]);
  }
  std::vector<Fragment> rest_kernel;
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    const Fragment& f = kernel[i];
    if (f.prim >= scene.primitives.size()) {
      c.note("fragment " + std::to_string(i) + ": no such primitive " + std::to_string(f.prim));
    } else if (scene.primitives[f.prim].type == PrimitiveType::kPath) {
      of_path[f.prim].push_back(&f);
    } else {
      rest_kernel.push_back(f);
      rest_kernel.back().prim = index[f.prim];
    }
    if (i > 0 && !fragment_before(kernel[i - 1], f))
      c.note("fragment " + std::to_string(i) + ": out of (prim, y, x, seg, sample) order");
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    if (scene.primitives[p].type == PrimitiveType::kPath)
      detail::check_path(scene, p, of_path[p], c);
  }
  // The prepared scene without its paths: ps with the same primitives kept.
  PreparedScene rest_ps = ps;
  rest_ps.primitives.clear();
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    if (ps.primitives[p].type != PrimitiveType::kPath)
      rest_ps.primitives.push_back(ps.primitives[p]);
  }
  if (multisampled(rest))
    check_multisampled(rest, rest_ps, rest_kernel, c);
  else
    check_single_sample(rest, rest_ps, rest_kernel, c);
  return c.take();
}

} // namespace rastrules::check
