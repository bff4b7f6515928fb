// SPDX-License-Identifier: MIT
// The C API (rastrules/rastrules.h) over the C++ library: the scene reader (io::read_scene),
// the kernel's prepare() and streamed fragments, the pipeline (pipe::run_pipeline) and the
// explanation (io::explain_*_pixel), composed as `rastrules render` and `rastrules explain`
// compose them. No rule is decided here. Every entry point catches every exception.
// Implements: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS (the C API's part: codes and messages)

#include "rastrules/rastrules.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "rastrules/io/explain.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/profile.hpp"
#include "rastrules/scene.hpp"

// The handles: a scene as read (and prepared when it has no pipeline state, as the command
// line's load_scene keeps it), and a render's fragments with their values in flat arrays.
struct rr_scene {
  rastrules::Scene scene;
  std::optional<rastrules::PreparedScene> prepared;
};

struct rr_render {
  std::vector<rastrules::Fragment> fragments;
  std::vector<rastrules::pipe::FragmentData> data; // empty, or one per fragment
  bool has_depth = false;
  rastrules::pipe::DepthFormat depth_format = rastrules::pipe::DepthFormat::kD32F;
  // Per fragment: where its depths start in depth_values, and where its area text starts in
  // area_texts (NUL-separated); filled at render time so that rr_fragment's pointers stay put.
  std::vector<std::size_t> depth_start;
  std::vector<double> depth_values;
  std::vector<std::size_t> area_start;
  std::string area_texts;
};

namespace {

using rastrules::Scene;
using rastrules::SceneError;

// The message of the last failed call on this thread (rr_last_error).
thread_local std::string t_message;
thread_local const char* t_message_ptr = "";

constexpr const char* kNoMemoryForMessage = "out of memory (the error message could not be kept)";

rr_status ok() {
  t_message.clear();
  t_message_ptr = "";
  return RR_OK;
}

rr_status fail(rr_status status, std::string_view message) noexcept {
  try {
    t_message.assign(message);
    t_message_ptr = t_message.c_str();
  } catch (...) {
    t_message_ptr = kNoMemoryForMessage;
  }
  return status;
}

// "FUNCTION: PREFIX WHAT" as the message, without letting an allocation failure escape (the
// handlers of guarded() run where memory may have run out).
rr_status fail_in_handler(rr_status status, const char* function, const char* prefix,
                          const char* what) noexcept {
  try {
    t_message = function;
    t_message += ": ";
    t_message += prefix;
    t_message += what;
    t_message_ptr = t_message.c_str();
  } catch (...) {
    t_message_ptr = kNoMemoryForMessage;
  }
  return status;
}

// Runs f, turning every exception into a status: no exception crosses the C interface.
template <class F> rr_status guarded(const char* function, F&& f) noexcept {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    return fail_in_handler(RR_ERROR_OUT_OF_MEMORY, function, "", "out of memory");
  } catch (const std::exception& e) {
    return fail_in_handler(RR_ERROR_INTERNAL, function, "internal error: ", e.what());
  } catch (...) {
    return fail_in_handler(RR_ERROR_INTERNAL, function, "internal error", "");
  }
}

// RR_ERROR_NULL_ARGUMENT naming the first of the pointers that is NULL; RR_OK when none is.
rr_status non_null(const char* function,
                   std::initializer_list<std::pair<const char*, const void*>> pointers) {
  for (const auto& [name, p] : pointers) {
    if (p == nullptr)
      return fail(RR_ERROR_NULL_ARGUMENT, std::string(function) + ": " + name + " is NULL");
  }
  return RR_OK;
}

// rule: SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
// A SceneError of the reader, the kernel or the pipeline as a status and its one-line message.
rr_status scene_error(const SceneError& e, std::string_view hint = {}) {
  const bool limit = e.kind != SceneError::Kind::kInput;
  return fail(limit ? RR_ERROR_LIMIT : RR_ERROR_BAD_SCENE, e.what() + std::string(hint));
}

// Reads and checks a scene; `name` replaces the empty field of a parse error ("(json)" or the
// file's path), as the command line names the file.
rr_status make_scene(std::string_view text, const std::string& name, rr_scene** out) {
  // rule: SCENE.INPUT.LIMITS
  if (text.size() > rastrules::io::kMaxSceneBytes) {
    return fail(RR_ERROR_BAD_SCENE,
                name + ": is larger than " + std::to_string(rastrules::io::kMaxSceneBytes >> 20) +
                    " MiB, the largest scene accepted (limit SCENE.INPUT.LIMITS)");
  }
  auto read = rastrules::io::read_scene(text);
  if (auto* err = std::get_if<SceneError>(&read)) {
    if (err->field.empty())
      return fail(RR_ERROR_BAD_SCENE, name + ": " + err->message);
    return scene_error(*err);
  }
  auto handle = std::make_unique<rr_scene>();
  handle->scene = std::move(std::get<Scene>(read));
  auto checked = rastrules::pipe::check_scene(handle->scene);
  if (auto* err = std::get_if<SceneError>(&checked))
    return scene_error(*err);
  handle->prepared = std::move(std::get<0>(checked));
  *out = handle.release();
  return ok();
}

// What the command line adds to a limit's message, in this interface's words.
// rule: SCENE.INPUT.LIMITS
constexpr std::string_view kWorkHint = "; raise it with rr_render_options.max_work";
constexpr std::string_view kFragmentHint = "; raise it with rr_render_options.max_fragments";

std::string_view hint_of(const SceneError& e) {
  return e.kind == SceneError::Kind::kWorkLimit       ? kWorkHint
         : e.kind == SceneError::Kind::kFragmentLimit ? kFragmentHint
                                                      : std::string_view{};
}

// run_pipeline with the limits of a render (as run_pipeline_or_report of the command line).
std::variant<rastrules::pipe::PipeResult, SceneError>
run_pipeline(const Scene& scene, std::uint64_t max_fragments, std::uint64_t max_work) {
  rastrules::pipe::PipeOptions o;
  o.max_fragments = max_fragments;
  o.max_work = max_work;
  return rastrules::pipe::run_pipeline(scene, o);
}

// Fills a render's flat arrays of depths and area texts.
void index_values(rr_render& r) {
  r.depth_start.reserve(r.fragments.size() + 1);
  r.area_start.reserve(r.fragments.size() + 1);
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    r.depth_start.push_back(r.depth_values.size());
    if (!r.data.empty()) {
      for (const rastrules::pipe::DepthValue& d : r.data[i].depth) {
        r.depth_values.push_back(r.depth_format == rastrules::pipe::DepthFormat::kD32F
                                     ? static_cast<double>(d.f)
                                     : static_cast<double>(d.unorm));
      }
    }
    r.area_start.push_back(r.area_texts.size());
    if (r.fragments[i].area) {
      r.area_texts += r.fragments[i].area.text();
      r.area_texts += '\0';
    }
  }
  r.depth_start.push_back(r.depth_values.size());
  r.area_start.push_back(r.area_texts.size());
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.LIMITS
// A scene without pipeline state, as `rastrules render` streams it (stream_within_limits).
rr_status render_window(const rastrules::PreparedScene& scene, std::uint64_t max_fragments,
                        std::uint64_t max_work, rr_render& r) {
  if (const auto e = rastrules::stream_within_limits(
          scene, max_fragments, max_work,
          [&](const rastrules::Fragment& f) { r.fragments.push_back(f); }))
    return fail(RR_ERROR_LIMIT, "render: " + e->message + std::string(hint_of(*e)));
  return RR_OK;
}

} // namespace

extern "C" {

const char* rr_version(void) {
  return RASTRULES_VERSION_STRING;
}

const char* rr_status_name(rr_status status) {
  switch (status) {
  case RR_OK:
    return "RR_OK";
  case RR_ERROR_NULL_ARGUMENT:
    return "RR_ERROR_NULL_ARGUMENT";
  case RR_ERROR_BAD_SCENE:
    return "RR_ERROR_BAD_SCENE";
  case RR_ERROR_LIMIT:
    return "RR_ERROR_LIMIT";
  case RR_ERROR_FILE:
    return "RR_ERROR_FILE";
  case RR_ERROR_OUT_OF_RANGE:
    return "RR_ERROR_OUT_OF_RANGE";
  case RR_ERROR_UNKNOWN_NAME:
    return "RR_ERROR_UNKNOWN_NAME";
  case RR_ERROR_OUT_OF_MEMORY:
    return "RR_ERROR_OUT_OF_MEMORY";
  case RR_ERROR_INTERNAL:
    return "RR_ERROR_INTERNAL";
  }
  return "unknown status";
}

const char* rr_last_error(void) {
  return t_message_ptr;
}

rr_status rr_scene_from_json(const char* text, size_t length, rr_scene** out) {
  return guarded("rr_scene_from_json", [&] {
    if (out != nullptr)
      *out = nullptr;
    if (const rr_status s = non_null("rr_scene_from_json", {{"out", out}, {"text", text}});
        s != RR_OK)
      return s;
    return make_scene(std::string_view(text, length), "(json)", out);
  });
}

rr_status rr_scene_from_file(const char* path, rr_scene** out) {
  return guarded("rr_scene_from_file", [&] {
    if (out != nullptr)
      *out = nullptr;
    if (const rr_status s = non_null("rr_scene_from_file", {{"out", out}, {"path", path}});
        s != RR_OK)
      return s;
    const std::string name = path;
    auto text = rastrules::io::read_scene_file(name);
    if (auto* err = std::get_if<SceneError>(&text))
      return fail(RR_ERROR_FILE, err->what());
    return make_scene(std::get<std::string>(text), name == "-" ? "<stdin>" : name, out);
  });
}

rr_status rr_scene_set_profile(rr_scene* scene, const char* name) {
  return guarded("rr_scene_set_profile", [&] {
    if (const rr_status s = non_null("rr_scene_set_profile", {{"scene", scene}, {"name", name}});
        s != RR_OK)
      return s;
    const auto p = rastrules::from_name<rastrules::ProfileName>(name);
    if (!p) {
      return fail(RR_ERROR_UNKNOWN_NAME, "rr_scene_set_profile: unknown profile \"" +
                                             rastrules::io::printable(name, 40) +
                                             "\" (d3d11, vulkan, opengl)");
    }
    // rule: PROFILE.CONVENTIONS
    Scene changed = scene->scene;
    rastrules::apply(rastrules::profile(*p), changed);
    auto checked = rastrules::pipe::check_scene(changed);
    if (auto* err = std::get_if<SceneError>(&checked))
      return scene_error(*err);
    scene->scene = std::move(changed);
    scene->prepared = std::move(std::get<0>(checked));
    return ok();
  });
}

rr_status rr_scene_get_info(const rr_scene* scene, rr_scene_info* out) {
  return guarded("rr_scene_get_info", [&] {
    if (const rr_status s = non_null("rr_scene_get_info", {{"scene", scene}, {"out", out}});
        s != RR_OK)
      return s;
    const Scene& s = scene->scene;
    *out = rr_scene_info{};
    out->width = s.width;
    out->height = s.height;
    out->primitives = static_cast<std::uint32_t>(s.primitives.size());
    out->samples = s.msaa.count();
    out->pipeline = scene->prepared ? 0 : 1;
    out->has_depth = s.depth ? 1 : 0;
    out->attributes = static_cast<std::uint32_t>(s.attributes.size());
    return ok();
  });
}

void rr_scene_free(rr_scene* scene) {
  delete scene;
}

rr_status rr_render_scene(const rr_scene* scene, const rr_render_options* options,
                          rr_render** out) {
  return guarded("rr_render_scene", [&] {
    if (out != nullptr)
      *out = nullptr;
    if (const rr_status s = non_null("rr_render_scene", {{"out", out}, {"scene", scene}});
        s != RR_OK)
      return s;
    // rule: SCENE.INPUT.LIMITS
    std::uint64_t max_fragments = rastrules::io::kDefaultMaxFragments;
    std::uint64_t max_work = rastrules::kDefaultMaxWork;
    if (options != nullptr && options->max_fragments != 0)
      max_fragments = options->max_fragments;
    if (options != nullptr && options->max_work != 0)
      max_work = options->max_work;
    auto r = std::make_unique<rr_render>();
    if (scene->prepared) {
      if (const rr_status s = render_window(*scene->prepared, max_fragments, max_work, *r);
          s != RR_OK)
        return s;
    } else {
      // rule: SCENE.OUTPUT.PIPELINE
      auto result = run_pipeline(scene->scene, max_fragments, max_work);
      if (auto* err = std::get_if<SceneError>(&result))
        return scene_error(*err, hint_of(*err));
      auto& piped = std::get<rastrules::pipe::PipeResult>(result);
      if (piped.fragments.size() > max_fragments) {
        return fail(RR_ERROR_LIMIT, "render: more than " + std::to_string(max_fragments) +
                                        " fragments (limit SCENE.INPUT.LIMITS)" +
                                        std::string(kFragmentHint));
      }
      if (!piped.data.empty() && piped.data.size() != piped.fragments.size())
        return fail(RR_ERROR_INTERNAL, "rr_render_scene: internal error: fragment data");
      r->fragments = std::move(piped.fragments);
      r->data = std::move(piped.data);
      r->has_depth = scene->scene.depth.has_value();
      r->depth_format = scene->scene.conventions.depth;
    }
    index_values(*r);
    *out = r.release();
    return ok();
  });
}

rr_status rr_render_fragment_count(const rr_render* render, size_t* count) {
  return guarded("rr_render_fragment_count", [&] {
    if (const rr_status s =
            non_null("rr_render_fragment_count", {{"render", render}, {"count", count}});
        s != RR_OK)
      return s;
    *count = render->fragments.size();
    return ok();
  });
}

rr_status rr_render_fragment(const rr_render* render, size_t index, rr_fragment* out) {
  return guarded("rr_render_fragment", [&] {
    if (const rr_status s = non_null("rr_render_fragment", {{"render", render}, {"out", out}});
        s != RR_OK)
      return s;
    if (index >= render->fragments.size()) {
      return fail(RR_ERROR_OUT_OF_RANGE, "rr_render_fragment: index " + std::to_string(index) +
                                             " is not below the fragment count " +
                                             std::to_string(render->fragments.size()));
    }
    const rastrules::Fragment& f = render->fragments[index];
    rr_fragment o{};
    o.prim = f.prim;
    o.x = f.x;
    o.y = f.y;
    o.mask = f.mask;
    if (f.seg) {
      o.flags |= RR_FRAGMENT_SEG;
      o.seg = *f.seg;
    }
    if (f.sample) {
      o.flags |= RR_FRAGMENT_SAMPLE;
      o.sample = *f.sample;
    }
    if (f.helper)
      o.flags |= RR_FRAGMENT_HELPER;
    if (f.coverage_q16) {
      o.flags |= RR_FRAGMENT_COVERAGE;
      o.coverage_q16 = *f.coverage_q16;
    }
    if (f.centroid) {
      o.flags |= RR_FRAGMENT_CENTROID;
      o.centroid_x = f.centroid->offset.x;
      o.centroid_y = f.centroid->offset.y;
    }
    if (f.derivatives) {
      o.flags |= RR_FRAGMENT_DERIVATIVES;
      o.ddx_x = f.derivatives->ddx_x;
      o.ddx_y = f.derivatives->ddx_y;
      o.ddy_x = f.derivatives->ddy_x;
      o.ddy_y = f.derivatives->ddy_y;
    }
    // rule: SCENE.OUTPUT.AREA
    if (f.area) {
      o.flags |= RR_FRAGMENT_AREA;
      o.area = f.area.approx();
      o.alpha = f.area.alpha();
      o.area_text = render->area_texts.data() + render->area_start[index];
    }
    o.passed = f.mask;
    // rule: SCENE.OUTPUT.PIPELINE
    if (!render->data.empty()) {
      const rastrules::pipe::FragmentData& d = render->data[index];
      if (d.part) {
        o.flags |= RR_FRAGMENT_PART;
        o.part = *d.part;
      }
      if (d.bary) {
        o.flags |= RR_FRAGMENT_BARY;
        for (std::size_t k = 0; k < 3; ++k)
          o.bary[k] = d.bary->e[k];
        o.bary_area = d.bary->area;
      }
      o.passed = d.passed;
      o.attr_count = d.attr.size();
      o.attr = d.attr.empty() ? nullptr : d.attr.data();
      if (render->has_depth) {
        o.flags |= RR_FRAGMENT_DEPTH;
        o.depth_count = render->depth_start[index + 1] - render->depth_start[index];
        o.depth =
            o.depth_count == 0 ? nullptr : render->depth_values.data() + render->depth_start[index];
      }
    }
    *out = o;
    return ok();
  });
}

void rr_render_free(rr_render* render) {
  delete render;
}

rr_status rr_explain(const rr_scene* scene, int32_t x, int32_t y, int as_json, char** out) {
  return guarded("rr_explain", [&] {
    if (out != nullptr)
      *out = nullptr;
    if (const rr_status s = non_null("rr_explain", {{"out", out}, {"scene", scene}}); s != RR_OK)
      return s;
    const Scene& s = scene->scene;
    // rule: SCENE.INPUT.ERRORS
    if (x < 0 || y < 0 || x >= s.width || y >= s.height) {
      return fail(RR_ERROR_OUT_OF_RANGE, "rr_explain: (" + std::to_string(x) + ", " +
                                             std::to_string(y) + ") is outside the " +
                                             std::to_string(s.width) + "x" +
                                             std::to_string(s.height) + " target");
    }
    std::string text;
    if (scene->prepared) {
      text = rastrules::io::explain_window_pixel(s, *scene->prepared, x, y, as_json != 0);
    } else {
      // rule: SCENE.OUTPUT.PIPELINE
      auto result =
          run_pipeline(s, rastrules::io::kDefaultMaxFragments, rastrules::kDefaultMaxWork);
      if (auto* err = std::get_if<SceneError>(&result))
        return scene_error(*err);
      auto explained = rastrules::io::explain_pipeline_pixel(
          s, std::get<rastrules::pipe::PipeResult>(result), x, y, as_json != 0);
      if (auto* err = std::get_if<SceneError>(&explained))
        return fail(RR_ERROR_INTERNAL, "rr_explain: " + err->message);
      text = std::move(std::get<std::string>(explained));
    }
    char* copy = static_cast<char*>(std::malloc(text.size() + 1));
    if (copy == nullptr)
      return fail(RR_ERROR_OUT_OF_MEMORY, "rr_explain: out of memory");
    std::memcpy(copy, text.c_str(), text.size() + 1);
    *out = copy;
    return ok();
  });
}

void rr_string_free(char* s) {
  std::free(s);
}

} // extern "C"
