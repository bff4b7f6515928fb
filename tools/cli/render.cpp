// SPDX-License-Identifier: MIT
// rastrules render: the fragment list, the picture and the resolved target of a scene.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS, SCENE.OUTPUT.MSAA,
//             SCENE.OUTPUT.PIPELINE (pipeline scenes through rastrules::pipe::run_pipeline),
//             FAST.THREADS.DETERMINISTIC, FAST.ISA.DISPATCH (--isa)

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include "chunk_pipe.hpp"
#include "cli.hpp"
#include "count.hpp"
#include "fast_list.hpp"
#include "parser.hpp"
#include "rastrules/io/fragment_binary.hpp"
#include "rastrules/io/fragment_json.hpp"
#include "rastrules/io/image.hpp"
#include "rastrules/io/picture.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/raster/fast_batch.hpp"

#include "rastrules/parallel.hpp"

namespace rastrules::cli {
namespace {

// Both fragment-list paths check the kernel's order; neither can fail it on a correct kernel.
constexpr std::string_view kFragmentsOutOfOrder =
    "internal error: the kernel emitted fragments out of (prim, y, x, seg) order";

// The outputs of one render, moved into place together: when one cannot be, the ones already
// in place are removed (no partial result).
struct Output {
  OutputFile* file;
  const std::optional<std::string>* path;
};

std::optional<std::string> commit_outputs(const std::vector<Output>& outputs) {
  std::vector<std::string> committed;
  for (const Output& o : outputs) {
    if (!*o.path)
      continue;
    if (auto err = o.file->commit()) {
      std::error_code ec;
      for (const std::string& done : committed) {
        if (done != "-" &&
            std::filesystem::is_regular_file(std::filesystem::symlink_status(done, ec))) {
          std::filesystem::remove(done, ec);
        }
      }
      return err;
    }
    committed.push_back(**o.path);
  }
  return std::nullopt;
}

// "render: N primitives, M fragments -> a, b" on standard output (unless an output is there).
void print_summary(std::size_t primitives, std::uint64_t fragments,
                   const std::vector<Output>& outputs) {
  std::string names;
  for (const Output& o : outputs) {
    if (*o.path)
      names += (names.empty() ? " -> " : ", ") + **o.path;
  }
  std::printf("render: %zu primitives, %llu fragments%s\n", primitives,
              static_cast<unsigned long long>(fragments), names.c_str());
}

// rule: MSAA.LIMITS
// The resolve's sample buffer is checked before any work (Resolver::start checks it again).
std::optional<std::string> resolve_too_large(std::int32_t width, std::int32_t height,
                                             std::uint32_t n) {
  if (auto problem = resolve_size_problem(width, height, n))
    return "--resolve: " + *problem;
  return std::nullopt;
}

// Returns the picture's magnification (--scale, or the default for the target), or the error
// when the picture would be too large.
std::variant<int, std::string> picture_scale_for(std::int32_t width, std::int32_t height,
                                                 std::optional<int> scale) {
  const int s = scale ? *scale : io::default_picture_scale(width, height);
  if (io::picture_fits(width, height, s))
    return s;
  return "--png: a picture of the " + std::to_string(width) + "x" + std::to_string(height) +
         " target" + (scale ? " at --scale " + std::to_string(*scale) : std::string()) +
         " would be larger than " + std::to_string(io::kMaxPictureSide) + " pixels a side";
}

// Writes a resolved target as an RGBA PNG; returns the error, if any.
std::optional<std::string> write_resolved_image(const ResolvedImage& r, std::FILE* out,
                                                const std::string& path) {
  std::vector<std::uint8_t> rgba;
  rgba.reserve(r.pixels.size() * 4);
  for (const Rgba8& px : r.pixels)
    rgba.insert(rgba.end(), px.begin(), px.end());
  if (auto err = io::write_png_rgba(out, r.width, r.height, rgba))
    return path + ": " + *err;
  return std::nullopt;
}

// rule: MSAA.RESOLVE.AVERAGE
// Resolves the fragments' samples and writes the RGBA PNG; returns the error, if any.
std::optional<std::string> write_resolved(const PreparedScene& scene,
                                          const std::vector<Fragment>& fragments, std::FILE* out,
                                          const std::string& path) {
  const auto resolved = resolve(scene, fragments);
  if (const auto* err = std::get_if<SceneError>(&resolved))
    return "--resolve: " + err->what();
  return write_resolved_image(std::get<ResolvedImage>(resolved), out, path);
}

// What `render` was asked for.
struct RenderRequest {
  std::string scene_path;
  std::optional<std::string> fragments_path, png_path, resolve_path, depth_out_path, count_path;
  bool fragments_binary = false;    // SCENE.OUTPUT.BINARY
  std::uint32_t binary_version = 2; // 1 with --fragments-format binary-v1
  std::optional<int> scale;
  bool png_depth = false;
  std::uint64_t max_fragments = io::kDefaultMaxFragments;
  std::uint64_t max_work = kDefaultMaxWork;
  RenderOptions options;
  int to_stdout = 0;
  bool pipeline_plain = false;
};

// The binary list's header for the scene, in the version asked for.
// rule: SCENE.OUTPUT.BINARY
io::FragmentBinaryHeader binary_header(const RenderRequest& rq, const PreparedScene& scene) {
  io::FragmentBinaryHeader h = io::fragment_binary_header(scene);
  h.version = rq.binary_version;
  return h;
}

// Returns the picture's magnification (0 without --png); prints the error and returns nullopt
// when the picture would be too large.
std::optional<int> picture_scale_of(std::int32_t width, std::int32_t height,
                                    const RenderRequest& rq) {
  if (!rq.png_path)
    return 0;
  const auto s = picture_scale_for(width, height, rq.scale);
  if (const auto* err = std::get_if<std::string>(&s)) {
    error(*err);
    return std::nullopt;
  }
  return std::get<int>(s);
}

// Returns the stored depth as a value in [0, 1] (d16 and d24: the UNORM value over 2^n - 1).
double depth_01(const pipe::DepthValue& d, pipe::DepthFormat f) {
  switch (f) {
  case pipe::DepthFormat::kD16:
    return static_cast<double>(d.unorm) / 65535.0;
  case pipe::DepthFormat::kD24:
    return static_cast<double>(d.unorm) / 16777215.0;
  case pipe::DepthFormat::kD32F:
    return static_cast<double>(d.f);
  }
  return 0.0;
}

// rule: SCENE.OUTPUT.PIPELINE, SCENE.INPUT.ERRORS, SCENE.INPUT.LIMITS
// Renders a pipeline scene with run_pipeline: its fragments with the fields the scene asks for,
// the coverage picture (or with --png-depth the depth buffer in grey), the resolved target of
// the samples that passed the depth test, and with --depth-out the final depth buffer.
int render_pipeline(const Scene& scene, const RenderRequest& rq) {
  // rule: SCENE.OUTPUT.BINARY
  if (rq.fragments_binary) {
    return error("--fragments: the binary format holds window-space coverage (prim, seg, x, y, "
                 "mask); a pipeline scene's fragments are written as JSON (SCENE.OUTPUT.BINARY)");
  }
  if ((rq.png_depth || rq.depth_out_path) && !scene.depth) {
    return error(std::string(rq.png_depth ? "--png-depth" : "--depth-out") +
                 ": the scene has no \"depth\" (SCENE.PIPELINE)");
  }
  if (rq.resolve_path) {
    if (auto err = resolve_too_large(scene.width, scene.height, scene.msaa.count()))
      return error(*err);
  }
  // rule: SCENE.INPUT.LIMITS
  // run_pipeline stops at the first fragment beyond the limit (and at a primitive that would
  // hold more than it to sort them); its list is checked again here.
  const std::optional<pipe::PipeResult> result =
      run_pipeline_or_report(scene, rq.options, rq.max_fragments, rq.pipeline_plain, rq.max_work);
  if (!result)
    return kExitBadInput;
  if (result->fragments.size() > rq.max_fragments) {
    return error("render: more than " + std::to_string(rq.max_fragments) +
                 " fragments (limit SCENE.INPUT.LIMITS)" + std::string(kMaxFragmentsHint));
  }
  // The target, sample pattern and colours as a prepared scene without geometry: the picture's
  // grid and sample points, and the resolve (run_pipeline has checked the scene).
  const Scene target = target_of(scene);
  auto prepared_or_error = prepare(target);
  if (auto* err = std::get_if<SceneError>(&prepared_or_error))
    return error(err->what());
  PreparedScene& prepared = std::get<PreparedScene>(prepared_or_error);

  const std::optional<int> picture_scale = picture_scale_of(scene.width, scene.height, rq);
  if (!picture_scale)
    return kExitBadInput;
  OutputFile fragments_file, png_file, resolve_file, depth_file;
  const std::vector<Output> outputs = {{&fragments_file, &rq.fragments_path},
                                       {&png_file, &rq.png_path},
                                       {&resolve_file, &rq.resolve_path},
                                       {&depth_file, &rq.depth_out_path}};
  for (const Output& o : outputs) {
    if (!*o.path)
      continue;
    if (auto err = o.file->open(**o.path))
      return error(*err);
  }
  const std::vector<Fragment>& fragments = result->fragments;
  // data is empty when the scene has no clip space, depth or attributes, else one per fragment.
  const std::vector<pipe::FragmentData>& data = result->data;
  if (!data.empty() && data.size() != fragments.size()) {
    return error("internal error: run_pipeline returned " + std::to_string(data.size()) +
                 " fragment data for " + std::to_string(fragments.size()) + " fragments");
  }
  if (rq.fragments_path) {
    io::FragmentWriter writer(fragments_file.get(), io::pipe_output_fields(scene));
    for (std::size_t i = 0; i < fragments.size(); ++i) {
      if (!writer.add(fragments[i], data.empty() ? nullptr : &data[i])) {
        return error("internal error: run_pipeline returned fragments out of (prim, part, y, x, "
                     "seg, sample) order or without one value per attribute and one depth per "
                     "covered sample");
      }
    }
    if (!writer.finish())
      return error(*rq.fragments_path + ": write failed");
  }
  const std::uint32_t samples = scene.msaa.count();
  if (rq.png_path) {
    std::optional<io::Image> image;
    if (rq.png_depth) {
      std::vector<double> depth01;
      depth01.reserve(result->depth_buffer.size());
      for (const pipe::DepthValue& d : result->depth_buffer)
        depth01.push_back(depth_01(d, scene.conventions.depth));
      image.emplace(
          io::draw_depth_picture(scene.width, scene.height, samples, depth01, *picture_scale));
    } else {
      io::CoverageMap coverage(scene.width, scene.height);
      if (io::samples_visible(prepared, *picture_scale))
        coverage.record_samples(samples);
      for (const Fragment& f : fragments)
        coverage.add_fragment(f);
      image.emplace(io::draw_picture(prepared, coverage, *picture_scale));
    }
    if (auto err = io::write_png(png_file.get(), *image))
      return error(*rq.png_path + ": " + *err);
  }
  // rule: MSAA.RESOLVE.AVERAGE, PIPE.DEPTH.TEST
  // Only the samples that passed the depth test write their primitive's colour.
  if (rq.resolve_path) {
    prepared.primitives.resize(scene.primitives.size());
    for (std::size_t p = 0; p < scene.primitives.size(); ++p)
      prepared.primitives[p].color = scene.primitives[p].color;
    std::vector<Fragment> written = fragments;
    if (!data.empty()) {
      for (std::size_t i = 0; i < written.size(); ++i)
        written[i].mask = data[i].passed;
    }
    if (auto err = write_resolved(prepared, written, resolve_file.get(), *rq.resolve_path))
      return error(*err);
  }
  if (rq.depth_out_path &&
      !io::write_depth_buffer(depth_file.get(), scene.width, scene.height, samples,
                              scene.conventions.depth, result->depth_buffer)) {
    return error(*rq.depth_out_path + ": write failed (or run_pipeline's depth buffer is not "
                                      "width x height x samples)");
  }
  if (auto err = commit_outputs(outputs))
    return error(*err);
  if (rq.to_stdout == 0 && verbosity() != Verbosity::kQuiet)
    print_summary(scene.primitives.size(), result->fragments.size(), outputs);
  return kExitOk;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.LIMITS, FAST.THREADS.DETERMINISTIC
// Calls emit for every fragment of the prepared scene in (prim, y, x, seg, sample) order, on
// rq.options.threads threads; exceptions thrown by emit stop it and pass through. Returns the
// primitive that needs to hold more than 2 * rq.max_fragments entries to be sorted, if any
// (nothing of it or after it is emitted).
std::optional<std::size_t> stream_fragments(const PreparedScene& scene, const RenderRequest& rq,
                                            const std::function<void(const Fragment&)>& emit,
                                            const StreamEncoding* encoding) {
  if (rq.options.threads <= 1) {
    for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
      if (!for_each_fragment_bounded(scene, p, 2 * rq.max_fragments, rq.options, emit))
        return p;
    }
    return std::nullopt;
  }
  // rule: FAST.THREADS.DETERMINISTIC, SCENE.INPUT.LIMITS
  // A pool created once produces work units in order: a band of rows of a streamed triangle
  // whose walk visits more than kUnitPixels pixels (so that several threads draw one large
  // triangle), or consecutive other primitives, up to kChunk of them or kUnitPixels of their
  // work. Their fragments reach this thread in order through the bounded buffers of
  // stream_ordered (a unit ahead of the writer waits), where emit checks them as above: the
  // outputs, the error and the primitive it names are those of one thread, and at most
  // buffers.max_held() fragments are buffered, whatever the scene. A unit's fragments mostly
  // fit its own buffer (a band's always do): a thread finishes the unit it draws while the
  // writer is still on an earlier one, so the threads draw in parallel (with bands of 2^16
  // pixels and a buffer of 2048 fragments, the thread ahead waited, and two threads took 1.4x
  // the time of one). A window of T + 6 units lets the threads run ahead of the writer by
  // several small units (with T + 1, they waited for it at every unit). A primitive that must
  // be held to be sorted is held by the thread that draws it, as with one thread.
  const StreamBuffers buffers{
      .batch = 1536, .batches_per_unit = 2, .window = std::size_t{rq.options.threads} + 6};
  constexpr std::size_t kChunk = 64; // primitives per unit: amortises the hand-over
  const auto kUnitPixels = static_cast<std::int64_t>(buffers.batch * buffers.batches_per_unit);
  struct Unit {
    std::size_t first = 0, end = 0;        // whole primitives [first, end), or
    std::int32_t y_first = 0, y_last = -1; // with end == first + 1 and banded: these rows
    bool banded = false;
  };
  struct TooManyHeld {
    std::size_t p;
  };
  const std::size_t n = scene.primitives.size();
  // The rows of primitive p's bands, when it is split: at most kUnitPixels pixels (at least one
  // row).
  const auto band_rows = [&](std::size_t p) -> std::int32_t {
    if (!is_streamed(scene, p))
      return 0;
    const PixelBounds b = streamed_bounds(scene, p);
    const std::int64_t w = std::int64_t{b.x1} - b.x0 + 1, h = std::int64_t{b.y1} - b.y0 + 1;
    if (b.y1 < b.y0 || w * h <= kUnitPixels)
      return 0;
    const std::int64_t rows = std::max<std::int64_t>(1, kUnitPixels / w);
    return rows >= h ? 0 : static_cast<std::int32_t>(rows);
  };
  // The plan, advanced under the pool's lock: unit i goes to slot i % window.
  std::vector<Unit> units(buffers.window);
  std::size_t next_p = 0;  // the first primitive not yet planned
  std::int32_t next_y = 0; // within a banded primitive next_p: its next band's first row
  bool in_bands = false;
  const auto plan = [&](std::size_t i) {
    if (next_p >= n)
      return false;
    Unit& u = units[i % buffers.window];
    u = Unit{};
    if (const std::int32_t rows = band_rows(next_p); rows > 0) {
      const PixelBounds b = streamed_bounds(scene, next_p);
      if (!in_bands) {
        in_bands = true;
        next_y = b.y0;
      }
      u = Unit{
          next_p, next_p + 1, next_y,
          static_cast<std::int32_t>(std::min<std::int64_t>(std::int64_t{next_y} + rows - 1, b.y1)),
          true};
      if (u.y_last >= b.y1) {
        in_bands = false;
        ++next_p;
      } else {
        next_y = u.y_last + 1;
      }
      return true;
    }
    u.first = next_p;
    std::uint64_t work = 0; // the chunk's sample tests: a bound on its fragments
    while (next_p < n && next_p - u.first < kChunk &&
           (next_p == u.first ||
            (band_rows(next_p) == 0 && work < static_cast<std::uint64_t>(kUnitPixels)))) {
      work += primitive_work(scene, next_p);
      ++next_p;
    }
    u.end = next_p;
    return true;
  };
  try {
    stream_ordered(
        rq.options.threads, buffers, plan,
        [&](std::size_t i, const std::function<void(const Fragment&)>& put) {
          const Unit u = units[i % buffers.window];
          if (u.banded) {
            for_each_fragment_in_rows(scene, u.first, u.y_first, u.y_last, rq.options, put);
            return;
          }
          for (std::size_t p = u.first; p < u.end; ++p) {
            if (!for_each_fragment_bounded(scene, p, 2 * rq.max_fragments, rq.options, put))
              throw TooManyHeld{p};
          }
        },
        emit, encoding);
  } catch (const TooManyHeld& held) {
    return held.p;
  }
  return std::nullopt;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.LIMITS, SCENE.OUTPUT.MSAA
// Renders a scene without pipeline state: fragments streamed primitive by primitive into the
// outputs, the coverage picture and the resolved target.
int render_window(const PreparedScene& scene, const RenderRequest& rq) {
  if (rq.png_depth || rq.depth_out_path) {
    return error(std::string(rq.png_depth ? "--png-depth" : "--depth-out") +
                 ": a window-space scene without \"depth\" has no depth buffer (SCENE.PIPELINE)");
  }
  // rule: SCENE.INPUT.LIMITS
  // The work limit, checked before any primitive is rasterized: the plain traversal's sample
  // tests, the same for every traversal, instruction set and thread count.
  if (const auto p = first_primitive_over_work(scene, rq.max_work))
    return error("render: primitives[" + std::to_string(*p) + "] " +
                 work_limit_problem(rq.max_work) + std::string(kMaxWorkHint));
  const std::optional<int> picture_scale = picture_scale_of(scene.width, scene.height, rq);
  if (!picture_scale)
    return kExitBadInput;

  // rule: MSAA.LIMITS, MSAA.RESOLVE.AVERAGE
  if (rq.resolve_path) {
    if (auto err = resolve_too_large(scene.width, scene.height, scene.msaa.count()))
      return error(*err);
  }

  OutputFile fragments_file, png_file, resolve_file;
  if (rq.fragments_path) {
    if (auto err = fragments_file.open(*rq.fragments_path))
      return error(*err);
  }
  if (rq.png_path) {
    if (auto err = png_file.open(*rq.png_path))
      return error(*err);
  }
  if (rq.resolve_path) {
    if (auto err = resolve_file.open(*rq.resolve_path))
      return error(*err);
  }

  // Fragments are streamed primitive by primitive in the (prim, y, x, seg) order of
  // SCENE.OUTPUT.FRAGMENTS: a triangle's as the traversal finds them (memory independent of
  // their number), a point's or line's after the kernel sorts that one primitive's list. The
  // coverage map (for the picture) is width * height.
  std::optional<io::FragmentWriter> writer;
  std::optional<io::FragmentBinaryWriter> binary_writer; // rule: SCENE.OUTPUT.BINARY
  if (rq.fragments_path && rq.fragments_binary)
    binary_writer.emplace(fragments_file.get(), binary_header(rq, scene));
  else if (rq.fragments_path)
    writer.emplace(fragments_file.get());
  std::unique_ptr<io::CoverageMap> coverage;
  if (rq.png_path) {
    coverage = std::make_unique<io::CoverageMap>(scene.width, scene.height);
    if (io::samples_visible(scene, *picture_scale))
      coverage->record_samples(scene.msaa.count());
  }
  // The resolve accumulates the fragments' samples as they stream (the target's samples, at
  // most 256 MiB by MSAA.LIMITS, whatever the fragment count).
  std::optional<Resolver> resolver;
  if (rq.resolve_path) {
    auto started = Resolver::start(scene);
    if (const auto* err = std::get_if<SceneError>(&started))
      return error("--resolve: " + err->what());
    resolver.emplace(std::move(std::get<Resolver>(started)));
  }
  struct ResolveFailed {
    SceneError error;
  };
  struct NotInBinary {
    std::uint32_t prim;
    std::string field;
  };
  bool in_order = true;
  std::uint64_t fragment_count = 0;
  // rule: SCENE.INPUT.LIMITS
  // The work limit: counted while streaming; the first fragment beyond it stops the traversal
  // (the exception unwinds out of the kernel's walk) and the outputs, still under their
  // temporary names, are removed by ~OutputFile.
  struct TooManyFragments {};
  // rule: FAST.THREADS.DETERMINISTIC
  // With threads, the fragments' text is made on the threads that draw them and only
  // concatenated here (the same bytes as one thread's writer makes).
  // With nothing but the fragment list to write, this thread sees each batch in brief.
  const bool encoded = writer && rq.options.threads > 1;
  StreamEncoding encoding{
      .encode = &io::FragmentWriter::encode,
      .consume_bytes = [&](std::string_view text) { writer->add_encoded_text(text); },
      .consume_summary = nullptr};
  if (encoded && !rq.png_path && !rq.resolve_path) {
    encoding.consume_summary = [&](const BatchSummary& b) {
      fragment_count += b.count;
      if (fragment_count > rq.max_fragments)
        throw TooManyFragments{};
      in_order = writer->add_without_text(b) && in_order;
    };
  }
  const auto emit = [&](const Fragment& f) {
    if (++fragment_count > rq.max_fragments)
      throw TooManyFragments{};
    if (writer)
      in_order = (encoded ? writer->add_without_text(f) : writer->add(f)) && in_order;
    if (binary_writer) {
      switch (binary_writer->add(f)) {
      case io::FragmentBinaryWriter::Added::kOk:
        break;
      case io::FragmentBinaryWriter::Added::kOutOfOrder:
        in_order = false;
        break;
      case io::FragmentBinaryWriter::Added::kUnsupported:
        throw NotInBinary{
            f.prim, io::unsupported_field(f, io::fragment_binary_header(scene)).value_or("field")};
      }
    }
    if (coverage)
      coverage->add_fragment(f);
    if (resolver) {
      if (auto err = resolver->add(f, fragment_count - 1))
        throw ResolveFailed{*err};
    }
  };
  const auto too_many_held = [&](std::size_t p) {
    return error(
        "render: primitives[" + std::to_string(p) + "] touches more than " +
        std::to_string(2 * rq.max_fragments) +
        " pixels or fragments that must be held to be sorted (limit SCENE.INPUT.LIMITS, 2 x "
        "--max-fragments)" +
        std::string(kMaxFragmentsHint));
  };
  // A primitive that is collected before it is emitted holds at most 2 * rq.max_fragments
  // entries: a pixel is held at most twice (once per triangle of a point or quadrilateral
  // segment), so one that needs more has more than rq.max_fragments fragments, except when
  // the sample mask removes the samples it covers (then the limit counts touched pixels).
  try {
    if (const auto p = stream_fragments(scene, rq, emit, encoded ? &encoding : nullptr))
      return too_many_held(*p);
  } catch (const TooManyFragments&) {
    return error("render: more than " + std::to_string(rq.max_fragments) +
                 " fragments (limit SCENE.INPUT.LIMITS)" + std::string(kMaxFragmentsHint));
  } catch (const ResolveFailed& e) {
    return error("--resolve: " + e.error.what());
  } catch (const NotInBinary& e) {
    // rule: SCENE.OUTPUT.BINARY
    return error("--fragments: the binary format holds prim, seg, x, y and mask; primitives[" +
                 std::to_string(e.prim) + "]'s fragments have a \"" + e.field +
                 "\" field (write JSON: --fragments-format json; SCENE.OUTPUT.BINARY)");
  }
  if (!in_order)
    return error(kFragmentsOutOfOrder);
  if ((writer && !writer->finish()) || (binary_writer && !binary_writer->finish()))
    return error(*rq.fragments_path + ": write failed");
  if (rq.png_path) {
    const io::Image image = io::draw_picture(scene, *coverage, *picture_scale);
    if (auto err = io::write_png(png_file.get(), image))
      return error(*rq.png_path + ": " + *err);
  }
  // rule: MSAA.RESOLVE.AVERAGE
  if (resolver) {
    if (auto err = write_resolved_image(resolver->finish(), resolve_file.get(), *rq.resolve_path))
      return error(*err);
  }
  // No partial result: when one output cannot be moved into place, the ones already in place
  // are removed.
  const std::vector<Output> outputs = {{&fragments_file, &rq.fragments_path},
                                       {&png_file, &rq.png_path},
                                       {&resolve_file, &rq.resolve_path}};
  if (auto err = commit_outputs(outputs))
    return error(*err);
  if (rq.to_stdout == 0 && verbosity() != Verbosity::kQuiet)
    print_summary(scene.primitives.size(), fragment_count, outputs);
  return kExitOk;
}

int write_counts(const FragmentCounts& counts, const RenderRequest& rq);

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY
// Ends a list written from runs into file (--fragments, the only output): the writer finished,
// the file committed and the summary printed; the error's status where one fails.
int finish_list(OutputFile& file, io::FragmentWriter* json, io::FragmentBinaryWriter* binary,
                bool in_order, const RenderRequest& rq, std::size_t primitives,
                std::uint64_t covered) {
  if (!in_order)
    return error(kFragmentsOutOfOrder);
  if (!(binary ? binary->finish() : json->finish()))
    return error(*rq.fragments_path + ": write failed");
  const std::vector<Output> outputs = {{&file, &rq.fragments_path}};
  if (auto err = commit_outputs(outputs))
    return error(*err);
  if (rq.to_stdout == 0 && verbosity() != Verbosity::kQuiet)
    print_summary(primitives, covered, outputs);
  return kExitOk;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, SCENE.INPUT.FAST_READER
// rule: FAST.BATCH.EQUALS.PLAIN
// render --fragments OUT (the only output, JSON or binary) of a scene of the fast reader's
// form: the fragment list written from the batch unit's runs (fast_runs_batch; with --threads,
// units of triangles and bands of rows made into bytes on the threads: write_fast_list), with
// no scene prepared and no fragment record kept. nullopt where it declines (another output, the
// plain traversal, the form, the target, a work bound or a fragment count over its limit, a vertex
// that does not snap): the caller renders the scene as any other, which names every error.
// The same bytes as that path (the tests compare them).
std::optional<int> render_fast_form_list(std::string_view text, const RenderRequest& rq) {
  if (!rq.fragments_path || rq.png_path || rq.resolve_path || rq.png_depth || rq.depth_out_path)
    return std::nullopt;
  const std::optional<FastForm> form = load_fast_form(text, rq.options, rq.max_work);
  if (!form)
    return std::nullopt;
  const PreparedScene& scene = *form->base.prepared;
  const Isa isa = effective_isa(rq.options);
  // The fragment limit and the vertices: the list stops (declines) at a vertex that does not
  // snap or past the limit, and a temporary file is then removed; what is written in place
  // (standard output, a device, a pipe) cannot be taken back, so there the count comes first
  // (a fraction of the time of the runs; on the threads too) and nothing is written for such a
  // scene.
  std::optional<std::uint64_t> counted;
  if (io::OutputFile::writes_in_place(*rq.fragments_path)) {
    counted =
        count_fast_list(form->xy, scene.width, scene.height, scene.state, isa, rq.options.threads);
    if (!counted || *counted > rq.max_fragments)
      return std::nullopt;
  }
  OutputFile file;
  if (auto err = file.open(*rq.fragments_path))
    return error(*err);
  std::optional<io::FragmentWriter> json;
  std::optional<io::FragmentBinaryWriter> binary; // rule: SCENE.OUTPUT.BINARY
  if (rq.fragments_binary)
    binary.emplace(file.get(), binary_header(rq, scene));
  else
    json.emplace(file.get());
  const FastListResult r =
      write_fast_list(form->xy, scene.width, scene.height, scene.state, isa, rq.options.threads,
                      rq.max_fragments, json ? &*json : nullptr, binary ? &*binary : nullptr);
  if (!r.ok || (counted && (r.declined || r.covered != *counted)))
    return error("internal error: the batch unit's runs disagree with its count (" +
                 std::to_string(r.covered) + " fragments, counted " +
                 std::to_string(counted.value_or(r.covered)) + ")");
  if (r.declined)
    return std::nullopt; // file (a temporary) is removed
  return finish_list(file, json ? &*json : nullptr, binary ? &*binary : nullptr, r.in_order, rq,
                     form->xy.size() / 6, r.covered);
}

namespace {

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, SCENE.INPUT.FAST_READER, SCENE.INPUT.LIMITS
// rule: FAST.THREADS.DETERMINISTIC
// The fragment list of a scene of the fast form written as the text is read
// (io::stream_triangles_fast): each chunk's work bound added up (declining past the limit, as
// load_fast_form does) and its runs written by write_fast_list into the output's temporary
// file, on this thread or, with two or more threads, on a writing thread beside the reader
// (ChunkPipe). The same bytes as the whole list written at once: the chunks are written in
// order, each triangle's runs its own.
class ListStream final : public io::TriangleStream {
public:
  explicit ListStream(const RenderRequest& rq) : rq_(rq) {}

  bool begin(const Scene& head) override {
    std::optional<PreparedScene> scene = prepared_head(head);
    if (!scene)
      return false;
    scene_ = std::move(*scene);
    if (file_.open(*rq_.fragments_path))
      return false; // the usual path names the error
    if (rq_.fragments_binary)
      binary_.emplace(file_.get(), binary_header(rq_, scene_));
    else
      json_.emplace(file_.get());
    pipe_.emplace(rq_.options.threads >= 2,
                  [this](std::span<const float> xy) { return write(xy); });
    return true;
  }
  bool triangles(std::span<const float> xy) override { return pipe_->push(xy); }

  // Once the text is read: kExitOk or an error's exit status when the list was written and
  // committed (or failed to be), nullopt when a chunk was refused or the text declined (the
  // temporary is then removed).
  std::optional<int> finish(bool read) {
    refused_ = pipe_ && !pipe_->finish();
    if (!read || !pipe_ || refused_)
      return std::nullopt;
    return finish_list(file_, json_ ? &*json_ : nullptr, binary_ ? &*binary_ : nullptr, in_order_,
                       rq_, first_prim_, covered_);
  }
  // After finish(): whether a chunk was refused (a vertex that does not snap, a limit passed):
  // reading the text another way would refuse it too.
  [[nodiscard]] bool refused() const { return refused_; }
  [[nodiscard]] bool disagreed() const { return disagreed_; }

private:
  bool write(std::span<const float> xy) {
    if (!add_work_bounds(xy, scene_.width, scene_.height, rq_.max_work, work_))
      return false;
    const FastListResult r =
        write_fast_list(xy, scene_.width, scene_.height, scene_.state, effective_isa(rq_.options),
                        1, rq_.max_fragments - covered_, json_ ? &*json_ : nullptr,
                        binary_ ? &*binary_ : nullptr, first_prim_);
    disagreed_ = disagreed_ || !r.ok;
    if (r.declined || !r.ok)
      return false;
    covered_ += r.covered;
    in_order_ = in_order_ && r.in_order;
    first_prim_ += static_cast<std::uint32_t>(xy.size() / 6);
    return true;
  }

  const RenderRequest& rq_;
  PreparedScene scene_;
  OutputFile file_;
  std::optional<io::FragmentWriter> json_;
  std::optional<io::FragmentBinaryWriter> binary_; // rule: SCENE.OUTPUT.BINARY
  double work_ = 0;
  std::uint64_t covered_ = 0;
  std::uint32_t first_prim_ = 0;
  bool in_order_ = true;
  bool refused_ = false;
  bool disagreed_ = false;
  std::optional<ChunkPipe> pipe_; // last: stopped before the members its thread uses
};

} // namespace

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.BINARY, SCENE.INPUT.FAST_READER
// render --fragments FILE (the only output, a file written through a temporary) of a scene
// whose root keys come before its list: the list written as the text is read (ListStream).
// nullopt where it declines (the form, a key after the list, a target or state the fast form
// does not take, output written in place); `refused` then says whether a chunk was refused
// (a vertex that does not snap, a limit passed), where the coordinates path would decline too.
std::optional<int> render_streamed_list(std::string_view text, const RenderRequest& rq,
                                        bool& refused) {
  refused = false;
  if (!rq.fragments_path || rq.png_path || rq.resolve_path || rq.png_depth || rq.depth_out_path ||
      rq.options.traversal != Traversal::kFast ||
      io::OutputFile::writes_in_place(*rq.fragments_path))
    return std::nullopt;
  // A JSON list on two or more threads is made into text on all of them, a large triangle in
  // bands (write_fast_list's units): one writing thread beside the reader made two large
  // triangles' text on one core (2^25 fragments into a file: 1.44 s streamed, 1.31 s in units,
  // 1.50 s on one thread). On 10^6 small triangles both ways take 251 ms.
  if (!rq.fragments_binary && rq.options.threads >= 2)
    return std::nullopt;
  ListStream stream(rq);
  const bool read = io::stream_triangles_fast(text, stream).has_value();
  const std::optional<int> done = stream.finish(read);
  if (stream.disagreed())
    return error("internal error: the batch unit's runs disagree with its count");
  refused = stream.refused();
  return done;
}

// rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.LIMITS
// Writes the counts alone (--count): the batch counter where the scene allows it, else the
// fragments streamed as for --fragments (window-space scenes) or run_pipeline's (pipeline
// scenes), counted without being kept. Helper lanes are not counted.
int render_count(const LoadedScene& loaded, const RenderRequest& rq) {
  std::optional<FragmentCounts> counts;
  const auto count_all = [&](const std::vector<Fragment>& fragments) {
    for (const Fragment& f : fragments) {
      if (!f.helper)
        counts->add(f.prim, f.x, f.y);
    }
  };
  if (!loaded.prepared) {
    const Scene& scene = loaded.scene;
    const std::optional<pipe::PipeResult> result =
        run_pipeline_or_report(scene, rq.options, rq.max_fragments, rq.pipeline_plain, rq.max_work);
    if (!result)
      return kExitBadInput;
    counts.emplace(scene.primitives.size(), scene.width, scene.height);
    count_all(result->fragments);
  } else {
    const PreparedScene& scene = *loaded.prepared;
    // rule: SCENE.INPUT.LIMITS
    if (const auto p = first_primitive_over_work(scene, rq.max_work))
      return error("render: primitives[" + std::to_string(*p) + "] " +
                   work_limit_problem(rq.max_work) + std::string(kMaxWorkHint));
    counts = batch_counts(loaded, rq.options);
    if (!counts) {
      counts.emplace(scene.primitives.size(), scene.width, scene.height);
      const auto emit = [&](const Fragment& f) {
        if (!f.helper)
          counts->add(f.prim, f.x, f.y);
      };
      if (const auto p = stream_fragments(scene, rq, emit, nullptr)) {
        return error(
            "render: primitives[" + std::to_string(*p) + "] touches more than " +
            std::to_string(2 * rq.max_fragments) +
            " pixels or fragments that must be held to be sorted (limit SCENE.INPUT.LIMITS, 2 x "
            "--max-fragments)" +
            std::string(kMaxFragmentsHint));
      }
    }
  }
  return write_counts(*counts, rq);
}

// rule: SCENE.OUTPUT.COUNT
// Writes --count's file and the summary.
int write_counts(const FragmentCounts& counts, const RenderRequest& rq) {
  OutputFile file;
  if (auto err = file.open(*rq.count_path))
    return error(*err);
  const std::string text = counts_json(counts);
  if (std::fwrite(text.data(), 1, text.size(), file.get()) != text.size() ||
      std::fflush(file.get()) != 0)
    return error(*rq.count_path + ": write failed");
  if (auto err = file.commit())
    return error(*err);
  if (rq.to_stdout == 0 && verbosity() != Verbosity::kQuiet) {
    std::uint64_t total = 0;
    for (const std::uint64_t n : counts.per_primitive)
      total += n;
    print_summary(counts.per_primitive.size(), total, {{&file, &rq.count_path}});
  }
  return kExitOk;
}

// Reads the value v of a limit flag (--max-fragments, --max-work) into out: an integer in
// [1, 2^max_bits]. Returns the exit code of the one-line error otherwise.
// rule: SCENE.INPUT.LIMITS
std::optional<int> parse_limit(const char* flag, const std::optional<std::string>& v, int max_bits,
                               std::uint64_t& out) {
  const auto n = v ? parse_int(*v, 1, std::int64_t{1} << max_bits) : std::nullopt;
  if (!n) {
    return error(std::string(flag) + " needs an integer in [1, 2^" + std::to_string(max_bits) +
                 "], got " + shown_value(v));
  }
  out = static_cast<std::uint64_t>(*n);
  return std::nullopt;
}

// Reads render's arguments into rq. Returns the exit code when render stops here (--help, a
// usage error), nullopt to go on.
std::optional<int> parse_render_args(const Args& args, RenderRequest& rq) {
  // rule: SCENE.OUTPUT.FRAGMENTS
  CommandLine cl("render", "Rasterize a scene (spec/scene.md; pipeline scenes through the "
                           "pipeline, SCENE.OUTPUT.PIPELINE). \"-\" reads standard input or "
                           "writes one output to standard output.");
  std::vector<std::string> scenes;
  std::optional<std::string> scale, max_fragments, max_work, threads, traversal, isa,
      fragments_format;
  cl.scene_files(scenes);
  cl.value("--fragments", rq.fragments_path, "OUT.json",
           "write the fragment list, sorted by (prim, y, x)", "--fragments needs a file name");
  cl.value("--fragments-format", fragments_format, "json|binary|binary-v1",
           "the fragment list's format: JSON, or the compact binary runs of "
           "SCENE.OUTPUT.BINARY (version 2, 8 bytes a run; binary-v1: version 1, 20 bytes a "
           "run) (default: binary when OUT ends in .bin)",
           "--fragments-format needs \"json\", \"binary\" or \"binary-v1\", got nothing");
  cl.value("--count", rq.count_path, "OUT.json",
           "write the counts alone: fragments per primitive and per pixel (overdraw), from the "
           "batch counter where the scene allows (SCENE.OUTPUT.COUNT)",
           "--count needs a file name");
  cl.value("--png", rq.png_path, "OUT.png",
           "draw the target magnified (the pixel grid, pixel centres, snapped edges, covered "
           "pixels by primitive, overlaps hatched in red; sample points of multisampled scenes)",
           "--png needs a file name");
  cl.value("--scale", scale, "N",
           "the picture's magnification (default 32, less for large "
           "targets; at most 4096 pixels a side)",
           "--scale needs an integer in [1, 4096], got nothing");
  cl.value("--resolve", rq.resolve_path, "OUT.png",
           "write the resolved target as an RGBA PNG (MSAA.RESOLVE.AVERAGE, MSAA.LIMITS)",
           "--resolve needs a file name");
  cl.value("--max-fragments", max_fragments, "N",
           "more fragments is an error (default 67108864, N in [1, 2^40]; SCENE.INPUT.LIMITS)",
           "--max-fragments needs an integer in [1, 2^40], got nothing");
  cl.value("--max-work", max_work, "N",
           "more sample tests is an error (default 68719476736, N in [1, 2^60]; "
           "SCENE.INPUT.LIMITS)",
           "--max-work needs an integer in [1, 2^60], got nothing");
  cl.value("--threads", threads, "N",
           "render with N threads (1 to 256, default 1), the same bytes as with one "
           "(FAST.THREADS.DETERMINISTIC)",
           "--threads needs an integer in [1, " + std::to_string(kMaxThreads) + "], got nothing");
  cl.value("--traversal", traversal, "plain|fast",
           "the coverage traversal (default fast), never the result (FAST.EQUALS.PLAIN)",
           "--traversal needs \"plain\" or \"fast\", got nothing");
  cl.value("--isa", isa, "scalar|avx2|avx512|auto",
           "the instruction set (default auto: the widest the processor runs)",
           "--isa needs \"scalar\", \"avx2\", \"avx512\" or \"auto\", got nothing");
  cl.flag("--png-depth", rq.png_depth,
          "pipeline scenes: draw the final depth buffer in grey (black near, white far)");
  cl.value("--depth-out", rq.depth_out_path, "OUT.json",
           "pipeline scenes: write the final depth buffer as JSON",
           "--depth-out needs a file name");
  cl.flag("--pipeline-plain", rq.pipeline_plain,
          "every optimization off (PIPE.OPT.*: binning, Hi-Z, early-Z, fast clear, the fast "
          "traversal), never changing the result");
  if (const auto stop = cl.parse(args, "render: "))
    return stop;
  for (const auto* path :
       {&rq.fragments_path, &rq.png_path, &rq.resolve_path, &rq.depth_out_path, &rq.count_path}) {
    if (*path && (*path)->empty()) {
      const char* name = path == &rq.fragments_path ? "--fragments"
                         : path == &rq.png_path     ? "--png"
                         : path == &rq.resolve_path ? "--resolve"
                         : path == &rq.count_path   ? "--count"
                                                    : "--depth-out";
      return usage_error(std::string(name) + " needs a file name");
    }
  }
  if (rq.pipeline_plain) {
    // rule: PIPE.OPT.TILES
    // Pipeline scenes: every optimization off; coverage scenes: the plain traversal.
    rq.options.traversal = Traversal::kPlain;
  }
  if (scale) {
    const auto n = parse_int(*scale, 1, io::kMaxPictureSide);
    if (!n)
      return error("--scale needs an integer in [1, 4096], got " + shown_value(scale));
    rq.scale = static_cast<int>(*n);
  }
  // rule: SCENE.INPUT.LIMITS
  if (max_fragments) {
    if (const auto status = parse_limit("--max-fragments", max_fragments, 40, rq.max_fragments))
      return *status;
  }
  if (max_work) {
    if (const auto status = parse_limit("--max-work", max_work, 60, rq.max_work))
      return *status;
  }
  if (threads) {
    // rule: FAST.THREADS.DETERMINISTIC
    const auto n = parse_int(*threads, 1, kMaxThreads);
    if (!n) {
      return error("--threads needs an integer in [1, " + std::to_string(kMaxThreads) + "], got " +
                   shown_value(threads));
    }
    rq.options.threads = static_cast<unsigned>(*n);
  }
  if (traversal) {
    const auto t = parse_traversal(*traversal);
    if (!t)
      return error("--traversal needs \"plain\" or \"fast\", got " + shown_value(traversal));
    rq.options.traversal = *t;
  }
  if (isa) {
    // rule: FAST.ISA.DISPATCH
    if (*isa == "auto") {
      rq.options.isa = std::nullopt;
    } else {
      const auto parsed = parse_isa(*isa);
      if (!parsed) {
        return error("--isa needs \"scalar\", \"avx2\", \"avx512\" or \"auto\", got " +
                     shown_value(isa));
      }
      if (!isa_supported(*parsed)) {
        return error("--isa " + *isa + ": this processor (or this build) cannot run " + *isa +
                     " (" + std::string(kMaxIsaVariable) + " may cap it); use --isa auto (here " +
                     std::string(to_string(best_isa())) + ")");
      }
      rq.options.isa = *parsed;
    }
  }
  // rule: FAST.ISA.DISPATCH
  if (const char* cap = std::getenv(kMaxIsaVariable);
      cap != nullptr && *cap != '\0' && !parse_isa(cap)) {
    return error(std::string(kMaxIsaVariable) + " needs \"scalar\", \"avx2\" or \"avx512\", got " +
                 shown_value(cap));
  }
  if (const auto status = take_scene_argument("render", scenes, rq.scene_path))
    return *status;
  if (!rq.fragments_path && !rq.png_path && !rq.resolve_path && !rq.depth_out_path &&
      !rq.count_path) {
    return usage_error("render: give --fragments OUT.json, --png OUT.png, --resolve OUT.png, "
                       "--depth-out OUT.json or --count OUT.json");
  }
  // rule: SCENE.OUTPUT.COUNT
  if (rq.count_path && (rq.fragments_path || rq.png_path || rq.resolve_path || rq.depth_out_path)) {
    return usage_error("render: --count writes the counts alone; give it without --fragments, "
                       "--png, --resolve and --depth-out");
  }
  // rule: SCENE.OUTPUT.BINARY
  if (fragments_format) {
    if (!rq.fragments_path)
      return usage_error("render: --fragments-format needs --fragments");
    if (*fragments_format != "json" && *fragments_format != "binary" &&
        *fragments_format != "binary-v1") {
      return error("--fragments-format needs \"json\", \"binary\" or \"binary-v1\", got " +
                   shown_value(fragments_format));
    }
    rq.fragments_binary = *fragments_format != "json";
    rq.binary_version = *fragments_format == "binary-v1" ? 1 : 2;
  } else if (rq.fragments_path) {
    rq.fragments_binary = rq.fragments_path->size() > 4 &&
                          rq.fragments_path->compare(rq.fragments_path->size() - 4, 4, ".bin") == 0;
  }
  rq.to_stdout =
      (rq.fragments_path && *rq.fragments_path == "-") + (rq.png_path && *rq.png_path == "-") +
      (rq.resolve_path && *rq.resolve_path == "-") +
      (rq.depth_out_path && *rq.depth_out_path == "-") + (rq.count_path && *rq.count_path == "-");
  if (rq.to_stdout > 1) {
    return usage_error("render: only one of --fragments, --png and --resolve can be standard "
                       "output (--depth-out counts too)");
  }
  // rule: SCENE.INPUT.ERRORS
  // Two outputs naming one file ("F" and "./F", or a link to it) would overwrite each other:
  // refused before any work, by the files' canonical paths.
  const std::pair<const char*, const std::optional<std::string>*> outputs[] = {
      {"--fragments", &rq.fragments_path},
      {"--png", &rq.png_path},
      {"--resolve", &rq.resolve_path},
      {"--depth-out", &rq.depth_out_path}};
  for (std::size_t i = 0; i < std::size(outputs); ++i) {
    for (std::size_t j = i + 1; j < std::size(outputs); ++j) {
      const std::optional<std::string>& a = *outputs[i].second;
      const std::optional<std::string>& b = *outputs[j].second;
      if (a && b && *a != "-" && *b != "-" && same_output_file(*a, *b)) {
        return error(std::string("render: ") + outputs[j].first + " " + *b +
                     " names the same file as " + outputs[i].first + " " + *a);
      }
    }
  }
  if (rq.scale && !rq.png_path)
    return usage_error("render: --scale needs --png");
  if (rq.png_depth && !rq.png_path)
    return usage_error("render: --png-depth needs --png");
  return std::nullopt;
}

} // namespace

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.PIPELINE, SCENE.INPUT.ERRORS
int run_render(const Args& args) {
  RenderRequest rq;
  if (const auto stop = parse_render_args(args, rq))
    return *stop;
  const std::optional<io::SceneText> text_file = read_scene_text(rq.scene_path);
  if (!text_file)
    return kExitBadInput;
  const std::string_view text = text_file->view();
  // rule: SCENE.OUTPUT.COUNT, SCENE.INPUT.FAST_READER
  // A large scene of triangles alone is counted from its coordinates, never prepared (the same
  // counts; the scene is loaded as any other wherever that path declines).
  if (rq.count_path) {
    if (const std::optional<FragmentCounts> counts =
            fast_form_counts(text, rq.options, rq.max_work))
      return write_counts(*counts, rq);
  } else {
    bool refused = false;
    if (const std::optional<int> done = render_streamed_list(text, rq, refused))
      return *done;
    if (!refused) {
      if (const std::optional<int> done = render_fast_form_list(text, rq))
        return *done;
    }
  }
  const auto loaded = load_scene_text(text, rq.scene_path);
  if (!loaded)
    return kExitBadInput;
  if (rq.count_path)
    return render_count(*loaded, rq);
  // A scene with pipeline state goes through the pipeline; one without, prepared by
  // load_scene(), is the pipeline's identity case, streamed in constant memory.
  if (!loaded->prepared)
    return render_pipeline(loaded->scene, rq);
  return render_window(*loaded->prepared, rq);
}

} // namespace rastrules::cli
