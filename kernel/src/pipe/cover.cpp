// SPDX-License-Identifier: MIT
// Stage 4 of run_pipeline: the coverage of every prepared primitive by the kernel's own rules,
// inside the viewport's scissor and the fragment limit, straight into the result; then each
// fragment linked to the drawn primitive (a strip's segment) it is shaded from.
// Implements: PIPE.VIEWPORT.SCISSOR, SCENE.INPUT.LIMITS, LINE.STRIP.SEQUENCE
#include <string>

#include "stages.hpp"

namespace rastrules::pipe::detail {

namespace {

struct Stop {
  SceneError error;
};

} // namespace

// rule: PIPE.VIEWPORT.SCISSOR, SCENE.INPUT.LIMITS
std::optional<SceneError> cover(const PreparedScene& ps, const std::vector<Source>& sources,
                                const ScissorRect& scissor, const PipeOptions& o,
                                std::vector<Fragment>& fragments) {
  // rule: SCENE.INPUT.LIMITS
  // The work limit, before any primitive is rasterized.
  if (const auto p = first_primitive_over_work(ps, o.max_work))
    return SceneError{idx("primitives", sources.empty() ? *p : sources[*p].prim),
                      work_limit_problem(o.max_work), SceneError::Kind::kWorkLimit};
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    const std::size_t prim = sources.empty() ? p : sources[p].prim;
    const auto emit = [&](const Fragment& f) {
      if (!scissor.contains(f.x, f.y))
        return;
      if (fragments.size() >= o.max_fragments)
        throw Stop{SceneError{idx("primitives", prim),
                              "the scene produces more than " + std::to_string(o.max_fragments) +
                                  " fragments (limit SCENE.INPUT.LIMITS)",
                              SceneError::Kind::kFragmentLimit}};
      fragments.push_back(f);
    };
    try {
      if (!for_each_fragment_bounded(ps, p, o.max_fragments, o.render, emit))
        return SceneError{idx("primitives", prim),
                          "touches more than " + std::to_string(o.max_fragments) +
                              " pixels or fragments that must be held to be sorted (limit "
                              "SCENE.INPUT.LIMITS)",
                          SceneError::Kind::kFragmentLimit};
    } catch (Stop& stop) {
      return stop.error;
    }
  }
  return std::nullopt;
}

// rule: LINE.STRIP.SEQUENCE
Links link(const std::vector<Source>& sources, std::vector<Fragment>& fragments,
           std::vector<FragmentData>& data) {
  Links l;
  l.first_drawn.assign(sources.size() + 1, 0);
  for (std::size_t p = 0; p < sources.size(); ++p)
    l.first_drawn[p + 1] = l.first_drawn[p] + sources[p].flat.size();
  l.drawn_of.resize(fragments.size());
  data.resize(fragments.size());
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    Fragment& f = fragments[i];
    const Source& src = sources[f.prim];
    const std::size_t segment = f.seg && *f.seg < src.flat.size() ? *f.seg : 0;
    l.drawn_of[i] = static_cast<std::uint32_t>(l.first_drawn[f.prim] + segment);
    data[i].drawn = l.drawn_of[i];
    f.prim = static_cast<std::uint32_t>(src.prim);
    data[i].part = src.part;
    data[i].passed = f.mask;
  }
  return l;
}

} // namespace rastrules::pipe::detail
