// SPDX-License-Identifier: MIT
// rastrules._core: the Python binding (python/README.md) of the library's one scene type, its one
// reader and writer (rastrules::io), the one data flow (pipe::run_pipeline, which render()
// and `rastrules render` run), the fragment JSON writer and `rastrules explain`
// (rastrules_cli_core). No rule is decided here: every value comes from those functions.
// Implements: SCENE.INPUT.ERRORS (bad input raises ValueError with the reader's one line)

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cli.hpp"
#include "rastrules/io/explain.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/profile.hpp"
#include "rastrules/scene.hpp"

namespace py = pybind11;

namespace rastrules::python {
namespace {

// The reader's error as one line: "FIELD: PROBLEM", or "ORIGIN: PROBLEM" for malformed JSON
// (no field), as `rastrules render` names the file.
// rule: SCENE.INPUT.ERRORS
[[noreturn]] void raise(const SceneError& e, const std::string& origin) {
  throw py::value_error(e.field.empty() ? origin + ": " + e.message : e.what());
}

Scene scene_from_text(std::string_view text, const std::string& origin) {
  auto scene = io::read_scene(text);
  if (auto* e = std::get_if<SceneError>(&scene))
    raise(*e, origin);
  return std::move(std::get<Scene>(scene));
}

Scene scene_from_file(const std::string& path) {
  auto text = io::read_scene_file(path);
  if (auto* e = std::get_if<SceneError>(&text))
    raise(*e, path);
  return scene_from_text(std::get<std::string>(text), path);
}

// The limits of one render (SCENE.INPUT.LIMITS): `rastrules render`'s defaults, raised or
// lowered by render(..., max_fragments=N, max_work=N).
struct Limits {
  std::uint64_t max_fragments = io::kDefaultMaxFragments;
  std::uint64_t max_work = kDefaultMaxWork;
};

// A limit's error as the command line words it, with the keyword argument that raises it.
// rule: SCENE.INPUT.LIMITS
[[noreturn]] void raise_limit(const std::string& message, SceneError::Kind kind) {
  throw py::value_error(
      message + (kind == SceneError::Kind::kWorkLimit       ? "; raise it with max_work=N"
                 : kind == SceneError::Kind::kFragmentLimit ? "; raise it with max_fragments=N"
                                                            : ""));
}

// run_pipeline as `rastrules render` runs a scene with pipeline state: every optimization on,
// the limits given. The GIL is released while it runs.
// rule: SCENE.INPUT.LIMITS, PIPE.EFFECTS.ON_DEMAND
void check_threads(unsigned threads) {
  if (threads < 1)
    throw py::value_error("threads: must be at least 1");
}

pipe::PipeResult run(const Scene& scene, unsigned threads, const Limits& limits) {
  check_threads(threads);
  pipe::PipeOptions o;
  o.render.threads = threads;
  o.max_fragments = limits.max_fragments;
  o.max_work = limits.max_work;
  std::variant<pipe::PipeResult, SceneError> result;
  {
    py::gil_scoped_release release;
    result = pipe::run_pipeline(scene, o);
  }
  if (auto* e = std::get_if<SceneError>(&result)) {
    if (e->kind != SceneError::Kind::kInput)
      raise_limit(e->what(), e->kind);
    raise(*e, "scene");
  }
  return std::move(std::get<pipe::PipeResult>(result));
}

// A scene without pipeline state, drawn as `rastrules render` draws it on one thread: prepared,
// the work limit checked before anything is drawn, then each primitive's fragments streamed in
// output order (a triangle's as the traversal finds them), the fragment limit counted as they
// come. Nothing of the kernel's fragment list is held: emit keeps what it needs. The GIL is
// released while it runs (emit must not touch Python objects).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.LIMITS
void stream(const Scene& scene, const Limits& limits,
            const std::function<void(const Fragment&)>& emit) {
  auto prepared = prepare(scene);
  if (auto* e = std::get_if<SceneError>(&prepared))
    raise(*e, "scene");
  std::optional<SceneError> limit;
  {
    py::gil_scoped_release release;
    limit = stream_within_limits(std::get<PreparedScene>(prepared), limits.max_fragments,
                                 limits.max_work, emit);
  }
  if (limit)
    raise_limit(limit->message, limit->kind);
}

// The fragment list exactly as `rastrules render SCENE --fragments -` writes it, by the same
// writer (io::FragmentWriter, into memory).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.PIPELINE
std::string fragments_text(const Scene& scene, unsigned threads, const Limits& limits) {
  check_threads(threads);
  if (has_pipeline_state(scene)) {
    const pipe::PipeResult r = run(scene, threads, limits);
    auto text = io::pipe_fragments_to_json(r.fragments, r.data, io::pipe_output_fields(scene));
    if (!text)
      throw std::logic_error("run_pipeline's fragments do not match the scene's output fields");
    return std::move(*text);
  }
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  if (out == nullptr)
    throw std::bad_alloc();
  bool ok = true;
  try {
    io::FragmentWriter writer(out);
    stream(scene, limits, [&](const Fragment& f) { ok = writer.add(f) && ok; });
    ok = writer.finish() && ok;
  } catch (...) {
    std::fclose(out);
    std::free(buffer);
    throw;
  }
  std::fclose(out);
  std::string text(buffer, size);
  std::free(buffer);
  if (!ok)
    throw std::logic_error("the kernel emitted fragments out of (prim, y, x, seg) order");
  return text;
}

template <class T> py::array_t<T> array_of(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

// The fragments as columns (rastrules/__init__.py makes the structured array of them): the
// plain fields always, a path's exact area when a fragment has one. A missing optional value is
// -1 (integers) or NaN.
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA, SCENE.OUTPUT.AREA
struct Columns {
  std::vector<std::uint32_t> prim, mask;
  std::vector<std::int32_t> x, y, seg, sample;
  std::vector<bool> helper;
  std::vector<double> coverage, area;
  std::vector<std::uint8_t> alpha;

  void add(const Fragment& f) {
    if (f.area && area.size() < prim.size()) { // the first fragment with an area
      area.resize(prim.size(), std::numeric_limits<double>::quiet_NaN());
      alpha.resize(prim.size(), 0);
    }
    prim.push_back(f.prim);
    x.push_back(f.x);
    y.push_back(f.y);
    mask.push_back(f.mask);
    seg.push_back(f.seg ? static_cast<std::int32_t>(*f.seg) : -1);
    sample.push_back(f.sample ? static_cast<std::int32_t>(*f.sample) : -1);
    helper.push_back(f.helper);
    // coverage_q16 / 65536 is exact in a double (SCENE.OUTPUT.COVERAGE).
    coverage.push_back(f.coverage_q16 ? static_cast<double>(*f.coverage_q16) / 65536.0
                                      : std::numeric_limits<double>::quiet_NaN());
    if (!area.empty() || f.area) {
      area.push_back(f.area ? f.area.approx() : std::numeric_limits<double>::quiet_NaN());
      alpha.push_back(f.area ? f.area.alpha() : std::uint8_t{0});
    }
  }

  [[nodiscard]] py::dict to_dict() const {
    py::dict out;
    out["prim"] = array_of(prim);
    out["x"] = array_of(x);
    out["y"] = array_of(y);
    out["mask"] = array_of(mask);
    out["seg"] = array_of(seg);
    out["sample"] = array_of(sample);
    py::array_t<bool> h(static_cast<py::ssize_t>(helper.size()));
    auto H = h.mutable_unchecked<1>();
    for (std::size_t i = 0; i < helper.size(); ++i)
      H(static_cast<py::ssize_t>(i)) = helper[i];
    out["helper"] = h;
    out["coverage"] = array_of(coverage);
    if (!area.empty()) {
      out["area"] = array_of(area);
      out["alpha"] = array_of(alpha);
    }
    return out;
  }
};

// The columns of a scene's fragments, and for a pipeline scene what its fragments carry
// (SCENE.OUTPUT.PIPELINE) as more columns: "part", "passed", "attr" (n x attributes) and
// "depth" (n x samples, NaN for samples outside the mask; d16 and d24 as their UNORM
// integers, d32f as the float).
// rule: SCENE.OUTPUT.PIPELINE
py::dict columns(const Scene& scene, unsigned threads, const Limits& limits) {
  check_threads(threads);
  const io::PipeOutputFields fields = io::pipe_output_fields(scene);
  const std::uint32_t samples = scene.msaa.count();
  Columns c;
  if (!has_pipeline_state(scene)) {
    stream(scene, limits, [&](const Fragment& f) { c.add(f); });
    py::dict out = c.to_dict();
    out["samples"] = samples;
    out["attribute_names"] = fields.attributes;
    return out;
  }
  const pipe::PipeResult r = run(scene, threads, limits);
  for (const Fragment& f : r.fragments)
    c.add(f);
  py::dict out = c.to_dict();
  out["samples"] = samples;
  out["attribute_names"] = fields.attributes;
  const std::size_t n = r.fragments.size();
  if (r.data.empty())
    return out;
  if (r.data.size() != n)
    throw std::logic_error("run_pipeline's fragment data do not match its fragments");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto part = py::array_t<std::int32_t>(static_cast<py::ssize_t>(n));
  auto passed = py::array_t<std::uint32_t>(static_cast<py::ssize_t>(n));
  const std::size_t k = fields.attributes.size();
  py::array_t<float> attr({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(k)});
  py::array_t<double> depth(
      {static_cast<py::ssize_t>(fields.depth ? n : 0), static_cast<py::ssize_t>(samples)});
  auto T = part.mutable_unchecked<1>();
  auto Q = passed.mutable_unchecked<1>();
  auto V = attr.mutable_unchecked<2>();
  auto D = depth.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const pipe::FragmentData& d = r.data[i];
    const auto j = static_cast<py::ssize_t>(i);
    T(j) = d.part ? static_cast<std::int32_t>(*d.part) : -1;
    Q(j) = d.passed;
    for (std::size_t a = 0; a < k; ++a) {
      V(j, static_cast<py::ssize_t>(a)) =
          a < d.attr.size() ? d.attr[a] : std::numeric_limits<float>::quiet_NaN();
    }
    if (!fields.depth)
      continue;
    // One depth per sample of the mask, ascending (FragmentData::depth), at its sample index.
    for (std::uint32_t s = 0; s < samples; ++s)
      D(j, static_cast<py::ssize_t>(s)) = nan;
    std::size_t next = 0;
    for (std::uint32_t s = 0; s < samples && next < d.depth.size(); ++s) {
      if (((r.fragments[i].mask >> s) & 1u) == 0)
        continue;
      const pipe::DepthValue& v = d.depth[next++];
      D(j, static_cast<py::ssize_t>(s)) = *fields.depth == pipe::DepthFormat::kD32F
                                              ? static_cast<double>(v.f)
                                              : static_cast<double>(v.unorm);
    }
  }
  out["part"] = part;
  out["passed"] = passed;
  if (k > 0)
    out["attr"] = attr;
  if (fields.depth) {
    out["depth"] = depth;
    out["depth_format"] = std::string(io::depth_format_name(*fields.depth));
  }
  return out;
}

// `rastrules explain SCENE --pixel X,Y [--json]`, on a scene in memory.
// rule: SCENE.INPUT.ERRORS, SCENE.OUTPUT.PIPELINE
std::string explain(const Scene& scene, std::int32_t x, std::int32_t y, bool as_json) {
  auto loaded = cli::load_scene(scene);
  if (auto* e = std::get_if<SceneError>(&loaded))
    raise(*e, "scene");
  const auto& l = std::get<cli::LoadedScene>(loaded);
  std::optional<pipe::PipeResult> result;
  if (!l.prepared)
    result = run(l.scene, 1, Limits{});
  if (x < 0 || y < 0 || x >= scene.width || y >= scene.height) {
    throw py::value_error("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                          ") is outside the " + std::to_string(scene.width) + "x" +
                          std::to_string(scene.height) + " target");
  }
  if (!result)
    return io::explain_window_pixel(l.scene, *l.prepared, x, y, as_json);
  auto text = io::explain_pipeline_pixel(l.scene, *result, x, y, as_json);
  if (auto* e = std::get_if<SceneError>(&text))
    raise(*e, "scene");
  return std::move(std::get<std::string>(text));
}

ProfileName profile_named(const std::string& name) {
  const auto p = from_name<ProfileName>(name);
  if (!p) {
    std::string known;
    for (const auto& entry : Names<ProfileName>::table)
      known += (known.empty() ? "" : ", ") + std::string(entry.first);
    throw py::value_error("profile: unknown profile \"" + io::printable(name, 40) + "\" (" + known +
                          ")");
  }
  return *p;
}

} // namespace
} // namespace rastrules::python

PYBIND11_MODULE(_core, m) {
  using namespace rastrules;
  using namespace rastrules::python;
  m.doc() = "rastrules' C++ library (the kernel, the scene reader and writer, the pipeline, "
            "explain); use the package rastrules, which wraps it.";
  m.attr("__version__") = RASTRULES_VERSION_TEXT;

  py::class_<Scene>(m, "Scene", R"doc(
A scene (spec/scene.md): the target, its conventions, the primitives and any pipeline state.

Made by rastrules.read_scene() from JSON text, a file or a dict; read by the same strict reader
as the command line, so bad input raises ValueError with its one-line message.)doc")
      .def_static(
          "from_json", [](std::string_view text) { return scene_from_text(text, "<string>"); },
          py::arg("text"), "Reads a scene from JSON text (ValueError on bad input).")
      .def_static("from_file", &scene_from_file, py::arg("path"),
                  "Reads a scene file ('-' is standard input; ValueError on bad input).")
      .def("to_json", &io::write_scene,
           "The scene as scene-file text, as the command line writes it (reads back to an "
           "equal scene).")
      .def_property_readonly("width", [](const Scene& s) { return s.width; })
      .def_property_readonly("height", [](const Scene& s) { return s.height; })
      .def_property_readonly(
          "samples", [](const Scene& s) { return s.msaa.count(); },
          "The samples per pixel (1 without multisampling).")
      .def_property_readonly(
          "has_pipeline", [](const Scene& s) { return has_pipeline_state(s); },
          "Whether the scene has pipeline state (SCENE.PIPELINE).")
      .def(
          "__len__", [](const Scene& s) { return s.primitives.size(); },
          "The number of primitives.")
      .def(
          "apply_profile",
          [](Scene& s, const std::string& name) { apply(profile(profile_named(name)), s); },
          py::arg("name"),
          "Sets every convention of the named profile (rastrules.profiles(); "
          "spec/rules/profile.md) in place.")
      .def(
          "copy", [](const Scene& s) { return Scene(s); }, "A copy of the scene.")
      .def("__eq__", [](const Scene& a, const Scene& b) { return io::same_scene(a, b); })
      .def("__repr__", [](const Scene& s) {
        return "<rastrules.Scene " + std::to_string(s.width) + "x" + std::to_string(s.height) +
               ", " + std::to_string(s.primitives.size()) + " primitives>";
      });

  // render_columns and render_json take the same arguments: render()'s.
  const auto def_render = [&m](const char* name, auto draw, const char* doc) {
    m.def(
        name,
        [draw](const Scene& s, unsigned threads, std::uint64_t max_fragments,
               std::uint64_t max_work) {
          return draw(s, threads, Limits{max_fragments, max_work});
        },
        py::arg("scene"), py::arg("threads") = 1,
        py::arg("max_fragments") = io::kDefaultMaxFragments, py::arg("max_work") = kDefaultMaxWork,
        doc);
  };
  def_render("render_columns", &columns,
             "The scene's fragments as a dict of NumPy columns (rastrules.render() makes the "
             "structured array).");
  def_render("render_json", &fragments_text,
             "The fragment list exactly as `rastrules render SCENE --fragments -` writes it.");
  m.def("explain", &explain, py::arg("scene"), py::arg("x"), py::arg("y"),
        py::arg("as_json") = false, "What `rastrules explain SCENE --pixel X,Y [--json]` prints.");
  m.def(
      "profiles",
      [] {
        std::vector<std::string> names;
        for (const auto& entry : Names<ProfileName>::table)
          names.emplace_back(entry.first);
        return names;
      },
      "The profile names (spec/rules/profile.md).");
}
