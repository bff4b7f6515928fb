// SPDX-License-Identifier: MIT
// The OpenGL adapter: draws a scene with Mesa's llvmpipe through EGL, headless (the surfaceless
// platform, no window and no pbuffer), in a GL 4.3+ core context, and reads back per-primitive,
// per-sample coverage from a shader storage buffer that the fragment shader ORs
// gl_SampleMaskIn into, like the lavapipe adapter. The window origin is made upper-left with
// glClipControl, so the framebuffer is y-down like the scene. Scenes with pipeline state are
// drawn with a program for their attributes, and their values and stored depths read back.
// Implements: DRIVER.OPENGL.DEVICE, DRIVER.OPENGL.ORIGIN, DRIVER.OPENGL.POSITION,
//             DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.SUPPORT, DRIVER.OPENGL.VALUES

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "drivers.hpp"
#include "gpu_common.hpp"
#include "rastrules/driver/opengl_shaders.h"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

// Uniform locations of shaders/opengl_coverage.*.
constexpr GLint kUniformInvK = 0;
constexpr GLint kUniformSlot = 1;
constexpr GLint kUniformWidth = 2;
constexpr GLint kUniformHeight = 3;
constexpr GLint kUniformSlots = 4;
constexpr GLint kUniformWindow = 5; // opengl_values.vert: 1 for window-space vertices

std::string egl_failed(const char* what) {
  return std::string("opengl: ") + what + " failed (EGL error 0x" + [] {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04X", static_cast<unsigned>(eglGetError()));
    return std::string(buf);
  }() + ")";
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr)
    return false;
  std::string_view all(list);
  std::size_t pos = 0;
  while (pos < all.size()) {
    const std::size_t end = std::min(all.find(' ', pos), all.size());
    if (all.substr(pos, end - pos) == name)
      return true;
    pos = end + 1;
  }
  return false;
}

class OpenGLDriver final : public detail::GpuDriver {
public:
  ~OpenGLDriver() override { destroy(); }

  // Opens the display, creates the context and everything draws share. Returns an empty
  // string on success, else the reason.
  // rule: DRIVER.OPENGL.DEVICE
  std::string init() {
    if (std::string why = open_display(); !why.empty())
      return why;
    if (std::string why = create_context(); !why.empty())
      return why;
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (renderer == nullptr ||
        std::string_view(renderer).find("llvmpipe") == std::string_view::npos) {
      return std::string("opengl: the renderer is '") +
             (renderer != nullptr ? renderer : "unknown") +
             "', not llvmpipe (install libgl1-mesa-dri and libegl-mesa0)";
    }
    // Keep Mesa's EGL and DRI drivers loaded for the life of the process: their process-wide
    // state (LLVM, caches) is not meant to be torn down by every driver that is opened and
    // closed (it shows as leaks under LeakSanitizer). Only marks already loaded libraries.
    for (const char* lib :
         {"libEGL_mesa.so.0", "swrast_dri.so", "libgallium_dri.so", "libglapi.so.0"}) {
      void* pinned = dlopen(lib, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
      (void)pinned; // deliberately never closed
    }
    if (std::string why = query_limits(renderer, version); !why.empty())
      return why;
    return create_shared();
  }

  // rule: DRIVER.OPENGL.SUPPORT
  [[nodiscard]] detail::SupportChecks support_checks() const override {
    detail::SupportChecks checks;
    checks.pattern_note = "OpenGL has the implementation's fixed positions only";
    checks.count_by = renderer_ + " with the standard positions";
    checks.k_limit = "limit";
    checks.msaa = [](const MultisampleState& ms) -> std::string {
      if (ms.count() == 1 && (ms.effective_mask() & 1U) == 0U) {
        return "a sample mask without sample 0 on a 1-sample target (OpenGL ignores the sample "
               "mask without a multisample buffer)";
      }
      return {};
    };
    checks.line = [](const Scene& s, const Primitive& p) -> std::string {
      const std::uint32_t samples = s.msaa.count();
      if (p.aa)
        return "antialiased lines not supported (GL_LINE_SMOOTH is not used)";
      if (samples == 1 && s.conventions.line_mode != LineMode::kVulkanBresenham) {
        return "line mode '" + std::string(to_string(s.conventions.line_mode)) +
               "' not supported on 1 sample (OpenGL aliased lines are 'vulkan-bresenham')";
      }
      if (samples > 1 && s.conventions.line_mode != LineMode::kQuadNarrow) {
        return "line mode '" + std::string(to_string(s.conventions.line_mode)) +
               "' not supported on a multisampled target (OpenGL multisampled lines are "
               "rectangles, 'quad-narrow')";
      }
      return {};
    };
    // rule: DRIVER.OPENGL.VALUES
    checks.pipeline = [this](const Scene& s) -> std::string {
      if (std::string why = detail::values_problem(s); !why.empty())
        return why;
      if (s.depth && s.depth->bias.clamp != 0.0f && polygon_offset_clamp_ == nullptr)
        return "a depth bias clamp not supported (no glPolygonOffsetClamp)";
      return {};
    };
    return checks;
  }

  // rule: DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.POSITION
  [[nodiscard]] DrawResult draw_packed(const Scene& scene, const detail::PackedScene& packed,
                                       std::uint32_t w, std::uint32_t h) override {
    if (eglMakeCurrent(display_, surface_, surface_, context_) != EGL_TRUE) {
      return DriverError{egl_failed("eglMakeCurrent")};
    }
    while (glGetError() != GL_NO_ERROR) {
    }

    const std::vector<float>& vertices = packed.vertices;
    const std::uint32_t slots = packed.slots;
    const std::size_t cov_words = std::max<std::size_t>(std::size_t{slots} * w * h, 1);
    const std::uint32_t samples = scene.msaa.count();
    if (std::string why = ensure_framebuffer(w, h, samples); !why.empty())
      return DriverError{why};

    // The coverage buffer: grown by doubling; its storage is re-specified in place and the
    // binding point is rewritten on every draw, so no stale binding can survive a regrowth.
    if (coverage_words_ < cov_words) {
      std::size_t words = 1024;
      while (words < cov_words)
        words *= 2;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, coverage_);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(words * 4U), nullptr,
                   GL_DYNAMIC_READ);
      coverage_words_ = words;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, coverage_);
    const GLuint zero = 0;
    glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, 0,
                         static_cast<GLsizeiptr>(cov_words * 4U), GL_RED_INTEGER, GL_UNSIGNED_INT,
                         &zero);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STREAM_DRAW);
    glBindVertexArray(vao_);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glEnableVertexAttribArray(0);
    glUseProgram(program_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);

    // rule: DRIVER.OPENGL.POSITION
    const double k = detail::position_scale(scene);
    const auto ki = static_cast<GLint>(k);
    glViewport(-ki, -ki, 2 * ki, 2 * ki);
    glDepthRangef(0.0F, 1.0F);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, static_cast<GLsizei>(w), static_cast<GLsizei>(h));
    glUniform1f(kUniformInvK, static_cast<float>(1.0 / k));
    glUniform1ui(kUniformWidth, w);
    glUniform1ui(kUniformHeight, h);
    glUniform1ui(kUniformSlots, slots);

    set_sample_mask(scene);

    GLint first_vertex = 0;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      const Primitive& p = scene.primitives[i];
      const GLenum mode = set_primitive_state(scene, p);
      glUniform1ui(kUniformSlot, packed.first_slot[i]);
      const auto count = static_cast<GLsizei>(p.v.size());
      glDrawArrays(mode, first_vertex, count);
      first_vertex += count;
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<std::uint32_t> cov(cov_words);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, coverage_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(cov_words * 4U),
                       cov.data());
    if (GLenum err = glGetError(); err != GL_NO_ERROR) {
      return DriverError{"opengl: GL error " + std::to_string(err) + " while drawing"};
    }

    // rule: DRIVER.OPENGL.COVERAGE
    return detail::decode_coverage(scene, packed, cov.data(), w, h);
  }

  // rule: DRIVER.OPENGL.VALUES
  [[nodiscard]] ValuesResult draw_pipeline(const Scene& scene, std::uint32_t w,
                                           std::uint32_t h) override {
    if (eglMakeCurrent(display_, surface_, surface_, context_) != EGL_TRUE) {
      return DriverError{egl_failed("eglMakeCurrent")};
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    const std::size_t n = scene.attributes.size();
    GLuint program = 0;
    // rule: MSAA.SHADING.SAMPLE
    const std::uint32_t per_sample =
        scene.msaa.shading == ShadingRate::kSample ? scene.msaa.count() : 0U;
    if (std::string why = values_program(scene.attributes, per_sample, &program); !why.empty())
      return DriverError{why};
    const detail::PackedPipeline packed = detail::pack_pipeline(scene);
    const std::uint32_t samples = scene.msaa.count();
    if (std::string why = ensure_framebuffer(w, h, samples); !why.empty())
      return DriverError{why};

    // The coverage and values buffers, cleared (DRIVER.OPENGL.VALUES).
    const std::size_t plane = std::size_t{w} * h;
    const std::size_t cov_words = std::max<std::size_t>(std::size_t{packed.slots} * plane, 1);
    const std::size_t val_words =
        std::max<std::size_t>(cov_words * n * std::max<std::uint32_t>(per_sample, 1U), 1);
    const GLuint zero = 0;
    for (const auto& [buffer, words, binding] :
         {std::tuple{coverage_, cov_words, 0U}, std::tuple{values_, val_words, 1U}}) {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(words * 4U), nullptr,
                   GL_DYNAMIC_READ);
      glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, 0,
                           static_cast<GLsizeiptr>(words * 4U), GL_RED_INTEGER, GL_UNSIGNED_INT,
                           &zero);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    }
    coverage_words_ = 0; // re-specified here: the coverage path sizes it again

    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(packed.vertices.size() * sizeof(float)),
                 packed.vertices.data(), GL_STREAM_DRAW);
    glBindVertexArray(vao_);
    const auto stride = static_cast<GLsizei>(packed.stride * sizeof(float));
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(0);
    for (std::size_t k = 0; k < n; ++k) {
      const auto loc = static_cast<GLuint>(1 + k);
      glVertexAttribPointer(loc, 1, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>((4 + k) * sizeof(float)));
      glEnableVertexAttribArray(loc);
    }
    glUseProgram(program);
    glUniform1ui(kUniformWidth, w);
    glUniform1ui(kUniformHeight, h);
    glUniform1ui(kUniformSlots, packed.slots);

    // rule: PIPE.VIEWPORT.SCISSOR
    const pipe::Viewport vp = detail::viewport_of(scene);
    const pipe::ScissorRect sc = pipe::viewport_scissor(vp);
    const std::int64_t x0 = std::clamp<std::int64_t>(sc.x0, 0, w);
    const std::int64_t y0 = std::clamp<std::int64_t>(sc.y0, 0, h);
    const std::int64_t x1 = std::clamp<std::int64_t>(sc.x1, x0, w);
    const std::int64_t y1 = std::clamp<std::int64_t>(sc.y1, y0, h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(static_cast<GLint>(x0), static_cast<GLint>(y0), static_cast<GLsizei>(x1 - x0),
              static_cast<GLsizei>(y1 - y0));
    // rule: PIPE.INTERP.FLAT
    glProvokingVertex(scene.conventions.provoking == pipe::Provoking::kFirst
                          ? GL_FIRST_VERTEX_CONVENTION
                          : GL_LAST_VERTEX_CONVENTION);
    set_sample_mask(scene);
    if (per_sample != 0) {
      glEnable(GL_SAMPLE_SHADING);
      glMinSampleShading(1.0F);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    std::string failed;
    draw_primitives(scene, packed, vp, [&](std::size_t i, GLenum mode, GLint first, GLsizei count) {
      glUniform1ui(kUniformSlot, packed.first_slot[i]);
      glDrawArrays(mode, first, count);
    });
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glDisable(GL_SAMPLE_SHADING);
    std::vector<std::uint32_t> cov(cov_words);
    std::vector<float> vals(val_words);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, coverage_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(cov_words * 4U),
                       cov.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, values_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(val_words * 4U),
                       vals.data());

    // rule: DRIVER.OPENGL.VALUES, PIPE.DEPTH.FORMAT
    // The stored depth: each slot alone into a cleared depth buffer of the scene's format and
    // sample count, test GL_ALWAYS, read back exactly (read_depth). A multisampled buffer is
    // read by a compute shader through float, which is exact for D16 and D32F only: D24 on
    // several samples reports no depth.
    const pipe::DepthFormat format = scene.conventions.depth;
    std::vector<std::vector<std::optional<pipe::DepthValue>>> depth;
    if (scene.depth && (samples == 1 || format != pipe::DepthFormat::kD24)) {
      if (std::string why = ensure_depth(w, h, format, samples); !why.empty())
        return DriverError{why};
      depth.resize(packed.slots);
      glBindFramebuffer(GL_FRAMEBUFFER, samples == 1 ? depth_framebuffer_ : depth_ms_framebuffer_);
      glDepthMask(GL_TRUE);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_ALWAYS);
      const std::size_t entries = plane * samples;
      std::array<std::vector<std::uint32_t>, 2> raw{std::vector<std::uint32_t>(entries),
                                                    std::vector<std::uint32_t>(entries)};
      draw_primitives(
          scene, packed, vp, [&](std::size_t i, GLenum mode, GLint first, GLsizei count) {
            // rule: PIPE.DEPTH.BIAS
            // Triangles only, as in the reference (GL_POLYGON_OFFSET_FILL offsets polygons).
            const pipe::DepthBias& bias = scene.depth->bias;
            if (mode == GL_TRIANGLES && bias.enabled()) {
              glEnable(GL_POLYGON_OFFSET_FILL);
              if (polygon_offset_clamp_ != nullptr)
                polygon_offset_clamp_(bias.slope_scaled, static_cast<float>(bias.bias), bias.clamp);
              else
                glPolygonOffset(bias.slope_scaled, static_cast<float>(bias.bias));
            } else {
              glDisable(GL_POLYGON_OFFSET_FILL);
            }
            const bool strip = mode == GL_LINE_STRIP;
            const GLsizei parts = strip ? count - 1 : 1;
            for (GLsizei s = 0; s < parts; ++s) {
              // Drawn twice, over a clear to 0 and over a clear to 1: a sample the slot
              // covers holds the same value both times, any other sample the two clear
              // values.
              for (std::size_t pass = 0; pass < 2; ++pass) {
                glDisable(GL_SCISSOR_TEST);
                glClearDepth(static_cast<double>(pass));
                glClear(GL_DEPTH_BUFFER_BIT);
                glEnable(GL_SCISSOR_TEST);
                if (strip)
                  glDrawArrays(GL_LINES, first + s, 2);
                else
                  glDrawArrays(mode, first, count);
                if (std::string why = read_depth(format, w, h, samples, raw[pass].data());
                    !why.empty()) {
                  failed = why;
                  return;
                }
              }
              auto& out = depth[packed.first_slot[i] + static_cast<std::uint32_t>(s)];
              out.resize(entries);
              for (std::size_t k = 0; k < entries; ++k) {
                if (raw[0][k] != raw[1][k])
                  continue;
                pipe::DepthValue v;
                if (format == pipe::DepthFormat::kD32F)
                  v.f = std::bit_cast<float>(raw[0][k]);
                else
                  v.unorm = raw[0][k];
                out[k] = v;
              }
            }
          });
      glDisable(GL_DEPTH_TEST);
      glDisable(GL_POLYGON_OFFSET_FILL);
      if (!failed.empty())
        return DriverError{failed};
    }
    glDisable(GL_DEPTH_CLAMP);
    for (std::size_t k = 0; k < n; ++k)
      glDisableVertexAttribArray(static_cast<GLuint>(1 + k));
    if (GLenum err = glGetError(); err != GL_NO_ERROR) {
      return DriverError{"opengl: GL error " + std::to_string(err) + " while drawing values"};
    }
    return detail::decode_values(scene, packed, cov.data(), vals.data(),
                                 depth.empty() ? nullptr : &depth, w, h, per_sample, samples);
  }

private:
  // Multisampling and the sample mask (DRIVER.OPENGL.SUPPORT).
  static void set_sample_mask(const Scene& scene) {
    if (scene.msaa.count() > 1) {
      glEnable(GL_MULTISAMPLE);
      glEnable(GL_SAMPLE_MASK);
      glSampleMaski(0, scene.msaa.effective_mask());
    } else {
      glDisable(GL_SAMPLE_MASK);
    }
  }

  // Sets the culling and front face of a primitive (none but for triangles) and returns its
  // draw mode.
  // rule: DRIVER.OPENGL.SUPPORT, DRIVER.OPENGL.ORIGIN
  static GLenum set_primitive_state(const Scene& scene, const Primitive& p) {
    glDisable(GL_CULL_FACE);
    switch (p.type) {
    case PrimitiveType::kTriangle:
      if (scene.cull != CullMode::kNone) {
        glEnable(GL_CULL_FACE);
        glCullFace(scene.cull == CullMode::kBack ? GL_BACK : GL_FRONT);
      }
      // Under GL_UPPER_LEFT the sign of GL's window-space area is reversed, so the
      // orientation is the one seen in the y-down image: clockwise on screen is GL_CW.
      glFrontFace(scene.conventions.front_face == FrontFace::kClockwise ? GL_CW : GL_CCW);
      return GL_TRIANGLES;
    case PrimitiveType::kPoint:
      return GL_POINTS;
    case PrimitiveType::kLine:
      return GL_LINES;
    case PrimitiveType::kLineStrip:
      return GL_LINE_STRIP;
    case PrimitiveType::kPath:
      break; // never here: unsupported() refuses paths
    }
    return GL_TRIANGLES;
  }

  // Sets each primitive's state and calls draw(i, mode, first vertex, vertex count): window
  // space through the viewport [-K, K] with depth [0, 1] (exact, DRIVER.OPENGL.POSITION), clip
  // space through the scene's viewport and depth range (glViewportIndexedf, glDepthRangef,
  // GL_DEPTH_CLAMP without depth clipping).
  // rule: DRIVER.OPENGL.VALUES, PIPE.VIEWPORT.TRANSFORM
  template <class Draw>
  void draw_primitives(const Scene& scene, const detail::PackedPipeline& packed,
                       const pipe::Viewport& vp, Draw&& draw) {
    const double k = detail::position_scale(scene);
    const bool depth_clip = !scene.depth || scene.depth->clip;
    GLint first = 0;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      const Primitive& p = scene.primitives[i];
      const auto count = static_cast<GLsizei>(packed.window_space[i] ? p.v.size() : p.pos.size());
      if (packed.window_space[i]) {
        glUniform1f(kUniformInvK, static_cast<float>(1.0 / k));
        glUniform1ui(kUniformWindow, 1U);
        const auto ki = static_cast<GLfloat>(k);
        glViewportIndexedf(0, -ki, -ki, 2 * ki, 2 * ki);
        glDepthRangef(0.0F, 1.0F);
        glDisable(GL_DEPTH_CLAMP);
      } else {
        glUniform1ui(kUniformWindow, 0U);
        glViewportIndexedf(0, vp.x, vp.y, vp.width, vp.height);
        glDepthRangef(vp.min_depth, vp.max_depth);
        if (depth_clip)
          glDisable(GL_DEPTH_CLAMP);
        else
          glEnable(GL_DEPTH_CLAMP);
      }
      const GLenum mode = set_primitive_state(scene, p);
      draw(i, mode, first, count);
      first += count;
    }
  }

  // Reads the depth buffer's w x h values (times samples: sample q of pixel p at p * samples + q)
  // exactly, in the format's unit (the UNORM integer, or the float32 bits): on one sample D16
  // as GL_UNSIGNED_SHORT, D24 from a GL_DEPTH24_STENCIL8 buffer as GL_UNSIGNED_INT_24_8 (depth
  // in the high 24 bits), D32F as GL_FLOAT; on several, D16 and D32F through the compute shader
  // (texelFetch of the multisampled texture, a float: exactly k / 65535 rounded to float32 for
  // D16, from which k is recovered by rounding, the stored float for D32F).
  // rule: DRIVER.OPENGL.VALUES
  std::string read_depth(pipe::DepthFormat f, std::uint32_t w, std::uint32_t h,
                         std::uint32_t samples, std::uint32_t* out) {
    const auto gw = static_cast<GLsizei>(w);
    const auto gh = static_cast<GLsizei>(h);
    const std::size_t plane = std::size_t{w} * h;
    if (samples > 1) {
      if (std::string why = ensure_depth_reader(); !why.empty())
        return why;
      const std::size_t entries = plane * samples;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, depth_out_);
      glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(entries * 4U), nullptr,
                   GL_DYNAMIC_READ);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, depth_out_);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, depth_ms_texture_);
      GLint program = 0;
      glGetIntegerv(GL_CURRENT_PROGRAM, &program);
      glUseProgram(depth_reader_);
      glUniform1ui(0, w);
      glUniform1ui(1, h);
      glUniform1ui(2, samples);
      glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
      glDispatchCompute((w + 7) / 8, (h + 7) / 8, 1);
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      std::vector<float> v(entries);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(entries * 4U),
                         v.data());
      glUseProgram(static_cast<GLuint>(program));
      for (std::size_t k = 0; k < entries; ++k) {
        out[k] = f == pipe::DepthFormat::kD16
                     ? static_cast<std::uint32_t>(std::lround(static_cast<double>(v[k]) * 65535.0))
                     : std::bit_cast<std::uint32_t>(v[k]);
      }
      return {};
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (f == pipe::DepthFormat::kD16) {
      std::vector<std::uint16_t> v(plane);
      glReadPixels(0, 0, gw, gh, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, v.data());
      std::copy(v.begin(), v.end(), out);
    } else if (f == pipe::DepthFormat::kD24) {
      glReadPixels(0, 0, gw, gh, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, out);
      for (std::size_t k = 0; k < plane; ++k)
        out[k] >>= 8;
    } else {
      glReadPixels(0, 0, gw, gh, GL_DEPTH_COMPONENT, GL_FLOAT, out);
    }
    return {};
  }

  // The compute program that copies a multisampled depth texture (unit 0) to a buffer.
  std::string ensure_depth_reader() {
    if (depth_reader_ != 0)
      return {};
    static constexpr const char* kSource = R"glsl(#version 430 core
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2DMS depth_texture;
layout(location = 0) uniform uint width;
layout(location = 1) uniform uint height;
layout(location = 2) uniform uint samples;
layout(std430, binding = 2) buffer Out {
  float v[];
};
void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= width || p.y >= height) {
    return;
  }
  for (uint q = 0u; q < samples; ++q) {
    v[(p.y * width + p.x) * samples + q] = texelFetch(depth_texture, ivec2(p), int(q)).r;
  }
}
)glsl";
    GLuint cs = 0;
    if (std::string why = compile(GL_COMPUTE_SHADER, kSource, &cs); !why.empty())
      return why;
    depth_reader_ = glCreateProgram();
    glAttachShader(depth_reader_, cs);
    glLinkProgram(depth_reader_);
    glDeleteShader(cs);
    GLint ok = GL_FALSE;
    glGetProgramiv(depth_reader_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
      glDeleteProgram(depth_reader_);
      depth_reader_ = 0;
      return "opengl: depth reader link failed";
    }
    glGenBuffers(1, &depth_out_);
    return {};
  }

  // A framebuffer with only a depth buffer of the format: on one sample a renderbuffer, on
  // several a multisampled texture (read_depth reads it in a shader).
  std::string ensure_depth(std::uint32_t w, std::uint32_t h, pipe::DepthFormat f,
                           std::uint32_t samples) {
    const bool d24 = f == pipe::DepthFormat::kD24;
    const GLenum internal = f == pipe::DepthFormat::kD16 ? GL_DEPTH_COMPONENT16
                            : d24                        ? GL_DEPTH24_STENCIL8
                                                         : GL_DEPTH_COMPONENT32F;
    const GLenum attachment = d24 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (samples > 1) {
      if (depth_ms_framebuffer_ != 0 && depth_ms_w_ == w && depth_ms_h_ == h &&
          depth_ms_format_ == f && depth_ms_samples_ == samples) {
        return {};
      }
      depth_ms_w_ = 0;
      if (depth_ms_framebuffer_ == 0)
        glGenFramebuffers(1, &depth_ms_framebuffer_);
      if (depth_ms_texture_ != 0)
        glDeleteTextures(1, &depth_ms_texture_); // immutable storage: a new texture
      glGenTextures(1, &depth_ms_texture_);
      glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, depth_ms_texture_);
      glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, static_cast<GLsizei>(samples), internal,
                                static_cast<GLsizei>(w), static_cast<GLsizei>(h), GL_TRUE);
      glBindFramebuffer(GL_FRAMEBUFFER, depth_ms_framebuffer_);
      glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, 0, 0);
      glFramebufferTexture(GL_FRAMEBUFFER, attachment, depth_ms_texture_, 0);
      glDrawBuffer(GL_NONE);
      glReadBuffer(GL_NONE);
      if (GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER); st != GL_FRAMEBUFFER_COMPLETE)
        return "opengl: depth framebuffer incomplete (status " + std::to_string(st) + ")";
      depth_ms_w_ = w;
      depth_ms_h_ = h;
      depth_ms_format_ = f;
      depth_ms_samples_ = samples;
      return {};
    }
    if (depth_framebuffer_ != 0 && depth_w_ == w && depth_h_ == h && depth_format_ == f)
      return {};
    depth_w_ = 0;
    if (std::string why = attach_renderbuffer(&depth_framebuffer_, &depth_renderbuffer_, attachment,
                                              internal, 1, w, h);
        !why.empty()) {
      return why;
    }
    depth_w_ = w;
    depth_h_ = h;
    depth_format_ = f;
    return {};
  }

  // Creates *fb and *rb on first use, gives *rb the storage (`samples` > 1: multisampled) and
  // attaches it to *fb at `attachment` (detaching the depth-stencil point first: the depth
  // formats use either point). Returns "" or why the framebuffer is incomplete.
  static std::string attach_renderbuffer(GLuint* fb, GLuint* rb, GLenum attachment, GLenum internal,
                                         std::uint32_t samples, std::uint32_t w, std::uint32_t h) {
    if (*fb == 0)
      glGenFramebuffers(1, fb);
    if (*rb == 0)
      glGenRenderbuffers(1, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, *rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER,
                                     samples > 1 ? static_cast<GLsizei>(samples) : 0, internal,
                                     static_cast<GLsizei>(w), static_cast<GLsizei>(h));
    glBindFramebuffer(GL_FRAMEBUFFER, *fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, *rb);
    if (attachment != GL_COLOR_ATTACHMENT0) {
      glDrawBuffer(GL_NONE);
      glReadBuffer(GL_NONE);
    }
    if (GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER); st != GL_FRAMEBUFFER_COMPLETE)
      return "opengl: framebuffer incomplete (status " + std::to_string(st) + ")";
    return {};
  }

  // The program of a scene's attribute declarations (one input per attribute with its
  // interpolation and location qualifiers), compiled on first use and kept.
  // rule: DRIVER.OPENGL.VALUES, PIPE.INTERP.LOCATION
  // per_sample > 0: sample-rate shading with that many samples (the entry of gl_SampleID;
  // gl_SampleID appears only then, since its use alone makes the shading per sample).
  std::string values_program(const std::vector<pipe::AttributeDecl>& attrs,
                             std::uint32_t per_sample, GLuint* program) {
    std::string decls;
    std::string key = std::to_string(per_sample) + ":";
    std::string vs_body;
    std::string fs_body;
    for (std::size_t k = 0; k < attrs.size(); ++k) {
      const std::string q =
          std::string(attrs[k].location == pipe::Location::kCentroid ? "centroid "
                      : attrs[k].location == pipe::Location::kSample ? "sample "
                                                                     : "") +
          (attrs[k].interpolation == pipe::Interpolation::kFlat     ? "flat"
           : attrs[k].interpolation == pipe::Interpolation::kLinear ? "noperspective"
                                                                    : "smooth");
      key += q + ";";
      const std::string i = std::to_string(k);
      decls += "layout(location = " + i + ") " + q + " VARYING float a" + i + ";\n";
      vs_body += "  a" + i + " = in_a" + i + ";\n";
      fs_body += "  values[base + " + i + "u] = a" + i + ";\n";
    }
    if (auto it = values_programs_.find(key); it != values_programs_.end()) {
      *program = it->second;
      return {};
    }
    std::string vs = std::string(kGlValues_vert);
    std::string fs = std::string(kGlValues_frag);
    std::string vs_in;
    for (std::size_t k = 0; k < attrs.size(); ++k) {
      const std::string i = std::to_string(k);
      vs_in += "layout(location = " + std::to_string(k + 1) + ") in float in_a" + i + ";\n";
    }
    const auto subst = [](std::string text, std::string_view what, const std::string& by) {
      const std::size_t at = text.find(what);
      return at == std::string::npos ? text : text.replace(at, what.size(), by);
    };
    const auto with = [&](std::string d, const char* dir) {
      for (std::size_t at = d.find("VARYING"); at != std::string::npos; at = d.find("VARYING"))
        d.replace(at, 7, dir);
      return d;
    };
    vs = subst(subst(subst(vs, "//INPUTS", vs_in), "//OUTPUTS", with(decls, "out")), "//COPY",
               vs_body);
    fs = subst(subst(fs, "//INPUTS", with(decls, "in")), "//STORE", fs_body);
    const std::string count = std::to_string(attrs.size()) + "u";
    fs = subst(fs, "//ENTRY",
               per_sample == 0 ? "pixel * " + count
                               : "(pixel * " + std::to_string(per_sample) +
                                     "u + uint(gl_SampleID)) * " + count);
    GLuint prog = 0;
    if (std::string why = link_program(vs.c_str(), fs.c_str(), &prog); !why.empty())
      return why;
    values_programs_.emplace(key, prog);
    *program = prog;
    return {};
  }

  // rule: DRIVER.OPENGL.DEVICE
  std::string open_display() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
      auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
          eglGetProcAddress("eglGetPlatformDisplayEXT"));
      if (get_platform_display != nullptr) {
        display_ =
            get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        platform_ = "surfaceless";
      }
    }
    if (display_ == EGL_NO_DISPLAY) {
      display_ = eglGetDisplay(EGL_DEFAULT_DISPLAY);
      platform_ = "default";
    }
    if (display_ == EGL_NO_DISPLAY)
      return "opengl: no EGL display (install libegl-mesa0)";
    EGLint major = 0;
    EGLint minor = 0;
    if (eglInitialize(display_, &major, &minor) != EGL_TRUE) {
      display_ = EGL_NO_DISPLAY;
      return egl_failed("eglInitialize (is Mesa's EGL installed?)");
    }
    egl_version_ = std::to_string(major) + "." + std::to_string(minor);
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE)
      return egl_failed("eglBindAPI(EGL_OPENGL_API)");
    return {};
  }

  std::string create_context() {
    const char* exts = eglQueryString(display_, EGL_EXTENSIONS);
    const bool no_config = has_extension(exts, "EGL_KHR_no_config_context") ||
                           has_extension(exts, "EGL_MESA_configless_context");
    const bool surfaceless = has_extension(exts, "EGL_KHR_surfaceless_context");
    EGLConfig config = nullptr; // EGL_NO_CONFIG_KHR
    if (!no_config || !surfaceless) {
      // The fallback: a config with a 1x1 pbuffer to make the context current on.
      const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                EGL_OPENGL_BIT, EGL_NONE};
      EGLint n = 0;
      if (eglChooseConfig(display_, attribs, &config, 1, &n) != EGL_TRUE || n < 1) {
        return egl_failed("eglChooseConfig (no pbuffer OpenGL config)");
      }
      const EGLint pb[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface_ = eglCreatePbufferSurface(display_, config, pb);
      if (surface_ == EGL_NO_SURFACE)
        return egl_failed("eglCreatePbufferSurface");
    }
    for (const auto& [maj, min] : {std::array<EGLint, 2>{4, 5}, std::array<EGLint, 2>{4, 3}}) {
      const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                maj,
                                EGL_CONTEXT_MINOR_VERSION,
                                min,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_NONE};
      context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attribs);
      if (context_ != EGL_NO_CONTEXT)
        break;
    }
    if (context_ == EGL_NO_CONTEXT)
      return egl_failed("eglCreateContext (OpenGL 4.3 core)");
    if (eglMakeCurrent(display_, surface_, surface_, context_) != EGL_TRUE) {
      return egl_failed("eglMakeCurrent");
    }
    return {};
  }

  // rule: DRIVER.OPENGL.DEVICE, DRIVER.OPENGL.POSITION
  std::string query_limits(const char* renderer, const char* version) {
    GLint major = 0;
    GLint minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 4 || (major == 4 && minor < 3)) {
      return "opengl: OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
             " (needs 4.3 for shader storage buffers)";
    }
    // glClipControl: core in 4.5, else ARB_clip_control (DRIVER.OPENGL.ORIGIN).
    bool clip_control = major > 4 || minor >= 5;
    GLint n_ext = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n_ext);
    for (GLint i = 0; i < n_ext && !clip_control; ++i) {
      const char* e =
          reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
      clip_control = e != nullptr && std::string_view(e) == "GL_ARB_clip_control";
    }
    if (!clip_control)
      return "opengl: no glClipControl (needs OpenGL 4.5 or ARB_clip_control)";
    // glPolygonOffsetClamp: core in 4.6, else ARB_ or EXT_polygon_offset_clamp (PIPE.DEPTH.BIAS).
    bool offset_clamp = major > 4 || minor >= 6;
    for (GLint i = 0; i < n_ext && !offset_clamp; ++i) {
      const char* e =
          reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
      offset_clamp = e != nullptr && (std::string_view(e) == "GL_ARB_polygon_offset_clamp" ||
                                      std::string_view(e) == "GL_EXT_polygon_offset_clamp");
    }
    if (offset_clamp) {
      for (const char* name : {"glPolygonOffsetClamp", "glPolygonOffsetClampEXT"}) {
        if (polygon_offset_clamp_ == nullptr) {
          polygon_offset_clamp_ =
              reinterpret_cast<PFNGLPOLYGONOFFSETCLAMPPROC>(eglGetProcAddress(name));
        }
      }
    }
    renderer_ = renderer;
    info_.name = "opengl";
    info_.description = std::string(renderer) + ", OpenGL " + version + ", EGL " + egl_version_ +
                        " (" + platform_ + "), origin upper-left (glClipControl)";
    GLint bits = -1;
    glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
    info_.subpixel_bits = bits;
    GLint max_samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    info_.sample_counts = {1};
    if (max_samples >= 4 && standard_positions(4))
      info_.sample_counts.push_back(4);
    info_.points = true;
    info_.lines_bresenham = true;
    info_.lines_rectangular = false; // only on multisampled targets (DRIVER.OPENGL.SUPPORT)
    info_.lines_d3d = false;
    info_.sample_mask = true;
    info_.sample_shading = false;
    info_.values = true; // DRIVER.OPENGL.VALUES
    // K is a power of two with a viewport [-K, K]: 2K <= GL_MAX_VIEWPORT_DIMS and [-K, K]
    // inside GL_VIEWPORT_BOUNDS_RANGE.
    GLint dims[2] = {0, 0};
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    GLfloat range[2] = {0.0F, 0.0F};
    glGetFloatv(GL_VIEWPORT_BOUNDS_RANGE, range);
    GLint rb = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &rb);
    const double max_dim = std::min(dims[0], dims[1]);
    const double bound = std::min(-static_cast<double>(range[0]), static_cast<double>(range[1]));
    max_k_ = detail::max_position_scale(max_dim, bound);
    info_.max_target_side = static_cast<std::int32_t>(std::min(static_cast<double>(rb), max_k_));
    return {};
  }

  // Returns whether the n-sample positions of a GL_R8 renderbuffer are the standard pattern
  // (GL_SAMPLE_POSITION: in [0, 1] of the pixel, y counted like the framebuffer's rows).
  bool standard_positions(std::uint32_t n) {
    GLuint rb = 0;
    GLuint fb = 0;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, static_cast<GLsizei>(n), GL_R8, 4, 4);
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    GLint got = 0;
    glGetIntegerv(GL_SAMPLES, &got);
    ok = ok && got == static_cast<GLint>(n);
    const SamplePattern want = standard_pattern(n);
    for (std::uint32_t i = 0; ok && i < n; ++i) {
      GLfloat pos[2] = {-1.0F, -1.0F};
      glGetMultisamplefv(GL_SAMPLE_POSITION, i, pos);
      const float sx = pos[0] * 16.0F - 8.0F;
      const float sy = pos[1] * 16.0F - 8.0F;
      ok = sx == static_cast<float>(want.positions[i].x) &&
           sy == static_cast<float>(want.positions[i].y);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
    return ok;
  }

  std::string compile(GLenum stage, const char* source, GLuint* shader) {
    *shader = glCreateShader(stage);
    glShaderSource(*shader, 1, &source, nullptr);
    glCompileShader(*shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(*shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE)
      return {};
    std::array<char, 1024> log{};
    glGetShaderInfoLog(*shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    std::string msg(log.data());
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    return "opengl: shader compilation failed: " + msg;
  }

  // Compiles and links a program of the two stages; *program is 0 on failure.
  std::string link_program(const char* vertex, const char* fragment, GLuint* program) {
    GLuint vs = 0;
    GLuint fs = 0;
    std::string why = compile(GL_VERTEX_SHADER, vertex, &vs);
    if (why.empty())
      why = compile(GL_FRAGMENT_SHADER, fragment, &fs);
    *program = 0;
    if (why.empty()) {
      *program = glCreateProgram();
      glAttachShader(*program, vs);
      glAttachShader(*program, fs);
      glLinkProgram(*program);
      GLint ok = GL_FALSE;
      glGetProgramiv(*program, GL_LINK_STATUS, &ok);
      if (ok != GL_TRUE) {
        why = "opengl: program link failed";
        glDeleteProgram(*program);
        *program = 0;
      }
    }
    if (vs != 0)
      glDeleteShader(vs);
    if (fs != 0)
      glDeleteShader(fs);
    return why;
  }

  // The program, buffers and fixed state shared by all draws.
  // rule: DRIVER.OPENGL.ORIGIN, DRIVER.OPENGL.SUPPORT
  std::string create_shared() {
    if (std::string why = link_program(kGlCoverage_vert, kGlCoverage_frag, &program_);
        !why.empty()) {
      return why;
    }
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vertex_buffer_);
    glGenBuffers(1, &coverage_);
    glGenBuffers(1, &values_);
    // Upper-left origin: window y runs down like the scene's (DRIVER.OPENGL.ORIGIN).
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    for (const GLenum cap : std::to_array<GLenum>(
             {GL_DITHER, GL_BLEND, GL_DEPTH_TEST, GL_STENCIL_TEST, GL_POLYGON_SMOOTH,
              GL_LINE_SMOOTH, GL_SAMPLE_SHADING, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_COVERAGE,
              GL_PROGRAM_POINT_SIZE, GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_RASTERIZER_DISCARD,
              GL_COLOR_LOGIC_OP})) {
      glDisable(cap);
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPointSize(1.0F);
    glLineWidth(1.0F);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    if (GLenum err = glGetError(); err != GL_NO_ERROR) {
      return "opengl: GL error " + std::to_string(err) + " while setting up";
    }
    return {};
  }

  // A framebuffer with one GL_R8 renderbuffer of the target's size and sample count.
  std::string ensure_framebuffer(std::uint32_t w, std::uint32_t h, std::uint32_t samples) {
    if (framebuffer_ != 0 && fb_w_ == w && fb_h_ == h && fb_samples_ == samples)
      return {};
    fb_w_ = 0;
    if (std::string why = attach_renderbuffer(&framebuffer_, &renderbuffer_, GL_COLOR_ATTACHMENT0,
                                              GL_R8, samples, w, h);
        !why.empty()) {
      return why;
    }
    GLint got = 0;
    glGetIntegerv(GL_SAMPLES, &got);
    if (got != static_cast<GLint>(samples > 1 ? samples : 0)) {
      fb_w_ = 0;
      return "opengl: asked for " + std::to_string(samples) + " samples, got " +
             std::to_string(got);
    }
    fb_w_ = w;
    fb_h_ = h;
    fb_samples_ = samples;
    return {};
  }

  void destroy() {
    if (display_ == EGL_NO_DISPLAY)
      return;
    if (context_ != EGL_NO_CONTEXT &&
        eglMakeCurrent(display_, surface_, surface_, context_) == EGL_TRUE) {
      if (program_ != 0)
        glDeleteProgram(program_);
      for (const auto& [key, prog] : values_programs_)
        glDeleteProgram(prog);
      if (values_ != 0)
        glDeleteBuffers(1, &values_);
      if (depth_framebuffer_ != 0)
        glDeleteFramebuffers(1, &depth_framebuffer_);
      if (depth_renderbuffer_ != 0)
        glDeleteRenderbuffers(1, &depth_renderbuffer_);
      if (depth_ms_framebuffer_ != 0)
        glDeleteFramebuffers(1, &depth_ms_framebuffer_);
      if (depth_ms_texture_ != 0)
        glDeleteTextures(1, &depth_ms_texture_);
      if (depth_reader_ != 0)
        glDeleteProgram(depth_reader_);
      if (depth_out_ != 0)
        glDeleteBuffers(1, &depth_out_);
      if (vao_ != 0)
        glDeleteVertexArrays(1, &vao_);
      if (vertex_buffer_ != 0)
        glDeleteBuffers(1, &vertex_buffer_);
      if (coverage_ != 0)
        glDeleteBuffers(1, &coverage_);
      if (framebuffer_ != 0)
        glDeleteFramebuffers(1, &framebuffer_);
      if (renderbuffer_ != 0)
        glDeleteRenderbuffers(1, &renderbuffer_);
    }
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT)
      eglDestroyContext(display_, context_);
    if (surface_ != EGL_NO_SURFACE)
      eglDestroySurface(display_, surface_);
    // No eglTerminate: the display is one per process and shared by every opened driver;
    // terminating it would destroy the contexts of the others (DRIVER.OPENGL.DEVICE).
    display_ = EGL_NO_DISPLAY;
  }

  std::string renderer_;
  std::string platform_;
  std::string egl_version_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLSurface surface_ = EGL_NO_SURFACE;
  EGLContext context_ = EGL_NO_CONTEXT;
  GLuint program_ = 0;
  GLuint vao_ = 0;
  GLuint vertex_buffer_ = 0;
  GLuint coverage_ = 0;
  std::size_t coverage_words_ = 0;
  GLuint framebuffer_ = 0;
  GLuint renderbuffer_ = 0;
  std::uint32_t fb_w_ = 0;
  std::uint32_t fb_h_ = 0;
  std::uint32_t fb_samples_ = 0;
  // The values path (DRIVER.OPENGL.VALUES).
  PFNGLPOLYGONOFFSETCLAMPPROC polygon_offset_clamp_ = nullptr;
  std::map<std::string, GLuint> values_programs_;
  GLuint values_ = 0;
  GLuint depth_framebuffer_ = 0;
  GLuint depth_renderbuffer_ = 0;
  std::uint32_t depth_w_ = 0;
  std::uint32_t depth_h_ = 0;
  pipe::DepthFormat depth_format_ = pipe::DepthFormat::kD24;
  GLuint depth_ms_framebuffer_ = 0;
  GLuint depth_ms_texture_ = 0;
  std::uint32_t depth_ms_w_ = 0;
  std::uint32_t depth_ms_h_ = 0;
  std::uint32_t depth_ms_samples_ = 0;
  pipe::DepthFormat depth_ms_format_ = pipe::DepthFormat::kD24;
  GLuint depth_reader_ = 0; // ensure_depth_reader
  GLuint depth_out_ = 0;
};

} // namespace

namespace detail {

// rule: DRIVER.OPENGL.DEVICE
std::unique_ptr<Driver> open_opengl(std::string_view arg, std::string* error) {
  return open_gpu_driver<OpenGLDriver>("opengl", arg, error);
}

} // namespace detail
} // namespace rastrules::driver
