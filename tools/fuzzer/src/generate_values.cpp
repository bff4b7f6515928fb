// SPDX-License-Identifier: MIT
// The values campaign's scene families (`rastrules fuzz --values`): pipeline scenes aimed at the
// hard cases of depth and attribute values.
// Implements: FUZZ.VALUES.GENERATE

#include <algorithm>
#include <cmath>
#include <limits>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/msaa.hpp"

namespace rastrules::fuzzer {
namespace {

// A value in [lo, hi] on a grid of 2^-bits.
float grid_value(Rng& rng, float lo, float hi, int bits) {
  const double scale = std::ldexp(1.0, bits);
  const auto k = rng.uniform(static_cast<std::int64_t>(std::ceil(lo * scale)),
                             static_cast<std::int64_t>(std::floor(hi * scale)));
  return static_cast<float>(static_cast<double>(k) / scale);
}

// A w with log2 uniform in [-20, 0] (ratios up to about 1e6 between vertices), or 1.
float pick_w(Rng& rng) {
  if (rng.chance(20))
    return 1.0f;
  return std::ldexp(1.0f, -static_cast<int>(rng.uniform(0, 20))) * grid_value(rng, 1.0f, 2.0f, 4);
}

// An attribute value: small grid values mostly, else huge, subnormal or of mixed magnitude.
float pick_attr(Rng& rng) {
  switch (rng.uniform(0, 7)) {
  case 0:
    return (rng.chance(50) ? 1.0f : -1.0f) *
           std::ldexp(1.0f, static_cast<int>(rng.uniform(100, 127)));
  case 1:
    return (rng.chance(50) ? 1.0f : -1.0f) *
           std::ldexp(1.0f, -static_cast<int>(rng.uniform(127, 149))); // subnormal
  case 2:
    return grid_value(rng, -1e6f, 1e6f, 0);
  default:
    return grid_value(rng, -4.0f, 4.0f, 10);
  }
}

// A depth in [0, 1]: near 0 or 1 in the format's resolution, or anywhere.
float pick_depth(Rng& rng, pipe::DepthFormat f) {
  const int bits = f == pipe::DepthFormat::kD16 ? 16 : (f == pipe::DepthFormat::kD24 ? 24 : 30);
  const float tiny = std::ldexp(1.0f, -static_cast<int>(rng.uniform(bits - 4, bits + 2)));
  switch (rng.uniform(0, 4)) {
  case 0:
    return 0.0f;
  case 1:
    return 1.0f;
  case 2:
    return tiny * static_cast<float>(rng.uniform(1, 15));
  case 3:
    return 1.0f - tiny * static_cast<float>(rng.uniform(1, 15));
  default:
    return grid_value(rng, 0.0f, 1.0f, 12);
  }
}

// A clip-space vertex at NDC (x, y) in [-lim, lim], depth z, clip w.
pipe::Vec4f clip_vertex(Rng& rng, float lim, float z, float w) {
  const float x = grid_value(rng, -lim, lim, 6), y = grid_value(rng, -lim, lim, 6);
  return {x * w, y * w, z * w, w};
}

struct ValueState {
  std::size_t attributes = 1;
  pipe::DepthFormat format = pipe::DepthFormat::kD24;
};

void add_attr(Rng& rng, Primitive& p, std::size_t n, std::size_t vertices) {
  p.attr.assign(vertices, std::vector<float>(n));
  for (auto& v : p.attr)
    for (float& a : v)
      a = pick_attr(rng);
}

Primitive clip_primitive(Rng& rng, PrimitiveType type, std::size_t n, const ValueState& st,
                         float lim, bool behind) {
  Primitive p;
  p.type = type;
  p.v.clear();
  for (std::size_t i = 0; i < n; ++i) {
    float z = pick_depth(rng, st.format);
    if (behind && i == 0)
      z = -grid_value(rng, 0.0f, 2.0f, 4) - 0.0625f; // before the near plane: clipped
    p.pos.push_back(clip_vertex(rng, lim, z, pick_w(rng)));
  }
  add_attr(rng, p, st.attributes, n);
  return p;
}

// rule: FUZZ.VALUES.GENERATE
void perspective_family(Rng& rng, Scene& s, const ValueState& st) {
  const auto n = rng.uniform(1, 2);
  for (std::int64_t i = 0; i < n; ++i)
    s.primitives.push_back(clip_primitive(rng, PrimitiveType::kTriangle, 3, st, 1.0f, false));
}

void clipped_family(Rng& rng, Scene& s, const ValueState& st) {
  const bool near = rng.chance(50);
  s.primitives.push_back(
      clip_primitive(rng, PrimitiveType::kTriangle, 3, st, near ? 1.0f : 3.0f, near));
}

void strip_family(Rng& rng, Scene& s, const ValueState& st) {
  const bool strip = rng.chance(70);
  const auto n = strip ? static_cast<std::size_t>(rng.uniform(3, 4)) : std::size_t{2};
  s.primitives.push_back(clip_primitive(
      rng, strip ? PrimitiveType::kLineStrip : PrimitiveType::kLine, n, st, 1.1f, rng.chance(25)));
}

void depth_family(Rng& rng, Scene& s, const ValueState& st) {
  // Window space: the depths reach the interpolation unchanged.
  Primitive p;
  for (FloatPoint& v : p.v)
    v = {grid_value(rng, -1.0f, static_cast<float>(s.width) + 1.0f, 4),
         grid_value(rng, -1.0f, static_cast<float>(s.height) + 1.0f, 4)};
  for (int i = 0; i < 3; ++i)
    p.z.push_back(pick_depth(rng, st.format));
  add_attr(rng, p, st.attributes, 3);
  s.primitives.push_back(p);
}

// rule: PIPE.INTERP.HORIZON
// A perspective triangle on a 4x target with one vertex at w = 2^-k (k in 14..22): the horizon
// (where the perspective denominator vanishes) runs close to its edges, so that the centres of
// partly covered pixels, extrapolated, lie near it or beyond it.
void horizon_family(Rng& rng, Scene& s, const ValueState& st) {
  set_sample_pattern(s, standard_pattern(4));
  Primitive p = clip_primitive(rng, PrimitiveType::kTriangle, 3, st, 1.0f, false);
  const auto k = static_cast<int>(rng.uniform(14, 22));
  const float w = std::ldexp(1.0f, -k);
  pipe::Vec4f& v = p.pos[static_cast<std::size_t>(rng.uniform(0, 2))];
  const float scale = w / v[3];
  for (float& c : v)
    c *= scale;
  s.primitives.push_back(p);
}

// rule: PIPE.DEPTH.BIAS
// One triangle, in clip or window space, under a depth bias: a constant of up to 1000 steps,
// one time in two a slope factor (1/4, 1 or 4, either sign), one time in four a clamp.
void bias_family(Rng& rng, Scene& s, const ValueState& st) {
  if (rng.chance(50))
    s.primitives.push_back(clip_primitive(rng, PrimitiveType::kTriangle, 3, st, 1.0f, false));
  else
    depth_family(rng, s, st);
  pipe::DepthBias& b = s.depth->bias;
  b.bias = static_cast<std::int32_t>(rng.uniform(-1000, 1000));
  if (rng.chance(50)) {
    b.slope_scaled =
        std::ldexp(rng.chance(50) ? 1.0f : -1.0f, 2 * static_cast<int>(rng.uniform(-1, 1)));
  }
  if (rng.chance(25)) {
    b.clamp = std::ldexp(rng.chance(50) ? 1.0f : -1.0f, -static_cast<int>(rng.uniform(6, 12)));
  }
}

} // namespace

// rule: FUZZ.VALUES.GENERATE
std::vector<std::pair<std::string, std::string>>
value_families_not_generated(Profile profile, const driver::Driver& driver,
                             const std::vector<std::string>& only) {
  const driver::DriverInfo& info = driver.info();
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string_view f : kValueFamilies) {
    if (!only.empty() && std::find(only.begin(), only.end(), f) == only.end()) {
      out.emplace_back(std::string(f), "not selected (--families)");
      continue;
    }
    if (!info.values)
      out.emplace_back(std::string(f), "the driver reports no values (DRIVER.VALUES)");
    else if (f == "strips" && !(profile == Profile::kD3D11 ? info.lines_d3d : info.lines_bresenham))
      out.emplace_back(std::string(f), "the driver does not draw the profile's lines");
    else if (f != "strips" && !info.triangles)
      out.emplace_back(std::string(f), "the driver does not draw triangles");
    else if (f == "horizon" && std::find(info.sample_counts.begin(), info.sample_counts.end(),
                                         4u) == info.sample_counts.end())
      out.emplace_back(std::string(f), "the driver draws no 4-sample target (partly covered "
                                       "pixels need one)");
  }
  return out;
}

// rule: FUZZ.VALUES.GENERATE
std::optional<Case> generate_value_case(std::uint64_t seed, std::uint64_t index, Profile profile,
                                        const driver::Driver& driver,
                                        const std::vector<std::string>& only) {
  std::vector<std::string> families;
  const auto skipped = value_families_not_generated(profile, driver, only);
  for (const std::string_view f : kValueFamilies) {
    if (std::none_of(skipped.begin(), skipped.end(), [&](const auto& e) { return e.first == f; }))
      families.emplace_back(f);
  }
  if (families.empty())
    return std::nullopt;
  const driver::DriverInfo& info = driver.info();
  const bool msaa4 = std::find(info.sample_counts.begin(), info.sample_counts.end(), 4u) !=
                     info.sample_counts.end();
  for (std::uint64_t attempt = 0; attempt < 16; ++attempt) {
    Rng rng(seed * 0x9E3779B97F4A7C15ull ^ (index + 1) * 0xC2B2AE3D27D4EB4Full ^
            attempt * 0x8CB92BA72F3D8DD7ull ^ 0x5641c0e5ull);
    rng.next();
    Case c;
    Scene& s = c.scene;
    s.width = static_cast<std::int32_t>(rng.uniform(4, 16));
    s.height = static_cast<std::int32_t>(rng.uniform(4, 16));
    apply_profile(profile, s);
    c.family = families[static_cast<std::size_t>(
        rng.uniform(0, static_cast<std::int64_t>(families.size()) - 1))];
    ValueState st;
    st.format = static_cast<pipe::DepthFormat>(rng.uniform(0, 2));
    st.attributes = static_cast<std::size_t>(rng.uniform(1, 3));
    s.conventions.depth = st.format;
    s.conventions.provoking = rng.chance(50) ? pipe::Provoking::kFirst : pipe::Provoking::kLast;
    for (std::size_t a = 0; a < st.attributes; ++a) {
      const auto how = static_cast<pipe::Interpolation>(rng.uniform(0, 2));
      s.attributes.push_back(
          {std::string(1, static_cast<char>('a' + a)), how, pipe::Location::kCenter});
    }
    pipe::DepthState depth;
    depth.func = rng.chance(75) ? pipe::CompareFunc::kAlways : pipe::CompareFunc::kLessEqual;
    s.depth = depth;
    if (c.family == "perspective")
      perspective_family(rng, s, st);
    else if (c.family == "clipped")
      clipped_family(rng, s, st);
    else if (c.family == "strips")
      strip_family(rng, s, st);
    else if (c.family == "depth")
      depth_family(rng, s, st);
    else if (c.family == "horizon")
      horizon_family(rng, s, st);
    else
      bias_family(rng, s, st);
    // One depth per covered sample: the standard 4x pattern one time in four.
    if (msaa4 && c.family != "horizon" && rng.chance(25))
      set_sample_pattern(s, standard_pattern(4));
    // rule: PIPE.INTERP.LOCATION
    // On 4 samples, half the interpolated attributes at the centroid (drawn last, so that the
    // scenes of 1-sample cases stay those of earlier versions).
    if (s.msaa.count() == 4) {
      for (pipe::AttributeDecl& a : s.attributes) {
        if (a.interpolation != pipe::Interpolation::kFlat && rng.chance(50))
          a.location = pipe::Location::kCentroid;
      }
      // rule: MSAA.SHADING.SAMPLE
      // One time in four sample-rate shading, and then each interpolated attribute at its
      // sample one time in two, for triangles; kept only when the driver draws it (the GPU adapters
      // do for pipeline scenes alone, so DriverInfo::sample_shading cannot say). Not with lines:
      // sample shading of Bresenham lines on several samples is undefined (MSAA.LINE.MODE), and the
      // other line modes are the coverage campaign's.
      const bool lines = std::any_of(s.primitives.begin(), s.primitives.end(), [](const auto& p) {
        return p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip;
      });
      if (rng.chance(25) && !lines) {
        const std::vector<pipe::AttributeDecl> before = s.attributes;
        s.msaa.shading = ShadingRate::kSample;
        for (pipe::AttributeDecl& a : s.attributes) {
          if (a.interpolation != pipe::Interpolation::kFlat && rng.chance(50))
            a.location = pipe::Location::kSample;
        }
        if (!driver.unsupported(s).empty()) {
          s.msaa.shading = ShadingRate::kPixel;
          s.attributes = before;
        }
      }
    }
    if (driver.unsupported(s).empty())
      return c;
  }
  return std::nullopt;
}

} // namespace rastrules::fuzzer
