// SPDX-License-Identifier: MIT
// Properties of the two compact outputs of `rastrules render`:
// - SCENE.OUTPUT.BINARY: on random scenes of triangles, points, lines and line strips,
//   single-sample or multisampled (random patterns, masks, shading, centroids, quads,
//   derivatives), the binary writer either refuses a fragment that has a field the format does
//   not hold (and only such a fragment) or writes a file that reads back to exactly the fragment
//   list, with as many runs as the list has maximal runs of a row and the size the format
//   gives; every cut of that file, and the file with one byte more, is refused.
// - SCENE.OUTPUT.COUNT: on random triangle scenes (any raster state, shared edges, every kind
//   of triangle), the batch counter's counts (batch_counts, the path of `--count`) equal the
//   counts of the fragment list, per primitive and per pixel, and so does their JSON.
// Implements (properties for): SCENE.OUTPUT.BINARY, SCENE.OUTPUT.COUNT

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "count.hpp"
#include "msaa_gen.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/io/fragment_binary.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace io = rastrules::io;
namespace mg = rastrules::msaa_gen;
using rastrules::Fragment;

constexpr std::int32_t kMaxSide = 16;

// A scene of 1 to 13 primitives, in thirds: single-sample with nothing else asked for; a random
// pattern and sample mask alone (fragments the format holds); a random multisample state
// (centroids, sample shading, quads, derivatives: fields it does not hold).
rc::Gen<mg::MsScene> scene() {
  return rc::gen::exec([] {
    const int kind = *rc::gen::inRange(0, 3);
    mg::MsScene s = *mg::scene_on(kind == 0 ? mg::standard(1) : *mg::any_pattern(), kMaxSide);
    if (kind < 2) {
      if (kind == 0)
        s.sample_mask = 0xFFFFFFFFu;
      s.centroid.reset();
      s.shading = rastrules::ShadingRate::kPixel;
      s.quads = false;
      s.derivatives = rastrules::DerivativeMode::kNone;
    } else if (!s.centroid && !s.quads && s.derivatives == rastrules::DerivativeMode::kNone) {
      s.shading = rastrules::ShadingRate::kSample; // at least one field the format does not hold
    }
    const auto more = *rc::gen::inRange(0, 13);
    for (int i = 0; i < more; ++i)
      s.prims.push_back(*mg::prim(s.width, s.height, true, true));
    mg::make_valid(s);
    return s;
  });
}

std::string shown(const mg::MsScene& s) {
  std::ostringstream os;
  mg::show(s, os);
  return os.str();
}

// The file a writer makes of the fragments: nullopt when it refuses one (at `refused`).
std::optional<std::vector<std::uint8_t>> written(const std::vector<Fragment>& fragments,
                                                 const io::FragmentBinaryHeader& header,
                                                 std::size_t& refused) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::tmpfile(), &std::fclose);
  RC_ASSERT(f != nullptr);
  {
    io::FragmentBinaryWriter w(f.get(), header);
    for (std::size_t i = 0; i < fragments.size(); ++i) {
      const io::FragmentBinaryWriter::Added a = w.add(fragments[i]);
      RC_ASSERT(a != io::FragmentBinaryWriter::Added::kOutOfOrder);
      if (a == io::FragmentBinaryWriter::Added::kUnsupported) {
        refused = i;
        return std::nullopt;
      }
    }
    RC_ASSERT(w.finish());
  }
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(std::ftell(f.get())));
  std::rewind(f.get());
  RC_ASSERT(std::fread(bytes.data(), 1, bytes.size(), f.get()) == bytes.size());
  return bytes;
}

// The maximal runs of the list: a new one at a new primitive, segment or row, or a gap.
std::uint64_t runs_of(const std::vector<Fragment>& fragments) {
  std::uint64_t runs = 0;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const Fragment& f = fragments[i];
    const bool extends = i > 0 && fragments[i - 1].prim == f.prim &&
                         fragments[i - 1].seg == f.seg && fragments[i - 1].y == f.y &&
                         fragments[i - 1].x + 1 == f.x;
    runs += extends ? 0 : 1;
  }
  return runs;
}

// rule: SCENE.OUTPUT.BINARY
RC_GTEST_PROP(OutputBinary, ReadsBackToTheFragmentListOrRefusesAFieldItDoesNotHold, ()) {
  const mg::MsScene s = *scene();
  const auto prepared = rastrules::prepare(mg::to_kernel(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&prepared))
    RC_FAIL("kernel rejected a valid scene: " + err->what() + "\n" + shown(s));
  const auto& ps = std::get<rastrules::PreparedScene>(prepared);
  const std::vector<Fragment> fragments = rastrules::rasterize(ps);
  io::FragmentBinaryHeader header = io::fragment_binary_header(ps);
  RC_ASSERT((header.mask_bytes == 0) == rastrules::is_single_sample(ps.msaa));
  RC_ASSERT(header.version == 2); // the default
  header.version = *rc::gen::element<std::uint32_t>(1, 2);
  RC_CLASSIFY(header.version == 1, "version 1");

  std::size_t refused = 0;
  const auto bytes = written(fragments, header, refused);
  // The first fragment with a field the format does not hold, if any.
  std::optional<std::size_t> first_unheld;
  for (std::size_t i = 0; i < fragments.size() && !first_unheld; ++i)
    if (io::unsupported_field(fragments[i], header))
      first_unheld = i;
  RC_CLASSIFY(first_unheld.has_value(), "a field the format does not hold");
  RC_CLASSIFY(header.mask_bytes == 2, "masks stored");
  if (!bytes) {
    if (first_unheld != refused)
      RC_FAIL("the writer refused fragment " + std::to_string(refused) +
              ", which the format holds\n" + shown(s));
    return;
  }
  if (first_unheld)
    RC_FAIL("the writer took fragment " + std::to_string(*first_unheld) +
            ", which has a field the format does not hold\n" + shown(s));

  const auto back = io::read_fragment_binary(*bytes);
  if (const auto* err = std::get_if<std::string>(&back))
    RC_FAIL("the written file does not read back: " + *err + "\n" + shown(s));
  const io::FragmentBinary& r = std::get<io::FragmentBinary>(back);
  if (r.fragments != fragments)
    RC_FAIL("the file reads back to another fragment list\n" + shown(s));
  RC_ASSERT(r.header.width == static_cast<std::uint32_t>(ps.width));
  RC_ASSERT(r.header.height == static_cast<std::uint32_t>(ps.height));
  RC_ASSERT(r.header.samples == ps.msaa.pattern.count());
  RC_ASSERT(r.runs == runs_of(fragments));
  RC_ASSERT(r.header.version == header.version);
  // Size: header, the end record, and each run: version 1 its 20 bytes and its masks padded to
  // 4 bytes; version 2 its word, its masks padded to 8 bytes, and a control word before it for
  // a primitive that its step cannot reach (more than 2^21 - 1 on, or a segment) and another
  // for a segment other than the previous run's (none after a step).
  const std::uint64_t unit = header.version == 1 ? 4 : 8;
  std::uint64_t size = io::kFragmentBinaryHeaderBytes + io::kFragmentBinaryEndBytes;
  std::uint32_t prim = 0;
  std::int64_t seg = -1;
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    ++n;
    const bool last = i + 1 == fragments.size() || runs_of({fragments[i], fragments[i + 1]}) == 2;
    if (!last)
      continue;
    const Fragment& f = fragments[i];
    const std::int64_t f_seg = f.seg ? std::int64_t{*f.seg} : -1;
    size += header.version == 1 ? io::kFragmentBinaryRunBytes : io::kFragmentBinaryWordBytes;
    if (header.version == 2) {
      if (f.prim != prim) {
        if (f.prim - prim > io::kFragmentBinaryMaxStep || f_seg != -1)
          size += io::kFragmentBinaryWordBytes;
        prim = f.prim;
        seg = -1;
      }
      if (f_seg != seg)
        size += io::kFragmentBinaryWordBytes;
      seg = f_seg;
    }
    if (header.mask_bytes == 2)
      size += (2 * n + unit - 1) / unit * unit;
    n = 0;
  }
  RC_ASSERT(bytes->size() == size);

  // Every cut is refused (the end record is missing or damaged), and so is a byte more.
  const auto cut = *rc::gen::inRange<std::size_t>(0, bytes->size());
  RC_ASSERT(std::holds_alternative<std::string>(
      io::read_fragment_binary(std::span<const std::uint8_t>(bytes->data(), cut))));
  std::vector<std::uint8_t> longer = *bytes;
  longer.push_back(*rc::gen::arbitrary<std::uint8_t>());
  RC_ASSERT(std::holds_alternative<std::string>(io::read_fragment_binary(longer)));
}

// rule: SCENE.INPUT.LIMITS
// add_work_bounds (four triangles at a time in SSE2 lanes where it can) adds exactly the work of
// each triangle's triangle_bound, and refuses exactly the lists with a coordinate that is not
// finite, whatever the coordinates (huge, tiny, negative, zeros of both signs, infinities, NaN)
// and however many triangles (the lanes' tail).
RC_GTEST_PROP(OutputCount, WorkBoundsAddEachTrianglesBound, ()) {
  const auto coordinate = rc::gen::weightedOneOf<float>(
      {{40, rc::gen::map(rc::gen::inRange(0, 64), [](int v) { return static_cast<float>(v); })},
       {6, rc::gen::map(rc::gen::inRange(-40, 20000), [](int v) { return static_cast<float>(v); })},
       {6, rc::gen::map(rc::gen::inRange(-400000, 400000),
                        [](int v) { return static_cast<float>(v) / 64.0f; })},
       {4, rc::gen::element(0.0f, -0.0f, 1e-40f, -1e-40f, 16383.5f, 16384.0f, 1e7f, -1e7f, 3e38f,
                            -3e38f)}});
  const auto triangles = *rc::gen::inRange<std::size_t>(0, 14);
  std::vector<float> xy;
  for (std::size_t i = 0; i < 6 * triangles; ++i)
    xy.push_back(*coordinate);
  // A quarter of the lists: one coordinate not finite, anywhere.
  if (triangles > 0 && *rc::gen::inRange(0, 4) == 0)
    xy[*rc::gen::inRange<std::size_t>(0, xy.size())] = *rc::gen::element(
        std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
        std::numeric_limits<float>::quiet_NaN());
  const auto width = *rc::gen::inRange<std::int32_t>(1, 16385);
  const auto height = *rc::gen::inRange<std::int32_t>(1, 16385);
  bool finite = true;
  double want = 0;
  for (std::size_t i = 0; i < triangles; ++i) {
    const auto b = rastrules::cli::triangle_bound(&xy[6 * i], width, height);
    if (!b)
      finite = false;
    else
      want += b->work();
  }
  RC_CLASSIFY(!finite, "not finite");
  RC_CLASSIFY(triangles >= 4, "four or more");
  double work = 7; // added to
  const bool ok = rastrules::cli::add_work_bounds(xy, width, height, std::uint64_t{1} << 62, work);
  RC_ASSERT(ok == finite);
  if (finite)
    RC_ASSERT(work == 7 + want);
  // The limit: exactly at the sum passes, one below refuses.
  if (finite && want >= 1) {
    double w = 0;
    RC_ASSERT(
        rastrules::cli::add_work_bounds(xy, width, height, static_cast<std::uint64_t>(want), w));
    w = 0;
    RC_ASSERT(!rastrules::cli::add_work_bounds(xy, width, height,
                                               static_cast<std::uint64_t>(want) - 1, w));
  }
}

// rule: SCENE.OUTPUT.COUNT, FAST.BATCH.EQUALS.PLAIN
RC_GTEST_PROP(OutputCount, TheBatchCountsAreTheFragmentListsCounts, ()) {
  const rastrules::gen::TriScene t = *rastrules::gen::tri_scene(40, 24);
  rastrules::Scene scene = rastrules::gen::to_kernel_scene(t);
  auto loaded = rastrules::cli::load_scene(scene);
  if (const auto* err = std::get_if<rastrules::SceneError>(&loaded)) {
    // Bad input is the one-line error of prepare() (e.g. a vertex beyond the snap range).
    RC_CLASSIFY(true, "rejected");
    RC_ASSERT(!err->what().empty());
    return;
  }
  const auto& ls = std::get<rastrules::cli::LoadedScene>(loaded);
  RC_ASSERT(ls.prepared.has_value());
  rastrules::RenderOptions options;
  options.traversal = rastrules::Traversal::kFast;
  const auto batch = rastrules::cli::batch_counts(ls, options);
  RC_ASSERT(batch.has_value()); // single-sample triangles in window space: always the batch

  rastrules::cli::FragmentCounts listed(ls.scene.primitives.size(), ls.prepared->width,
                                        ls.prepared->height);
  rastrules::RenderOptions plain;
  plain.traversal = rastrules::Traversal::kPlain;
  for (const Fragment& f : rastrules::rasterize(*ls.prepared, plain))
    listed.add(f.prim, f.x, f.y);
  bool overdraw = false;
  for (std::size_t i = 0; listed.hits && i < listed.hits->size(); ++i)
    overdraw = overdraw || (*listed.hits)[i] > 1;
  RC_CLASSIFY(overdraw, "overdraw");
  if (batch->per_primitive != listed.per_primitive || batch->hits != listed.hits) {
    std::ostringstream os;
    rastrules::gen::showValue(t, os);
    RC_FAIL("the batch counts differ from the fragment list's\n" + os.str());
  }
  RC_ASSERT(rastrules::cli::counts_json(*batch) == rastrules::cli::counts_json(listed));
}

} // namespace
