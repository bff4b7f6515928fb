// SPDX-License-Identifier: MIT
// The compact binary fragment list (SCENE.OUTPUT.BINARY): the fragments of
// SCENE.OUTPUT.FRAGMENTS as runs of consecutive pixels of one row, written as a stream and read
// back strictly. `rastrules render SCENE.json --fragments OUT.bin` writes it.
// Implements: SCENE.OUTPUT.BINARY

#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules::io {

// The file's first 8 bytes: 0x89 "RRF" CR LF 0x1A LF (a file damaged by a text-mode transfer
// or cut by a terminal does not pass for one).
inline constexpr std::uint8_t kFragmentBinaryMagic[8] = {0x89, 'R',  'R',  'F',
                                                         '\r', '\n', 0x1A, '\n'};
// Version 2 (the default) packs a run into one 64-bit word; version 1 takes 20 bytes a run.
inline constexpr std::uint32_t kFragmentBinaryVersion = 2;
inline constexpr std::size_t kFragmentBinaryHeaderBytes = 32;
inline constexpr std::size_t kFragmentBinaryRunBytes = 20; // version 1, before its masks
inline constexpr std::size_t kFragmentBinaryEndBytes = 24;
inline constexpr std::uint32_t kFragmentBinaryNoSeg = 0xFFFFFFFFu;
inline constexpr std::uint32_t kFragmentBinaryEnd = 0xFFFFFFFFu; // version 1's end "prim"
// Version 2's words (little-endian u64). A run: bits 0-14 n (1 .. 16384), 15-28 x, 29-42 y,
// 43-63 the step of prim from the previous run's (0 .. 2^21 - 1; a step other than 0 starts the
// new primitive with no segment). A control word: bits 0-14 zero, 15-31 its kind, 32-63 its
// value.
inline constexpr std::size_t kFragmentBinaryWordBytes = 8;
inline constexpr std::uint32_t kFragmentBinaryMaxStep = (std::uint32_t{1} << 21) - 1;
inline constexpr std::uint32_t kFragmentBinaryPrim = 1; // prim := value, no segment
inline constexpr std::uint32_t kFragmentBinarySeg = 2;  // seg := value (0xFFFFFFFF: none)
inline constexpr std::uint32_t kFragmentBinaryStop = 3; // the end record's first word (value 0)

// What the header says about the target and the masks.
struct FragmentBinaryHeader {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t samples = 1;
  // 0: every mask is 1 and none is stored (single-sample scenes, is_single_sample); 2: one
  // 16-bit mask a fragment.
  std::uint32_t mask_bytes = 0;
  std::uint32_t version = kFragmentBinaryVersion; // 1 or 2
};

// Returns the header a render of the prepared scene writes: its target, its sample count, and
// mask_bytes 0 exactly when the scene is single-sample (is_single_sample).
[[nodiscard]] FragmentBinaryHeader fragment_binary_header(const PreparedScene& scene);

// Writes the binary fragment list to a FILE* as a stream (a buffer of at most 1 MiB).
// The caller adds fragments in (prim, y, x, seg) order (SCENE.OUTPUT.FRAGMENTS).
// rule: SCENE.OUTPUT.BINARY
class FragmentBinaryWriter {
public:
  enum class Added {
    kOk,
    kOutOfOrder,  // f does not come after the previous fragment
    kUnsupported, // f has a field the format does not hold (unsupported_field(f) names it)
  };
  FragmentBinaryWriter(std::FILE* out, FragmentBinaryHeader header);
  FragmentBinaryWriter(const FragmentBinaryWriter&) = delete;
  FragmentBinaryWriter& operator=(const FragmentBinaryWriter&) = delete;

  // Appends one fragment (extending the current run when it is the next pixel of its row).
  Added add(const Fragment& f);
  // Appends the n >= 1 fragments of primitive prim at x, x + 1, ..., x + n - 1 of row y (no
  // segment, mask 1): the same file as adding them one by one. kUnsupported when the header
  // stores masks; kOutOfOrder when the first does not come after the previous fragment.
  Added add_run(std::uint32_t prim, std::int32_t y, std::int32_t x, std::uint32_t n) {
    const struct {
      std::uint32_t tri;
      std::int32_t y, x;
      std::uint32_t n;
    } one{0, y, x, n};
    return add_runs(&one, 1, prim);
  }
  // add_run for each of runs[0 .. count) in turn (each with .tri, .y, .x and .n: primitive
  // prim_base + tri); kOutOfOrder when any run was out of order (it is left out, as add_run
  // leaves it). Inline, with the writer's state in locals for the loop and the runs' bytes
  // staged on the stack: the batch unit hands over a chunk's runs at once (2.6 x 10^6 runs for
  // 10^6 small triangles, where a call a run, its state stored and reloaded through the writer
  // and an append a run took 15 % of `render --fragments OUT.bin`).
  template <class Run> Added add_runs(const Run* runs, std::size_t count, std::uint32_t prim_base) {
    if (header_.mask_bytes != 0)
      return Added::kUnsupported;
    const bool v1 = header_.version == 1;
    bool in_order = true;
    bool open = run_open_;
    Key first = run_first_;
    // The last fragment as one unsigned 128-bit key ordered as (prim, y, x): the order check
    // without a branch on each field.
    Order last = order_of(last_.prim, last_.y, last_.x);
    bool have_last = count_ > 0;
    std::uint32_t length = run_length_, prim = prim_;
    std::int64_t seg = seg_;
    std::uint64_t fragments = count_, written = runs_;
    char stage[kStageBytes + 3 * kFragmentBinaryWordBytes];
    char* out = stage;
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t p = prim_base + runs[i].tri;
      const std::int32_t y = runs[i].y, x = runs[i].x;
      const auto n = static_cast<std::uint32_t>(runs[i].n);
      // After last in (prim, y, x, seg) order, this run's seg (none) being the least.
      if (have_last && !(last < order_of(p, y, x))) [[unlikely]] {
        in_order = false;
        continue;
      }
      // The batch unit's runs never join (one a row of a triangle): a branch on the whole test,
      // not on each of its parts (the first, the same primitive, is a coin toss).
      const bool joins = open & (p == first.prim) & (first.seg == -1) & (y == first.y) &
                         (std::int64_t{x} == std::int64_t{first.x} + length);
      if (joins) [[unlikely]] {
        length += n;
      } else {
        if (open) {
          out = v1 ? put_fields(out, first, length) : put_run_word(out, first, length, prim, seg);
          ++written;
          if (out - stage >= static_cast<std::ptrdiff_t>(kStageBytes)) [[unlikely]] {
            buffer_.append(stage, static_cast<std::size_t>(out - stage));
            out = stage;
            if (buffer_.size() >= kBufferBytes)
              flush_buffer();
          }
        }
        open = true;
        first = Key{p, y, x, -1};
        length = n;
      }
      last = order_of(p, y, static_cast<std::int32_t>(std::int64_t{x} + n - 1));
      have_last = true;
      fragments += n;
    }
    if (out != stage) {
      buffer_.append(stage, static_cast<std::size_t>(out - stage));
      if (buffer_.size() >= kBufferBytes)
        flush_buffer();
    }
    run_open_ = open;
    run_first_ = first;
    if (fragments != count_) // the last fragment added, which closes the open run's row
      last_ = Key{first.prim, first.y,
                  static_cast<std::int32_t>(std::int64_t{first.x} + length - 1), first.seg};
    run_length_ = length;
    prim_ = prim;
    seg_ = seg;
    count_ = fragments;
    runs_ = written;
    return in_order ? Added::kOk : Added::kOutOfOrder;
  }
  // Writes the last run and the end record. Returns false when any write failed.
  bool finish();

  [[nodiscard]] std::uint64_t count() const { return count_; }
  [[nodiscard]] std::uint64_t runs() const { return runs_; }

private:
  // The buffer is written out when it holds this many bytes.
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
  // add_runs appends its staged bytes to the buffer when they reach this many.
  static constexpr std::size_t kStageBytes = 4096;
  // A fragment's place in the order the format holds: (prim, y, x, seg), seg -1 when there is
  // none (a Fragment record, 76 bytes with its optionals, built twice a run made the writer
  // cost three times the batch unit that found the runs).
  struct Key {
    std::uint32_t prim = 0;
    std::int32_t y = 0, x = 0;
    std::int64_t seg = -1;
  };
  // (prim, y, x) as an unsigned 128-bit integer in the same order.
  __extension__ typedef unsigned __int128 Order; // GCC and Clang
  static Order order_of(std::uint32_t prim, std::int32_t y, std::int32_t x) {
    const auto flip = [](std::int32_t v) {
      return std::uint64_t{static_cast<std::uint32_t>(v) ^ 0x80000000u};
    };
    return (Order{prim} << 64) | (flip(y) << 32) | flip(x);
  }
  // Version 1: the run (k, n)'s 20 bytes at out; returns their end.
  static char* put_fields(char* out, const Key& k, std::uint32_t n) {
    const std::uint32_t fields[5] = {
        k.prim, k.seg < 0 ? kFragmentBinaryNoSeg : static_cast<std::uint32_t>(k.seg),
        static_cast<std::uint32_t>(k.y), static_cast<std::uint32_t>(k.x), n};
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(out, fields, sizeof fields);
      return out + sizeof fields;
    }
    for (const std::uint32_t v : fields)
      for (int b = 0; b < 4; ++b)
        *out++ = static_cast<char>((v >> (8 * b)) & 0xFF);
    return out;
  }
  // A little-endian u64 at out; returns its end.
  static char* put_word(char* out, std::uint64_t w) {
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(out, &w, sizeof w);
      return out + sizeof w;
    }
    for (int b = 0; b < 8; ++b)
      *out++ = static_cast<char>((w >> (8 * b)) & 0xFF);
    return out;
  }
  // Version 2's word of the run (k, n) whose primitive is step after the previous run's.
  static std::uint64_t run_word(const Key& k, std::uint32_t n, std::uint64_t step) {
    return std::uint64_t{n} | (std::uint64_t{static_cast<std::uint32_t>(k.x)} << 15) |
           (std::uint64_t{static_cast<std::uint32_t>(k.y)} << 29) | (step << 43);
  }
  static char* put_control(char* out, std::uint32_t kind, std::uint32_t value) {
    return put_word(out, (std::uint64_t{value} << 32) | (std::uint64_t{kind} << 15));
  }
  // Version 2: the run (k, n)'s word at out, after the control words its primitive and segment
  // need (prim and seg: the previous run's, 0 and none before the first; updated). At most 24
  // bytes; returns their end.
  static char* put_run_word(char* out, const Key& k, std::uint32_t n, std::uint32_t& prim,
                            std::int64_t& seg) {
    std::uint64_t step = k.prim - prim; // k.prim >= prim: runs come in order
    // No segment before or now, and a step the word holds (every triangle's run): no control
    // word, and no branch on whether the primitive is new.
    if (step <= kFragmentBinaryMaxStep && k.seg == -1 && seg == -1) [[likely]] {
      prim = k.prim;
      return put_word(out, run_word(k, n, step));
    }
    if (step != 0) {
      if (step > kFragmentBinaryMaxStep || k.seg != -1) {
        out = put_control(out, kFragmentBinaryPrim, k.prim);
        step = 0;
      }
      prim = k.prim;
      seg = -1;
    }
    if (k.seg != seg) {
      out = put_control(out, kFragmentBinarySeg,
                        k.seg < 0 ? kFragmentBinaryNoSeg : static_cast<std::uint32_t>(k.seg));
      seg = k.seg;
    }
    return put_word(out, run_word(k, n, step));
  }
  void close_run();
  void flush_buffer();

  std::FILE* out_;
  FragmentBinaryHeader header_;
  std::string buffer_;
  // Whether the pixel at k continues the open run (its row's next pixel, the same primitive and
  // segment); k comes after last_ (checked first).
  [[nodiscard]] bool extends(const Key& k) const {
    return run_open_ && k.prim == run_first_.prim && k.seg == run_first_.seg &&
           k.y == run_first_.y && std::int64_t{k.x} == std::int64_t{run_first_.x} + run_length_;
  }
  // The open run: its first fragment and its masks.
  bool run_open_ = false;
  Key run_first_{};
  std::uint32_t run_length_ = 0;
  std::vector<std::uint16_t> run_masks_;
  Key last_{};
  std::uint32_t prim_ = 0; // version 2: the previous run's primitive and segment
  std::int64_t seg_ = -1;
  std::uint64_t count_ = 0;
  std::uint64_t runs_ = 0;
  bool failed_ = false;
};

// Returns the name of the first field f has that the binary format does not hold ("coverage",
// "sample", "helper", "centroid", "ddx", "area"), or nullopt when it holds f entirely; with
// header.mask_bytes 0, a mask other than 1 is "mask".
[[nodiscard]] std::optional<std::string> unsupported_field(const Fragment& f,
                                                           const FragmentBinaryHeader& header);

// A binary fragment list read back.
struct FragmentBinary {
  FragmentBinaryHeader header;
  std::uint64_t runs = 0;
  std::vector<Fragment> fragments; // prim, x, y, mask, and seg where the run has one
};

// Reads a binary fragment list, checking everything: the magic, the version, the header's
// fields, every run (inside the target, n >= 1, masks inside the sample count and not 0, the
// padding zero), the (prim, y, x, seg) order across runs, the end record's counts, and nothing
// after it. More than max_fragments fragments is an error (the memory of the result is bounded
// by it). Returns the list, or a one-line error naming the byte offset and the problem.
// rule: SCENE.OUTPUT.BINARY
[[nodiscard]] std::variant<FragmentBinary, std::string>
read_fragment_binary(std::span<const std::uint8_t> bytes,
                     std::uint64_t max_fragments = std::uint64_t{1} << 26);

} // namespace rastrules::io
