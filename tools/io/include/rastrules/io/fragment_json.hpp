// SPDX-License-Identifier: MIT
// The fragment list output (spec/scene.md), written as a stream.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA,
//             SCENE.OUTPUT.PIPELINE

#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/parallel.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::io {

// What the fragments of a pipeline scene carry besides a plain fragment's fields
// (SCENE.OUTPUT.PIPELINE): "attr" when the scene declares attributes (named here, in order),
// "depth" and "passed" when it has a depth state (its format).
struct PipeOutputFields {
  std::vector<std::string> attributes;
  std::optional<pipe::DepthFormat> depth;
};

// Returns the fields the scene asks for.
[[nodiscard]] PipeOutputFields pipe_output_fields(const Scene& s);

// The text of runs of plain fragments (prim, x, y, mask 1, no other field), as FragmentWriter
// writes them: the head of the last primitive is kept, so that its next runs format only their
// row and columns (incremented in place: to_chars a pixel was most of a run's time).
// rule: SCENE.OUTPUT.FRAGMENTS
class RunText {
public:
  // Appends the lines of the n >= 1 fragments (prim, x + k, y, mask 1), k = 0 .. n - 1, each
  // as add(f) writes it; the first without its comma when first (the list's first fragment).
  // x + n - 1 must fit an int32_t.
  void append(std::string& out, std::uint32_t prim, std::int32_t y, std::int32_t x, std::uint32_t n,
              bool first);

private:
  bool has_prim_ = false;
  std::uint32_t prim_ = 0;
  // ",\n  {\"prim\": " prim_ ", \"x\": " (at most 30 bytes), padded: copied 32 bytes at a
  // time from head_ or head_ + 1.
  std::array<char, 40> head_{};
  std::size_t head_n_ = 0;
};

// Writes {"fragments": [...]} to a FILE*, one fragment per line, without holding the list in
// memory. The caller emits fragments in (prim, y, x, seg) order (SCENE.OUTPUT.FRAGMENTS); the
// writer checks that order and refuses fragments that break it. Fragments with a seg get a
// "seg" field, fragments with a coverage a "coverage" field (SCENE.OUTPUT.COVERAGE); the
// multisampling fields "sample", "helper", "centroid", "ddx" and "ddy" appear only when the
// fragment has them (SCENE.OUTPUT.MSAA).
// rule: SCENE.OUTPUT.FRAGMENTS
class FragmentWriter {
public:
  explicit FragmentWriter(std::FILE* out);
  // A writer of a pipeline scene's fragments (SCENE.OUTPUT.PIPELINE): add(f, data).
  FragmentWriter(std::FILE* out, PipeOutputFields fields);
  FragmentWriter(const FragmentWriter&) = delete;
  FragmentWriter& operator=(const FragmentWriter&) = delete;

  // Appends one fragment. Returns false (and writes nothing) when it does not come after the
  // previous one in (prim, y, x, seg) order.
  bool add(const Fragment& f);

  // Appends the n >= 1 fragments of primitive prim at x, x + 1, ..., x + n - 1 of row y (mask
  // 1, no other field): the same text as adding them one by one. Returns false (and writes
  // nothing) when the first does not come after the previous fragment.
  bool add_run(std::uint32_t prim, std::int32_t y, std::int32_t x, std::uint32_t n);

  // Appends one fragment of a pipeline scene with its data (nullptr: none, as run_pipeline
  // gives for a scene without clip space, depth or attributes): "part" after "prim" when it has
  // one, then the plain fields, then "bary" (when it has barycentrics), "attr", "depth" and
  // "passed" as the writer's fields say, "attr" and "depth" not for a killed fragment
  // (PIPE.DEPTH.KILL). Returns false (and writes nothing) when it does not come after the
  // previous one in (prim, part, y, x, seg, sample) order (a missing part first), or when its
  // data does not match the fields (one value per attribute, one depth per sample of the mask;
  // none for a killed fragment).
  bool add(const Fragment& f, const pipe::FragmentData* data);

  // Appends to out the text add(f) writes for f when f is not the first fragment: what the
  // threads of a render make of the fragments they draw (StreamEncoding), so that the writer
  // only concatenates.
  static void encode(const Fragment& f, std::string& out);

  // Checks f's place in the order and counts it as add(f) does, writing nothing: its text,
  // made by encode, comes through add_encoded_text in the same order.
  bool add_without_text(const Fragment& f);
  // The same for a batch of fragments in brief (StreamEncoding::consume_summary).
  bool add_without_text(const BatchSummary& batch);

  // Appends the text encode made of fragments add_without_text accepted (the comma before the
  // list's first fragment is dropped).
  void add_encoded_text(std::string_view text);

  // Closes the list. Returns false when any write failed.
  bool finish();

  [[nodiscard]] std::uint64_t count() const { return count_; }

private:
  void flush_buffer();

  std::FILE* out_;
  std::string buffer_;
  std::uint64_t count_ = 0;
  Fragment last_{};
  std::optional<std::uint32_t> last_part_;
  PipeOutputFields fields_;
  bool failed_ = false;
  bool text_started_ = false; // add_encoded_text has written a fragment's text
  RunText run_text_;
};

// Returns coverage_q16 / 65536 as its exact decimal: "0.5", "0.0000152587890625", "1.0"
// (always a point and at least one fraction digit; no trailing zeros otherwise).
// rule: SCENE.OUTPUT.COVERAGE
[[nodiscard]] std::string format_coverage(std::uint32_t coverage_q16);

// Returns v / 16 as its exact decimal: "3.5625", "-0.25", "1.0" (always a point and at least one
// fraction digit). Centroids and derivatives are multiples of 1/16 px (SCENE.OUTPUT.MSAA).
// rule: SCENE.OUTPUT.MSAA
[[nodiscard]] std::string format_sixteenths(std::int64_t sixteenths);

// Returns the centroid of a fragment of pixel (x, y) at offset o from its centre, in 1/16 px
// from the target's origin: (16 x + 8 + o.x, 16 y + 8 + o.y).
[[nodiscard]] std::array<std::int64_t, 2> centroid_sixteenths(std::int32_t x, std::int32_t y,
                                                              SampleOffset o);

// Returns the fragment list as one string (for small lists and tests).
[[nodiscard]] std::string fragments_to_json(const std::vector<Fragment>& fragments);

// The same for a pipeline scene's fragments and their data (SCENE.OUTPUT.PIPELINE; data empty
// or one entry per fragment, as in PipeResult); nullopt when a fragment is out of order, does
// not match the fields (as FragmentWriter::add) or the arrays differ in size.
[[nodiscard]] std::optional<std::string>
pipe_fragments_to_json(const std::vector<Fragment>& fragments,
                       const std::vector<pipe::FragmentData>& data, const PipeOutputFields& fields);

// Returns a stored depth value as written in the output: the UNORM integer for d16 and d24, the
// float32 in its shortest round-trip form for d32f (SCENE.OUTPUT.PIPELINE).
[[nodiscard]] std::string depth_text(const pipe::DepthValue& d, pipe::DepthFormat format);

// Writes the final depth buffer (`render --depth-out FILE.json`, SCENE.OUTPUT.PIPELINE):
// {"format": "d24", "width": W, "height": H, "samples": N, "depth": [...]} with
// width * height * samples values, index (y * W + x) * N + k, one target row per line.
// Returns false when a write failed or the buffer's size is not width * height * samples.
// rule: SCENE.OUTPUT.PIPELINE
[[nodiscard]] bool write_depth_buffer(std::FILE* out, std::int32_t width, std::int32_t height,
                                      std::uint32_t samples, pipe::DepthFormat format,
                                      const std::vector<pipe::DepthValue>& buffer);

} // namespace rastrules::io
