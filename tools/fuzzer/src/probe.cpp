// SPDX-License-Identifier: MIT
// rastrules probe: find a driver's conventions with small probe scenes.
// Implements: FUZZ.PROBE

#include <algorithm>
#include <bit>
#include <variant>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer {
namespace {

constexpr std::int64_t kUnits = 4096; // probe offsets in 1/4096 px

class Prober {
public:
  explicit Prober(driver::Driver& d) : d_(d) {}

  // The driver's observable coverage, or nullopt (error_ set).
  std::optional<std::vector<Fragment>> draw(const Scene& s) {
    if (const std::string why = d_.unsupported(s); !why.empty()) {
      error_ = "probe scene not supported: " + why;
      return std::nullopt;
    }
    auto r = d_.draw(s);
    if (auto* e = std::get_if<driver::DriverError>(&r)) {
      error_ = e->message;
      return std::nullopt;
    }
    return observable(std::get<std::vector<Fragment>>(r));
  }

  // The mask of pixel (x, y) of primitive 0 (0 when not covered).
  std::optional<std::uint32_t> mask(const Scene& s, std::int32_t x, std::int32_t y) {
    auto f = draw(s);
    if (!f)
      return std::nullopt;
    for (const Fragment& g : *f) {
      if (g.prim == 0 && g.x == x && g.y == y)
        return g.mask;
    }
    return 0u;
  }

  std::string error_;

private:
  driver::Driver& d_;
};

Scene base_scene() {
  Scene s;
  s.width = 8;
  s.height = 8;
  return s;
}

// Clockwise triangles whose one edge lies on a line: a left edge (interior to its right) at x,
// a right edge at x, a top edge (interior below) at y, a bottom edge at y.
Scene left_edge(float x) {
  Scene s = base_scene();
  s.primitives.push_back(
      make_triangle({FloatPoint{x, 6.0f}, FloatPoint{x, -6.0f}, FloatPoint{x + 6.0f, 0.0f}}));
  return s;
}
Scene right_edge(float x) {
  Scene s = base_scene();
  s.primitives.push_back(
      make_triangle({FloatPoint{x, -6.0f}, FloatPoint{x, 6.0f}, FloatPoint{x - 6.0f, 0.0f}}));
  return s;
}
Scene top_edge(float y) {
  Scene s = base_scene();
  s.primitives.push_back(
      make_triangle({FloatPoint{-6.0f, y}, FloatPoint{6.0f, y}, FloatPoint{0.0f, y + 6.0f}}));
  return s;
}
Scene bottom_edge(float y) {
  Scene s = base_scene();
  s.primitives.push_back(
      make_triangle({FloatPoint{6.0f, y}, FloatPoint{-6.0f, y}, FloatPoint{0.0f, y - 6.0f}}));
  return s;
}

std::string convention_name(const ProbeReport& r) {
  if (r.top != r.bottom && r.left != r.right) {
    return std::string(r.top ? "top" : "bottom") + "-" + (r.left ? "left" : "right");
  }
  std::string s = "no consistent fill convention: samples on ";
  std::string on;
  for (const auto& [name, in] :
       {std::pair{"top", r.top}, {"bottom", r.bottom}, {"left", r.left}, {"right", r.right}}) {
    if (in)
      on += (on.empty() ? "" : ", ") + std::string(name);
  }
  return s + (on.empty() ? "no" : on) + " edges are inside";
}

bool power_of_two(std::int64_t v) {
  return v > 0 && std::has_single_bit(static_cast<std::uint64_t>(v));
}

// Sets r.top, r.bottom, r.left, r.right and r.fill from an edge exactly through the centre
// (0.5, 0.5) of pixel (0, 0); halves are exact on every grid of at least one subpixel bit.
// Returns false (r.error set) when a draw failed.
bool probe_fill(Prober& p, ProbeReport& r) {
  const auto t = p.mask(top_edge(0.5f), 0, 0), b = p.mask(bottom_edge(0.5f), 0, 0),
             l = p.mask(left_edge(0.5f), 0, 0), rr = p.mask(right_edge(0.5f), 0, 0);
  if (!t || !b || !l || !rr) {
    r.error = p.error_;
    return false;
  }
  r.top = *t != 0;
  r.bottom = *b != 0;
  r.left = *l != 0;
  r.right = *rr != 0;
  r.fill = convention_name(r);
  return true;
}

// Returns whether a vertical edge moved d / 4096 px away from the centre of pixel (0, 0) has
// a snapped position other than 0.5, or nullopt (p.error_ set) when a draw failed. The edge
// moves right when `upward`, else left; which edge is drawn depends on the tie rule r found.
std::optional<bool> edge_leaves_centre(Prober& p, const ProbeReport& r, bool upward,
                                       std::int64_t d) {
  if (upward) {
    const float x = 0.5f + static_cast<float>(d) / static_cast<float>(kUnits);
    if (r.left) {
      auto m = p.mask(left_edge(x), 0, 0);
      if (!m)
        return std::nullopt;
      return *m == 0; // covered iff snapped <= 0.5
    }
    auto m = p.mask(right_edge(x), 0, 0);
    if (!m)
      return std::nullopt;
    return *m != 0; // covered iff snapped > 0.5
  }
  const float x = 0.5f - static_cast<float>(d) / static_cast<float>(kUnits);
  if (!r.left) {
    auto m = p.mask(left_edge(x), 0, 0);
    if (!m)
      return std::nullopt;
    return *m != 0; // covered iff snapped < 0.5
  }
  auto m = p.mask(right_edge(x), 0, 0);
  if (!m)
    return std::nullopt;
  return *m == 0; // covered iff snapped >= 0.5
}

// Sets r.rounding and r.subpixel_bits from the threshold t (in 1/4096 px) at which an edge
// moving `upward` (or downward) leaves the centre. Ties at the half step: half to even keeps
// 0.5 (an even multiple of the step for 2 bits or more): t = s/2 + 1; half away from the
// centre: t = s/2; truncation: t = s.
void classify_threshold(std::int64_t t, bool upward, ProbeReport& r) {
  std::int64_t step = 0;
  if (t == 1) {
    step = 1;
    r.rounding = "finer than 1/4096 px";
  } else if (power_of_two(2 * (t - 1))) {
    step = 2 * (t - 1);
    r.rounding = upward ? "round half to even (ties keep the even grid point 0.5)"
                        : "round half to even or half up";
  } else if (power_of_two(2 * t)) {
    step = 2 * t;
    r.rounding = upward ? "round half up" : "round half down";
  } else if (power_of_two(t)) {
    step = t;
    r.rounding = upward ? "truncation toward -infinity" : "truncation toward +infinity";
  } else {
    r.rounding = "no power-of-two grid explains the threshold";
  }
  if (step > 0)
    r.subpixel_bits = 12 - std::countr_zero(static_cast<std::uint64_t>(step));
}

// Snapping: moves a vertical edge away from the centre by d / 4096 px and finds the smallest d
// at which its snapped position leaves 0.5 (binary search; the answer is monotone in d). With
// a left edge inside on ties (or a right edge outside on ties) the snapped position is > 0.5
// exactly when ... see spec/driver.md FUZZ.PROBE. Sets r.threshold_4096, r.rounding and
// r.subpixel_bits. Returns false (r.error set) when a draw failed.
bool probe_snapping(Prober& p, ProbeReport& r) {
  const bool upward = r.left || !r.right;
  std::int64_t lo = 1, hi = kUnits - 1; // find the smallest d in [lo, hi] that leaves
  auto at_hi = edge_leaves_centre(p, r, upward, hi);
  if (!at_hi) {
    r.error = p.error_;
    return false;
  }
  if (!*at_hi) {
    r.rounding = "the edge never left the centre within one pixel";
    return true;
  }
  while (lo < hi) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    auto v = edge_leaves_centre(p, r, upward, mid);
    if (!v) {
      r.error = p.error_;
      return false;
    }
    if (*v)
      hi = mid;
    else
      lo = mid + 1;
  }
  r.threshold_4096 = lo;
  classify_threshold(lo, upward, r);
  return true;
}

// Returns the fill convention r measured when it is consistent, else top-left: points and
// lines are compared under it, so a driver with another (legal) tie rule is not reported as
// drawing them differently.
FillConvention measured_convention(const ProbeReport& r) {
  const bool consistent = r.top != r.bottom && r.left != r.right;
  return !consistent ? FillConvention::kTopLeft
         : r.top     ? (r.left ? FillConvention::kTopLeft : FillConvention::kTopRight)
                     : (r.left ? FillConvention::kBottomLeft : FillConvention::kBottomRight);
}

// Returns r.point_rule's text: whether the driver's points match the reference's point rule.
std::string probe_points(driver::Driver& driver, Prober& p, FillConvention measured) {
  Scene s = base_scene();
  s.conventions.fill = measured;
  for (const FloatPoint v : {FloatPoint{1.0f, 1.0f}, FloatPoint{3.5f, 1.5f},
                             FloatPoint{5.25f, 2.0f}, FloatPoint{2.0f, 5.5f}}) {
    Primitive pt;
    pt.type = PrimitiveType::kPoint;
    pt.v = {v};
    s.primitives.push_back(pt);
  }
  if (!driver.info().points || !driver.unsupported(s).empty())
    return "not probed (the driver does not draw points)";
  auto got = p.draw(s);
  if (!got)
    return "not probed: " + p.error_;
  std::string err;
  auto c = compare(s, *got, Profile::kD3D11, Mode::kExact, &err);
  return c && c->match ? "1x1 squares around the snapped position, as POINT.SHAPE.SQUARE"
                       : "differs from POINT.SHAPE.SQUARE on the probe points";
}

// Returns r.line_mode's text: each line mode the driver accepts, drawn with that mode and
// compared with the reference.
std::string probe_lines(driver::Driver& driver, Prober& p, FillConvention measured) {
  Scene s = base_scene();
  s.conventions.fill = measured;
  for (const auto& [a, b] : {std::pair{FloatPoint{0.5f, 0.5f}, FloatPoint{6.5f, 3.5f}},
                             {FloatPoint{1.0f, 1.0f}, FloatPoint{7.0f, 1.0f}},
                             {FloatPoint{1.25f, 0.75f}, FloatPoint{2.75f, 6.25f}},
                             {FloatPoint{0.0f, 0.0f}, FloatPoint{5.0f, 5.0f}},
                             {FloatPoint{6.5f, 7.0f}, FloatPoint{1.5f, 4.0f}}}) {
    Primitive l;
    l.type = PrimitiveType::kLine;
    l.v = {a, b};
    s.primitives.push_back(l);
  }
  std::string modes;
  for (const LineMode m : {LineMode::kD3DDiamond, LineMode::kVulkanBresenham, LineMode::kQuadNarrow,
                           LineMode::kQuadWide}) {
    s.conventions.line_mode = m;
    if (!driver.unsupported(s).empty())
      continue;
    auto got = p.draw(s);
    std::string verdict;
    if (!got) {
      verdict = "failed: " + p.error_;
    } else {
      std::string err;
      auto c = compare(s, *got, Profile::kD3D11, Mode::kExact, &err);
      verdict = !c         ? "not compared: " + err
                : c->match ? "matches the reference"
                           : "differs from the reference (" + std::to_string(c->missing.size()) +
                                 " missing, " + std::to_string(c->extra.size()) + " extra pixels)";
    }
    modes += (modes.empty() ? "" : "; ") + std::string(io::line_mode_name(m)) + " " + verdict;
  }
  return modes.empty() ? "not probed (the driver draws no lines)" : modes;
}

// Returns the offset (1/16 px from the centre) of each of the 4 samples of pixel (0, 0) along
// one axis (0: x, 1: y), found by scanning a left (axis 0) or top (axis 1) edge across the
// pixel in steps of 1/16 px; nullopt (p.error_ set) when a draw failed. `inclusive`: whether
// such edges are inside on ties.
std::optional<std::array<int, 4>> scan_sample_axis(Prober& p, const SamplePattern& standard4,
                                                   int axis, bool inclusive) {
  std::array<int, 4> found = {99, 99, 99, 99};
  // Edge at offset o (1/16 px from the centre): a left (top) edge covers samples with
  // offset > o, or == o when left (top) edges are inclusive; the sample's offset is the
  // largest o that still covers it when inclusive, else that + 1.
  for (int o = -9; o <= 8; ++o) {
    const float pos = 0.5f + static_cast<float>(o) / 16.0f;
    Scene s = axis == 0 ? left_edge(pos) : top_edge(pos);
    set_sample_pattern(s, standard4);
    auto m = p.mask(s, 0, 0);
    if (!m)
      return std::nullopt;
    for (std::size_t k = 0; k < 4; ++k) {
      if ((*m & (1u << k)) != 0)
        found[k] = inclusive ? o : o + 1;
    }
  }
  return found;
}

// 4x sample positions: sets r.samples_4x and r.samples_note from a scan of a vertical and a
// horizontal edge across pixel (0, 0).
void probe_samples(driver::Driver& driver, Prober& p, ProbeReport& r) {
  const auto& counts = driver.info().sample_counts;
  if (std::find(counts.begin(), counts.end(), 4u) == counts.end()) {
    r.samples_note = "not probed (the driver has no 4x multisampling)";
    return;
  }
  const SamplePattern standard4 = standard_pattern(4);
  const auto sx = scan_sample_axis(p, standard4, 0, r.left);
  const auto sy = sx ? scan_sample_axis(p, standard4, 1, r.top) : std::nullopt;
  if (!sy) {
    r.samples_note = "not probed: " + p.error_;
    return;
  }
  for (std::size_t k = 0; k < 4; ++k)
    r.samples_4x.push_back(
        {static_cast<std::int8_t>((*sx)[k]), static_cast<std::int8_t>((*sy)[k])});
  r.samples_note = r.samples_4x == standard4.positions
                       ? "the standard 4x pattern (MSAA.PATTERN.STANDARD)"
                       : "differs from the standard 4x pattern";
}

} // namespace

// rule: FUZZ.PROBE
ProbeReport probe(driver::Driver& driver) {
  ProbeReport r;
  Prober p(driver);
  if (!probe_fill(p, r) || !probe_snapping(p, r))
    return r;
  const FillConvention measured = measured_convention(r);
  r.point_rule = probe_points(driver, p, measured);
  r.line_mode = probe_lines(driver, p, measured);
  probe_samples(driver, p, r);
  return r;
}

} // namespace rastrules::fuzzer
