// SPDX-License-Identifier: MIT
// Comparison of a driver's depth and attribute values with the exact ones: the exactly rounded
// value of each (the oracle's exact rationals, rounded once), the distance in ulps or depth
// units, and the allowance of the mode.
// Implements: FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <tuple>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::fuzzer {
namespace {

namespace op = oracle::pipe;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The float32 values in order as integers: adjacent floats differ by one, -0 and +0 are equal.
std::int64_t ordered(float f) {
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const auto mag = static_cast<std::int64_t>(bits & 0x7fffffffu);
  return (bits >> 31) != 0 ? -mag : mag;
}

// The number of float32 steps between a and b (infinite when either is NaN).
double ulps(float a, float b) {
  if (std::isnan(a) || std::isnan(b))
    return kInf;
  return static_cast<double>(std::abs(ordered(a) - ordered(b)));
}

// The spacing of float32 at x (2^-149 at least).
double ulp32(double x) {
  const double a = std::fabs(x);
  if (!(a >= 0x1p-126))
    return 0x1p-149;
  return std::ldexp(1.0, std::max(std::ilogb(a), -126) - 23);
}

bool same_float(float a, float b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

op::Raw2 raw_of(Vec2 v) {
  return {v.x.raw(), v.y.raw()};
}

// rule: PIPE.BARY.EXACT, PIPE.BARY.LINE
// The exact barycentrics of evaluation point s for a drawn primitive, as the spec defines them.
op::Bary bary_at(const pipe::DrawnPrimitive& d, Vec2 s) {
  op::Bary b;
  if (d.type == PrimitiveType::kTriangle && d.snapped.size() == 3)
    return op::barycentrics({raw_of(d.snapped[0]), raw_of(d.snapped[1]), raw_of(d.snapped[2])},
                            raw_of(s));
  if (d.snapped.size() < 2) {
    b.e = {1, 0, 0};
    b.area = 1;
    return b;
  }
  const op::Raw2 v0 = raw_of(d.snapped[0]), v1 = raw_of(d.snapped[1]), p = raw_of(s);
  const std::int64_t dx = v1[0] - v0[0], dy = v1[1] - v0[1];
  const std::int64_t den = dx * dx + dy * dy;
  const std::int64_t num = (p[0] - v0[0]) * dx + (p[1] - v0[1]) * dy;
  b.e = {den - num, num, 0};
  b.area = den;
  return b;
}

// The allowances of FUZZ.VALUES.LEGAL (spec/driver.md gives each with its source).
constexpr double kAttrUlps = 2.0;      // ulp32(x) multiples
constexpr double kAttrRoundings = 8.0; // float32 roundings of the formula's terms, times S
constexpr double kDepthRoundings = 4.0;

struct Expected {
  float exact32 = 0; // the exactly rounded float32
  double x = 0;      // the exact value (nearest double)
  double s = 0;      // S of the conditioning (PIPE.INTERP.BOUND's)
  // Perspective, at or beyond the horizon: the flat value by rastrules' choice
  // (PIPE.INTERP.HORIZON), a value no API defines.
  bool horizon = false;
  std::string rule;
};

// The exact value of attribute k of a fragment evaluated at s.
Expected attribute_expected(const pipe::DrawnPrimitive& d, std::size_t k, pipe::Interpolation how,
                            Vec2 s) {
  Expected e;
  const std::array<float, 3>& a = d.attr[k];
  const float flat = d.flat[k];
  if (how == pipe::Interpolation::kFlat) {
    e.rule = "PIPE.INTERP.FLAT";
    e.exact32 = flat;
    e.x = flat;
    return e;
  }
  const op::Bary b = bary_at(d, s);
  if (how == pipe::Interpolation::kLinear) {
    e.rule = "PIPE.INTERP.LINEAR";
    if (b.area == 0) { // a zero-length line: vertex 0's value (PIPE.BARY.LINE)
      e.exact32 = a[0];
      e.x = a[0];
      return e;
    }
    e.exact32 = op::linear_nearest32(b, a);
    e.x = op::linear_exact(b, a);
    double sum = 0;
    for (std::size_t i = 0; i < 3; ++i)
      sum += std::fabs(static_cast<double>(b.e[i]) * a[i]);
    e.s = sum / std::fabs(static_cast<double>(b.area));
    return e;
  }
  e.rule = "PIPE.INTERP.PERSPECTIVE";
  const std::optional<float> p = b.area == 0 ? std::nullopt : op::perspective_nearest32(b, a, d.w);
  if (!p) { // the horizon (or a zero-length line): the flat value (PIPE.INTERP.HORIZON)
    e.exact32 = flat;
    e.x = flat;
    e.horizon = b.area != 0;
    return e;
  }
  e.exact32 = *p;
  e.x = *op::perspective_exact(b, a, d.w);
  double num = 0, den = 0, den_abs = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double eq = static_cast<double>(b.e[i]) / d.w[i];
    num += std::fabs(eq * a[i]);
    den += eq;
    den_abs += std::fabs(eq);
  }
  e.s = (num + std::fabs(e.x) * den_abs) / std::fabs(den);
  return e;
}

struct DepthExpected {
  pipe::DepthValue stored; // exactly rounded
  double scaled = 0;       // the exact clamped depth times 2^n - 1 (UNORM) or itself (d32f)
  double s_scaled = 0;     // S of PIPE.DEPTH.BOUND in the same unit
};

std::string format_name(pipe::DepthFormat f) {
  return f == pipe::DepthFormat::kD16 ? "d16" : (f == pipe::DepthFormat::kD24 ? "d24" : "d32f");
}

double unorm_max(pipe::DepthFormat f) {
  return f == pipe::DepthFormat::kD16 ? 65535.0 : 16777215.0;
}

DepthExpected depth_expected(const pipe::DrawnPrimitive& d, Vec2 s, const pipe::Viewport& vp,
                             pipe::DepthFormat f) {
  const op::Bary b = bary_at(d, s);
  const std::string name = format_name(f);
  double x = 0, sz = 0;
  op::Stored st;
  if (b.area == 0) {
    x = d.z[0];
    sz = std::fabs(x);
    st = op::store_exact(x, vp.min_depth, vp.max_depth, name);
  } else {
    x = op::depth_exact(b, d.z);
    for (std::size_t i = 0; i < 3; ++i)
      sz += std::fabs(static_cast<double>(b.e[i]) * d.z[i]);
    sz /= std::fabs(static_cast<double>(b.area));
    st = op::depth_stored_nearest(b, d.z, vp.min_depth, vp.max_depth, name);
  }
  const double clamped =
      std::clamp(x, static_cast<double>(vp.min_depth), static_cast<double>(vp.max_depth));
  DepthExpected e;
  e.stored.unorm = st.unorm;
  e.stored.f = st.f;
  const double m = f == pipe::DepthFormat::kD32F ? 1.0 : unorm_max(f);
  e.scaled = clamped * m;
  e.s_scaled = sz * m;
  return e;
}

using Key = std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::uint32_t, std::uint32_t>;
Key key_of(const Fragment& f) {
  return {f.prim, f.y, f.x, f.seg.value_or(0xffffffffu), f.sample.value_or(0xffffffffu)};
}

// Keeps the largest distance.
void keep_worst(std::optional<ValueDiff>& worst, const ValueDiff& d) {
  if (!worst || d.distance > worst->distance)
    worst = d;
}

} // namespace

// rule: FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL
std::optional<ValueComparison> compare_values(const Scene& scene, const driver::Drawing& drawing,
                                              Profile profile, Mode mode, std::string* error) {
  auto run = pipe::run_pipeline(scene, pipe::PipeOptions::plain());
  if (auto* e = std::get_if<SceneError>(&run)) {
    if (error != nullptr)
      *error = "the reference rejects the scene: " + e->what();
    return std::nullopt;
  }
  const pipe::PipeResult& ref = std::get<pipe::PipeResult>(run);
  ValueComparison out;
  if (ref.data.empty() || drawing.values.empty())
    return out;
  const pipe::Viewport vp = scene.viewport.value_or(pipe::Viewport{
      0.0f, 0.0f, static_cast<float>(scene.width), static_cast<float>(scene.height), 0.0f, 1.0f});
  const pipe::DepthFormat fmt = scene.conventions.depth;
  const SamplePattern& pattern = scene.msaa.pattern;
  std::multimap<Key, std::size_t> by_key;
  for (std::size_t i = 0; i < ref.fragments.size(); ++i) {
    if (!ref.fragments[i].helper)
      by_key.emplace(key_of(ref.fragments[i]), i);
  }
  const bool legal = mode == Mode::kLegal;
  for (std::size_t j = 0; j < drawing.fragments.size() && j < drawing.values.size(); ++j) {
    const Fragment& got_f = drawing.fragments[j];
    const driver::FragmentValues& got = drawing.values[j];
    if (got.attr.empty() && got.depth.empty())
      continue;
    // The reference fragments of this key (several only where clipped parts overlap,
    // PIPE.CLIP.FOLD); each is judged, and the one with the fewest values beyond the allowance
    // (then the smallest largest distance) is kept.
    std::optional<std::pair<std::vector<ValueDiff>, std::pair<std::uint64_t, std::uint64_t>>> best;
    std::uint64_t best_beyond = 0;
    double best_worst = kInf;
    const auto range = by_key.equal_range(key_of(got_f));
    for (auto it = range.first; it != range.second; ++it) {
      const std::size_t i = it->second;
      const Fragment& rf = ref.fragments[i];
      const pipe::FragmentData& rd = ref.data[i];
      if (got.part && rd.part != got.part)
        continue;
      if (rd.attr.empty() && rd.depth.empty())
        continue; // killed by the depth test: nothing to compare
      const pipe::DrawnPrimitive& dp = ref.drawn[rd.drawn];
      std::vector<ValueDiff> diffs;
      std::uint64_t n_attr = 0, n_depth = 0, beyond = 0;
      double worst = 0;
      const auto base = [&](std::string what, std::string rule) {
        ValueDiff d;
        d.prim = rf.prim;
        d.x = rf.x;
        d.y = rf.y;
        d.seg = rf.seg;
        d.sample = rf.sample;
        d.part = rd.part;
        d.what = std::move(what);
        d.rule = std::move(rule);
        return d;
      };
      // rule: PIPE.INTERP.LOCATION
      const auto point_of = [&](pipe::Location l) {
        if (l == pipe::Location::kCentroid && rf.centroid)
          return sample_position(rf.x, rf.y, rf.centroid->offset);
        if (l == pipe::Location::kSample && rf.sample)
          return sample_position(rf.x, rf.y, pattern.positions[*rf.sample]);
        return pixel_center(rf.x, rf.y);
      };
      if (!got.attr.empty() && rd.attr.size() == got.attr.size()) {
        for (std::size_t k = 0; k < got.attr.size(); ++k) {
          const pipe::AttributeDecl& decl = scene.attributes[k];
          const Expected e = attribute_expected(dp, k, decl.interpolation, point_of(decl.location));
          ValueDiff d = base("attr " + decl.name, e.rule);
          d.expected = e.exact32;
          d.reference = rd.attr[k];
          d.got = got.attr[k];
          d.distance = ulps(got.attr[k], e.exact32);
          if (legal && e.horizon) {
            // rule: FUZZ.VALUES.LEGAL
            // Beyond the horizon no API defines the value: anything is allowed.
            d.allowed = kInf;
            d.within = true;
          } else if (legal && decl.interpolation != pipe::Interpolation::kFlat) {
            const auto judge = [&](const Expected& x) {
              const double tol = kAttrUlps * ulp32(x.x) + kAttrRoundings * 0x1p-24 * x.s;
              d.allowed = tol / ulp32(x.x);
              d.within = x.horizon || (std::isfinite(got.attr[k]) &&
                                       std::fabs(static_cast<double>(got.attr[k]) - x.x) <= tol);
            };
            judge(e);
            // rule: FUZZ.VALUES.LEGAL
            // Under sample-rate shading Vulkan and OpenGL may evaluate an input that is not
            // at its sample at the invocation's sample instead.
            if (!d.within && profile != Profile::kD3D11 && rf.sample &&
                decl.location != pipe::Location::kSample) {
              judge(attribute_expected(dp, k, decl.interpolation,
                                       sample_position(rf.x, rf.y, pattern.positions[*rf.sample])));
            }
          } else if (legal) {
            d.within = same_float(got.attr[k], e.exact32);
          } else {
            d.allowed = ulps(rd.attr[k], e.exact32);
            d.within = same_float(got.attr[k], e.exact32) || same_float(got.attr[k], rd.attr[k]);
          }
          ++n_attr;
          worst = std::max(worst, d.distance);
          if (!d.within)
            ++beyond;
          diffs.push_back(std::move(d));
        }
      }
      if (!got.depth.empty() && rd.depth.size() == got.depth.size()) {
        // rule: FUZZ.VALUES.LEGAL, PIPE.DEPTH.BIAS
        // Vulkan and OpenGL leave r (up to a factor 2) and the slope (max or Euclidean) to the
        // implementation: the bias may lie up to |bias| r + |slope| MaxDepthSlope (sqrt 2 - 1)
        // beyond the reference's, in depth units (scaled like e.scaled below).
        double bias_allowance = 0;
        if (legal && profile != Profile::kD3D11 && scene.depth &&
            dp.type == PrimitiveType::kTriangle && dp.snapped.size() == 3) {
          const pipe::DepthBias& b = scene.depth->bias;
          if (b.enabled()) {
            const std::array<Vec2, 3> v{dp.snapped[0], dp.snapped[1], dp.snapped[2]};
            const double r = pipe::depth_bias(v, dp.z, pipe::DepthBias{1, 0.0f, 0.0f}, fmt);
            const double slope = pipe::depth_bias(v, dp.z, pipe::DepthBias{0, 1.0f, 0.0f}, fmt);
            const double m = fmt == pipe::DepthFormat::kD32F ? 1.0 : unorm_max(fmt);
            bias_allowance =
                (std::fabs(static_cast<double>(b.bias)) * r +
                 std::fabs(static_cast<double>(b.slope_scaled)) * slope * (std::sqrt(2.0) - 1.0)) *
                m;
          }
        }
        std::size_t n = 0;
        for (std::uint32_t k = 0; k < scene.msaa.count(); ++k) {
          if ((rf.mask >> k & 1u) == 0)
            continue;
          const DepthExpected e =
              depth_expected(dp, sample_position(rf.x, rf.y, pattern.positions[k]), vp, fmt);
          const pipe::DepthValue& g = got.depth[n];
          const pipe::DepthValue& r = rd.depth[n];
          ++n;
          ValueDiff d = base("depth[" + std::to_string(k) + "]", "PIPE.DEPTH.FORMAT");
          d.sample = rf.sample ? rf.sample : std::optional<std::uint32_t>(k);
          if (fmt == pipe::DepthFormat::kD32F) {
            d.expected = e.stored.f;
            d.reference = r.f;
            d.got = g.f;
            d.distance = ulps(g.f, e.stored.f);
            if (legal) {
              const double tol =
                  0.5 * ulp32(e.scaled) + kDepthRoundings * 0x1p-24 * e.s_scaled + bias_allowance;
              d.allowed = tol / ulp32(e.scaled);
              d.within =
                  std::isfinite(g.f) && std::fabs(static_cast<double>(g.f) - e.scaled) <= tol;
            } else {
              d.allowed = ulps(r.f, e.stored.f);
              d.within = same_float(g.f, e.stored.f) || same_float(g.f, r.f);
            }
          } else {
            d.expected = e.stored.unorm;
            d.reference = r.unorm;
            d.got = g.unorm;
            d.distance = std::fabs(static_cast<double>(g.unorm) - e.stored.unorm);
            if (legal) {
              // rule: FUZZ.VALUES.LEGAL
              const double conversion = profile == Profile::kD3D11 ? 0.6 : 1.0;
              const double tol =
                  conversion + kDepthRoundings * 0x1p-24 * e.s_scaled + bias_allowance;
              d.allowed = tol;
              d.within = std::fabs(static_cast<double>(g.unorm) - e.scaled) <= tol;
            } else {
              d.allowed = std::fabs(static_cast<double>(r.unorm) - e.stored.unorm);
              d.within = g.unorm == e.stored.unorm || g.unorm == r.unorm;
            }
          }
          ++n_depth;
          worst = std::max(worst, d.distance);
          if (!d.within)
            ++beyond;
          diffs.push_back(std::move(d));
        }
      }
      if (!best || beyond < best_beyond || (beyond == best_beyond && worst < best_worst)) {
        best.emplace(std::move(diffs), std::pair{n_attr, n_depth});
        best_beyond = beyond;
        best_worst = worst;
      }
    }
    if (!best)
      continue;
    out.attributes += best->second.first;
    out.depths += best->second.second;
    for (ValueDiff& d : best->first) {
      keep_worst(d.what.starts_with("depth") ? out.worst_depth : out.worst_attribute, d);
      if (d.within)
        continue;
      ++out.beyond;
      if (out.diffs.size() < kMaxValueDiffs)
        out.diffs.push_back(std::move(d));
    }
  }
  return out;
}

} // namespace rastrules::fuzzer
