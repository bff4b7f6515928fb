// SPDX-License-Identifier: MIT
// Implements: SCENE.OUTPUT.BINARY

#include "rastrules/io/fragment_binary.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <tuple>

#include "rastrules/msaa.hpp"

namespace rastrules::io {
namespace {

// Little-endian, whatever the host's byte order.
void put_u32(std::string& out, std::uint32_t v) {
  const char b[4] = {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF),
                     static_cast<char>((v >> 16) & 0xFF), static_cast<char>((v >> 24) & 0xFF)};
  out.append(b, 4);
}

void put_u64(std::string& out, std::uint64_t v) {
  put_u32(out, static_cast<std::uint32_t>(v & 0xFFFFFFFFu));
  put_u32(out, static_cast<std::uint32_t>(v >> 32));
}

std::uint32_t get_u32(std::span<const std::uint8_t> b, std::size_t at) {
  return std::uint32_t{b[at]} | (std::uint32_t{b[at + 1]} << 8) | (std::uint32_t{b[at + 2]} << 16) |
         (std::uint32_t{b[at + 3]} << 24);
}

std::uint64_t get_u64(std::span<const std::uint8_t> b, std::size_t at) {
  return std::uint64_t{get_u32(b, at)} | (std::uint64_t{get_u32(b, at + 4)} << 32);
}

// The bytes of a run's masks with their padding to a multiple of 4 (version 1) or 8.
std::size_t mask_block_bytes(std::uint32_t mask_bytes, std::uint64_t n, std::uint32_t version) {
  if (mask_bytes == 0)
    return 0;
  const std::uint64_t unit = version == 1 ? 4 : 8;
  return static_cast<std::size_t>((n * mask_bytes + unit - 1) / unit * unit);
}

// The order of SCENE.OUTPUT.FRAGMENTS restricted to what the format holds: (prim, y, x, seg),
// a missing seg first.
std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::int64_t> order_key(const Fragment& f) {
  return {f.prim, f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1};
}
// The same of the writer's keys (seg -1: none).
template <class Key>
std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::int64_t> key_order(const Key& k) {
  return {k.prim, k.y, k.x, k.seg};
}

std::string at_offset(std::size_t offset, const std::string& problem) {
  return "byte " + std::to_string(offset) + ": " + problem;
}

} // namespace

FragmentBinaryHeader fragment_binary_header(const PreparedScene& scene) {
  FragmentBinaryHeader h;
  h.width = static_cast<std::uint32_t>(scene.width);
  h.height = static_cast<std::uint32_t>(scene.height);
  h.samples = scene.msaa.count();
  h.mask_bytes = is_single_sample(scene.msaa) ? 0 : 2;
  return h;
}

std::optional<std::string> unsupported_field(const Fragment& f,
                                             const FragmentBinaryHeader& header) {
  if (f.coverage_q16)
    return "coverage";
  if (f.sample)
    return "sample";
  if (f.helper)
    return "helper";
  if (f.centroid)
    return "centroid";
  if (f.derivatives)
    return "ddx";
  if (f.area)
    return "area";
  if (header.mask_bytes == 0 ? f.mask != 1 : (f.mask == 0 || f.mask > 0xFFFFu))
    return "mask";
  return std::nullopt;
}

// rule: SCENE.OUTPUT.BINARY
FragmentBinaryWriter::FragmentBinaryWriter(std::FILE* out, FragmentBinaryHeader header)
    : out_(out), header_(header) {
  buffer_.reserve(kBufferBytes + 64);
  if (header_.version != 1)
    header_.version = 2;
  buffer_.append(reinterpret_cast<const char*>(kFragmentBinaryMagic), 8);
  put_u32(buffer_, header_.version);
  put_u32(buffer_, header_.width);
  put_u32(buffer_, header_.height);
  put_u32(buffer_, header_.samples);
  put_u32(buffer_, header_.mask_bytes);
  put_u32(buffer_, 0); // reserved
}

FragmentBinaryWriter::Added FragmentBinaryWriter::add(const Fragment& f) {
  if (unsupported_field(f, header_))
    return Added::kUnsupported;
  const Key k{f.prim, f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1};
  if (count_ > 0 && !(key_order(last_) < key_order(k)))
    return Added::kOutOfOrder;
  if (!extends(k)) {
    close_run();
    run_open_ = true;
    run_first_ = k;
    run_length_ = 0;
  }
  if (header_.mask_bytes != 0)
    run_masks_.push_back(static_cast<std::uint16_t>(f.mask));
  ++run_length_;
  last_ = k;
  ++count_;
  return Added::kOk;
}

void FragmentBinaryWriter::close_run() {
  if (!run_open_)
    return;
  char fields[3 * kFragmentBinaryWordBytes];
  const char* end = header_.version == 1
                        ? put_fields(fields, run_first_, run_length_)
                        : put_run_word(fields, run_first_, run_length_, prim_, seg_);
  buffer_.append(fields, static_cast<std::size_t>(end - fields));
  if (header_.mask_bytes != 0) {
    for (const std::uint16_t m : run_masks_) {
      const char b[2] = {static_cast<char>(m & 0xFF), static_cast<char>(m >> 8)};
      buffer_.append(b, 2);
    }
    buffer_.append(mask_block_bytes(2, run_masks_.size(), header_.version) - run_masks_.size() * 2,
                   '\0');
    run_masks_.clear();
  }
  run_open_ = false;
  ++runs_;
  if (buffer_.size() >= kBufferBytes)
    flush_buffer();
}

void FragmentBinaryWriter::flush_buffer() {
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), out_) != buffer_.size())
    failed_ = true;
  buffer_.clear();
}

bool FragmentBinaryWriter::finish() {
  close_run();
  if (header_.version == 1) {
    put_u32(buffer_, kFragmentBinaryEnd);
    put_u32(buffer_, 0);
  } else {
    char word[kFragmentBinaryWordBytes];
    buffer_.append(word,
                   static_cast<std::size_t>(put_control(word, kFragmentBinaryStop, 0) - word));
  }
  put_u64(buffer_, count_);
  put_u64(buffer_, runs_);
  flush_buffer();
  if (std::fflush(out_) != 0)
    failed_ = true;
  return !failed_;
}

namespace {

// What a reader has read so far of the runs: the last fragment, for the order.
struct ReadState {
  FragmentBinary& r;
  std::uint64_t max_fragments;
  std::uint32_t max_mask;
  bool have_last = false;
  Fragment last{};
};

// Where a run lies, for the errors: the offsets of the run, of its row, its column and its n
// (a version 2 word's own offset for all four), and of its masks.
struct RunPlace {
  std::size_t start, row, column, n, masks;
};

// Checks one run and appends its fragments; returns the bytes its masks take with their
// padding, or an error.
std::variant<std::size_t, std::string> take_run(std::span<const std::uint8_t> bytes, ReadState& st,
                                                const RunPlace& at, std::uint32_t prim,
                                                std::int64_t seg, std::uint32_t x, std::uint32_t y,
                                                std::uint32_t n) {
  const FragmentBinaryHeader& h = st.r.header;
  if (y >= h.height)
    return at_offset(at.row, "row " + std::to_string(static_cast<std::int32_t>(y)) +
                                 " is outside the target's " + std::to_string(h.height));
  if (x >= h.width)
    return at_offset(at.column, "column " + std::to_string(static_cast<std::int32_t>(x)) +
                                    " is outside the target's " + std::to_string(h.width));
  if (n < 1 || std::uint64_t{x} + n > h.width)
    return at_offset(at.n, "a run of " + std::to_string(n) + " pixels from column " +
                               std::to_string(x) + " does not fit a row of " +
                               std::to_string(h.width));
  if (st.r.fragments.size() + n > st.max_fragments)
    return at_offset(at.n, "more than " + std::to_string(st.max_fragments) + " fragments");
  const std::size_t masks = mask_block_bytes(h.mask_bytes, n, h.version);
  if (bytes.size() - at.masks < masks)
    return at_offset(bytes.size(), "the file ends inside a run's masks");
  Fragment first(prim, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), 1,
                 seg < 0 ? std::nullopt
                         : std::optional<std::uint32_t>(static_cast<std::uint32_t>(seg)));
  if (st.have_last && !(order_key(st.last) < order_key(first)))
    return at_offset(at.start,
                     "a run that does not come after the previous one in (prim, y, x, seg) "
                     "order");
  for (std::uint32_t i = 0; i < n; ++i) {
    Fragment f = first;
    f.x = static_cast<std::int32_t>(x + i);
    if (h.mask_bytes != 0) {
      const std::size_t m_at = at.masks + std::size_t{i} * 2;
      f.mask = std::uint32_t{bytes[m_at]} | (std::uint32_t{bytes[m_at + 1]} << 8);
      if (f.mask == 0 || f.mask > st.max_mask)
        return at_offset(m_at, "mask " + std::to_string(f.mask) + " is not a nonzero mask of " +
                                   std::to_string(h.samples) + " samples");
    }
    st.r.fragments.push_back(f);
  }
  for (std::size_t p = at.masks + std::size_t{n} * h.mask_bytes; p < at.masks + masks; ++p) {
    if (bytes[p] != 0)
      return at_offset(p, "a run's padding is not 0");
  }
  st.last = st.r.fragments.back();
  st.have_last = true;
  ++st.r.runs;
  return masks;
}

// The end record at `at` (whole: its 24 bytes; its first 8 checked by the caller's version):
// the counts, and nothing after it.
std::optional<std::string> check_end(std::span<const std::uint8_t> bytes, std::size_t at,
                                     const FragmentBinary& r) {
  if (const std::uint64_t n = get_u64(bytes, at + 8); n != r.fragments.size())
    return at_offset(at + 8, "the end record counts " + std::to_string(n) +
                                 " fragments, the runs hold " + std::to_string(r.fragments.size()));
  if (const std::uint64_t n = get_u64(bytes, at + 16); n != r.runs)
    return at_offset(at + 16, "the end record counts " + std::to_string(n) +
                                  " runs, the file holds " + std::to_string(r.runs));
  if (at + kFragmentBinaryEndBytes != bytes.size())
    return at_offset(at + kFragmentBinaryEndBytes, "bytes after the end record");
  return std::nullopt;
}

// Version 1: 20-byte runs, each with its prim and seg.
std::optional<std::string> read_runs20(std::span<const std::uint8_t> bytes, ReadState& st) {
  std::size_t at = kFragmentBinaryHeaderBytes;
  while (true) {
    if (bytes.size() - at < 4)
      return at_offset(bytes.size(), "the file ends before the end record");
    const std::uint32_t prim = get_u32(bytes, at);
    if (prim == kFragmentBinaryEnd) {
      if (bytes.size() - at < kFragmentBinaryEndBytes)
        return at_offset(bytes.size(), "the file ends inside the end record");
      if (get_u32(bytes, at + 4) != 0)
        return at_offset(at + 4, "the end record's reserved field is not 0");
      return check_end(bytes, at, st.r);
    }
    if (bytes.size() - at < kFragmentBinaryRunBytes)
      return at_offset(bytes.size(), "the file ends inside a run");
    const std::uint32_t seg = get_u32(bytes, at + 4);
    const auto taken =
        take_run(bytes, st, RunPlace{at, at + 8, at + 12, at + 16, at + kFragmentBinaryRunBytes},
                 prim, seg == kFragmentBinaryNoSeg ? -1 : std::int64_t{seg},
                 get_u32(bytes, at + 12), get_u32(bytes, at + 8), get_u32(bytes, at + 16));
    if (const auto* err = std::get_if<std::string>(&taken))
      return *err;
    at += kFragmentBinaryRunBytes + std::get<std::size_t>(taken);
  }
}

// Version 2: 64-bit words, runs and control words.
std::optional<std::string> read_words(std::span<const std::uint8_t> bytes, ReadState& st) {
  std::size_t at = kFragmentBinaryHeaderBytes;
  std::uint32_t prim = 0;
  std::int64_t seg = -1;
  while (true) {
    if (bytes.size() - at < kFragmentBinaryWordBytes)
      return at_offset(bytes.size(), "the file ends before the end record");
    const std::uint64_t w = get_u64(bytes, at);
    const auto n = static_cast<std::uint32_t>(w & 0x7FFF);
    if (n == 0) {
      const auto kind = static_cast<std::uint32_t>((w >> 15) & 0x1FFFF);
      const auto value = static_cast<std::uint32_t>(w >> 32);
      if (kind == kFragmentBinaryStop) {
        if (bytes.size() - at < kFragmentBinaryEndBytes)
          return at_offset(bytes.size(), "the file ends inside the end record");
        if (value != 0)
          return at_offset(at + 4, "the end record's value is not 0");
        return check_end(bytes, at, st.r);
      }
      if (kind == kFragmentBinaryPrim) {
        prim = value;
        seg = -1;
      } else if (kind == kFragmentBinarySeg) {
        seg = value == kFragmentBinaryNoSeg ? -1 : std::int64_t{value};
      } else {
        return at_offset(at, "a control word of unknown kind " + std::to_string(kind));
      }
      at += kFragmentBinaryWordBytes;
      continue;
    }
    if (const auto step = static_cast<std::uint32_t>(w >> 43); step != 0) {
      if (prim > 0xFFFFFFFFu - step)
        return at_offset(at, "a run whose primitive passes 4294967295");
      prim += step;
      seg = -1;
    }
    const auto taken = take_run(bytes, st, RunPlace{at, at, at, at, at + kFragmentBinaryWordBytes},
                                prim, seg, static_cast<std::uint32_t>((w >> 15) & 0x3FFF),
                                static_cast<std::uint32_t>((w >> 29) & 0x3FFF), n);
    if (const auto* err = std::get_if<std::string>(&taken))
      return *err;
    at += kFragmentBinaryWordBytes + std::get<std::size_t>(taken);
  }
}

} // namespace

// rule: SCENE.OUTPUT.BINARY
std::variant<FragmentBinary, std::string> read_fragment_binary(std::span<const std::uint8_t> bytes,
                                                               std::uint64_t max_fragments) {
  FragmentBinary r;
  if (bytes.size() < kFragmentBinaryHeaderBytes)
    return at_offset(bytes.size(), "the file ends inside the 32-byte header");
  if (!std::equal(bytes.begin(), bytes.begin() + 8, std::begin(kFragmentBinaryMagic)))
    return at_offset(0, "not a rastrules binary fragment list (wrong magic bytes)");
  FragmentBinaryHeader& h = r.header;
  h.version = get_u32(bytes, 8);
  if (h.version != 1 && h.version != 2)
    return at_offset(8, "version " + std::to_string(h.version) + " is neither 1 nor 2");
  h.width = get_u32(bytes, 12);
  h.height = get_u32(bytes, 16);
  h.samples = get_u32(bytes, 20);
  h.mask_bytes = get_u32(bytes, 24);
  if (h.width < 1 || h.width > static_cast<std::uint32_t>(kMaxTargetSide))
    return at_offset(12, "width " + std::to_string(h.width) + " is outside [1, " +
                             std::to_string(kMaxTargetSide) + "]");
  if (h.height < 1 || h.height > static_cast<std::uint32_t>(kMaxTargetSide))
    return at_offset(16, "height " + std::to_string(h.height) + " is outside [1, " +
                             std::to_string(kMaxTargetSide) + "]");
  if (h.samples < 1 || h.samples > 16)
    return at_offset(20, "samples " + std::to_string(h.samples) + " is outside [1, 16]");
  if (h.mask_bytes != 0 && h.mask_bytes != 2)
    return at_offset(24, "mask bytes " + std::to_string(h.mask_bytes) + " is neither 0 nor 2");
  if (h.mask_bytes == 0 && h.samples != 1)
    return at_offset(24, "mask bytes 0 (no masks) with " + std::to_string(h.samples) + " samples");
  if (get_u32(bytes, 28) != 0)
    return at_offset(28, "the reserved field is not 0");
  ReadState st{r, max_fragments,
               h.samples >= 16 ? 0xFFFFu : static_cast<std::uint32_t>((1u << h.samples) - 1u)};
  if (auto err = h.version == 1 ? read_runs20(bytes, st) : read_words(bytes, st))
    return *err;
  return r;
}

} // namespace rastrules::io
