// SPDX-License-Identifier: MIT
// Properties of the external driver's capabilities (spec/driver.md,
// DRIVER.EXTERNAL.CAPABILITIES) over random declarations and the campaign's own scenes:
// - a declaration written as a reply reads back as itself;
// - undeclared() refuses a scene exactly when a predicate written here from the spec's list
//   (primitive types, line modes, antialiasing, sample count, pattern, fill convention for
//   triangles, sample mask, shading, pipeline state, target side) says it is not declared;
// - a campaign against a driver with the declaration sends only declared scenes, and sends some
//   whenever the declaration allows a triangle scene of its profile.

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/external.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/name_table.hpp"

namespace rastrules::driver {
namespace {

template <class E> std::uint32_t all_bits() {
  return (1u << Names<E>::table.size()) - 1u;
}

// A random declaration; each key present with probability 1/2 (absent: everything).
struct Declared {
  Capabilities caps;
  nlohmann::json reply = nlohmann::json::object();
};

template <class E>
void maybe_names(Declared& d, const char* key, std::uint32_t Capabilities::*field) {
  if (!*rc::gen::arbitrary<bool>())
    return;
  const std::uint32_t bits = *rc::gen::inRange<std::uint32_t>(1u, all_bits<E>() + 1u);
  d.caps.*field = bits;
  nlohmann::json names = nlohmann::json::array();
  for (const auto& [name, value] : Names<E>::table) {
    if ((bits >> static_cast<unsigned>(value) & 1u) != 0)
      names.push_back(std::string(name));
  }
  d.reply[key] = names;
}

void maybe_flag(Declared& d, const char* key, bool Capabilities::*field) {
  if (!*rc::gen::arbitrary<bool>())
    return;
  const bool on = *rc::gen::arbitrary<bool>();
  d.caps.*field = on;
  d.reply[key] = on;
}

Declared random_declaration() {
  Declared d;
  maybe_names<PrimitiveType>(d, "primitives", &Capabilities::primitives);
  maybe_names<LineMode>(d, "line_modes", &Capabilities::line_modes);
  maybe_names<FillConvention>(d, "fill_conventions", &Capabilities::fill);
  maybe_names<PatternKind>(d, "sample_patterns", &Capabilities::patterns);
  if (*rc::gen::arbitrary<bool>()) {
    const auto bits = *rc::gen::inRange<std::uint32_t>(1u, 32u);
    d.caps.sample_counts = bits;
    nlohmann::json counts = nlohmann::json::array();
    for (unsigned i = 0; i < 5; ++i) {
      if ((bits >> i & 1u) != 0)
        counts.push_back(1u << i);
    }
    d.reply["sample_counts"] = counts;
  }
  maybe_flag(d, "antialiased_lines", &Capabilities::antialiased_lines);
  maybe_flag(d, "sample_mask", &Capabilities::sample_mask);
  maybe_flag(d, "sample_shading", &Capabilities::sample_shading);
  maybe_flag(d, "pipeline", &Capabilities::pipeline);
  if (*rc::gen::arbitrary<bool>()) {
    d.caps.max_target_side = *rc::gen::inRange(1, 20);
    d.reply["max_target_side"] = d.caps.max_target_side;
  }
  return d;
}

bool same(const Capabilities& a, const Capabilities& b) {
  return a.primitives == b.primitives && a.line_modes == b.line_modes && a.fill == b.fill &&
         a.patterns == b.patterns && a.sample_counts == b.sample_counts &&
         a.antialiased_lines == b.antialiased_lines && a.sample_mask == b.sample_mask &&
         a.sample_shading == b.sample_shading && a.pipeline == b.pipeline &&
         a.max_target_side == b.max_target_side && a.subpixel_bits == b.subpixel_bits;
}

// The spec's list, written independently of undeclared().
bool declared(const Capabilities& c, const Scene& s) {
  const auto in = [](std::uint32_t bits, unsigned i) { return i < 32 && (bits >> i & 1u) != 0; };
  bool ok = (c.pipeline || !has_pipeline_state(s)) && s.width <= c.max_target_side &&
            s.height <= c.max_target_side;
  const std::uint32_t n = s.msaa.count();
  unsigned log2n = 0;
  while ((1u << log2n) < n)
    ++log2n;
  ok = ok && (1u << log2n) == n && in(c.sample_counts, log2n);
  ok = ok && in(c.patterns, static_cast<unsigned>(s.msaa.pattern.kind));
  ok = ok && (c.sample_mask || s.msaa.effective_mask() == full_mask(n));
  ok = ok && (c.sample_shading || s.msaa.shading != ShadingRate::kSample);
  for (const Primitive& p : s.primitives) {
    ok = ok && in(c.primitives, static_cast<unsigned>(p.type));
    if (p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip) {
      ok = ok && in(c.line_modes, static_cast<unsigned>(s.conventions.line_mode));
      ok = ok && (c.antialiased_lines || !p.aa);
    }
    if (p.type == PrimitiveType::kTriangle)
      ok = ok && in(c.fill, static_cast<unsigned>(s.conventions.fill));
  }
  return ok;
}

// A driver with a declaration: the reference's coverage, the external driver's choices.
class DeclaredDriver final : public Driver {
public:
  explicit DeclaredDriver(Capabilities caps) : caps_(caps) {
    info_ = open_driver("reference", nullptr)->info();
    apply_capabilities(caps_, info_);
  }
  [[nodiscard]] const DriverInfo& info() const override { return info_; }
  [[nodiscard]] std::string unsupported(const Scene& s) const override {
    return undeclared(caps_, s);
  }
  [[nodiscard]] DrawResult draw(const Scene&) override { return std::vector<Fragment>{}; }

private:
  Capabilities caps_;
  DriverInfo info_;
};

// rule: DRIVER.EXTERNAL.CAPABILITIES
RC_GTEST_PROP(DriverCapabilities, AReplyReadsBackAsItsDeclaration, ()) {
  const Declared d = random_declaration();
  const auto parsed = parse_capabilities(nlohmann::json{{"capabilities", d.reply}}.dump());
  RC_ASSERT(std::holds_alternative<Capabilities>(parsed));
  RC_ASSERT(same(std::get<Capabilities>(parsed), d.caps));
}

// rule: DRIVER.EXTERNAL.CAPABILITIES, FUZZ.GENERATE
RC_GTEST_PROP(DriverCapabilities, UndeclaredIsTheSpecsListOnTheCampaignsScenes, ()) {
  const Declared d = random_declaration();
  const auto full = open_driver("reference", nullptr);
  const auto profile = *rc::gen::element(fuzzer::Profile::kD3D11, fuzzer::Profile::kVulkan);
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  int refused = 0;
  for (std::uint64_t i = 0; i < 8; ++i) {
    const auto c = fuzzer::generate_case(seed, i, profile, *full);
    RC_ASSERT(c.has_value());
    const bool yes = declared(d.caps, c->scene);
    RC_ASSERT(yes == undeclared(d.caps, c->scene).empty());
    refused += yes ? 0 : 1;
  }
  RC_CLASSIFY(refused == 0, "all declared");
  RC_CLASSIFY(refused == 8, "none declared");
}

// rule: DRIVER.EXTERNAL.CAPABILITIES, FUZZ.GENERATE
RC_GTEST_PROP(DriverCapabilities, CampaignsSendOnlyDeclaredScenesAndSomeWhenTrianglesAre, ()) {
  const Declared d = random_declaration();
  DeclaredDriver driver(d.caps);
  const auto profile = *rc::gen::element(fuzzer::Profile::kD3D11, fuzzer::Profile::kVulkan);
  const auto seed = *rc::gen::inRange<std::uint64_t>(0, 1u << 20);
  int sent = 0;
  for (std::uint64_t i = 0; i < 8; ++i) {
    if (const auto c = fuzzer::generate_case(seed, i, profile, driver)) {
      RC_ASSERT(declared(d.caps, c->scene));
      ++sent;
    }
  }
  // A plain single-sample triangle scene of this profile (standard pattern, full mask, pixel
  // shading, no pipeline state, targets up to 16 px) is declared: then cases are generated.
  Scene plain;
  plain.width = plain.height = 16;
  fuzzer::apply_profile(profile, plain);
  plain.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  if (declared(d.caps, plain))
    RC_ASSERT(sent > 0);
  RC_CLASSIFY(sent == 0, "nothing sent");
}

} // namespace
} // namespace rastrules::driver
