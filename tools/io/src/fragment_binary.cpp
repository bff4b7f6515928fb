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

// The bytes of a run's masks with their padding to a multiple of 4.
std::size_t mask_block_bytes(std::uint32_t mask_bytes, std::uint64_t n) {
  if (mask_bytes == 0)
    return 0;
  return static_cast<std::size_t>((n * mask_bytes + 3) / 4 * 4);
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
  buffer_.append(reinterpret_cast<const char*>(kFragmentBinaryMagic), 8);
  put_u32(buffer_, kFragmentBinaryVersion);
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

void FragmentBinaryWriter::append_little_endian(const std::uint32_t (&fields)[5]) {
  for (const std::uint32_t v : fields)
    put_u32(buffer_, v);
}

void FragmentBinaryWriter::close_run() {
  if (!run_open_)
    return;
  append_run_fields();
  if (header_.mask_bytes != 0) {
    for (const std::uint16_t m : run_masks_) {
      const char b[2] = {static_cast<char>(m & 0xFF), static_cast<char>(m >> 8)};
      buffer_.append(b, 2);
    }
    if (run_masks_.size() % 2 != 0)
      buffer_.append(2, '\0');
    run_masks_.clear();
  }
  end_run();
}

void FragmentBinaryWriter::flush_buffer() {
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), out_) != buffer_.size())
    failed_ = true;
  buffer_.clear();
}

bool FragmentBinaryWriter::finish() {
  close_run();
  put_u32(buffer_, kFragmentBinaryEnd);
  put_u32(buffer_, 0);
  put_u64(buffer_, count_);
  put_u64(buffer_, runs_);
  flush_buffer();
  if (std::fflush(out_) != 0)
    failed_ = true;
  return !failed_;
}

// rule: SCENE.OUTPUT.BINARY
std::variant<FragmentBinary, std::string> read_fragment_binary(std::span<const std::uint8_t> bytes,
                                                               std::uint64_t max_fragments) {
  FragmentBinary r;
  if (bytes.size() < kFragmentBinaryHeaderBytes)
    return at_offset(bytes.size(), "the file ends inside the 32-byte header");
  if (!std::equal(bytes.begin(), bytes.begin() + 8, std::begin(kFragmentBinaryMagic)))
    return at_offset(0, "not a rastrules binary fragment list (wrong magic bytes)");
  if (const std::uint32_t v = get_u32(bytes, 8); v != kFragmentBinaryVersion)
    return at_offset(8, "version " + std::to_string(v) + " is not 1");
  FragmentBinaryHeader& h = r.header;
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
  const std::uint32_t max_mask =
      h.samples >= 16 ? 0xFFFFu : static_cast<std::uint32_t>((1u << h.samples) - 1u);
  std::size_t at = kFragmentBinaryHeaderBytes;
  bool have_last = false;
  Fragment last{};
  while (true) {
    if (bytes.size() - at < 4)
      return at_offset(bytes.size(), "the file ends before the end record");
    const std::uint32_t prim = get_u32(bytes, at);
    if (prim == kFragmentBinaryEnd) {
      if (bytes.size() - at < kFragmentBinaryEndBytes)
        return at_offset(bytes.size(), "the file ends inside the end record");
      if (get_u32(bytes, at + 4) != 0)
        return at_offset(at + 4, "the end record's reserved field is not 0");
      if (const std::uint64_t n = get_u64(bytes, at + 8); n != r.fragments.size())
        return at_offset(at + 8, "the end record counts " + std::to_string(n) +
                                     " fragments, the runs hold " +
                                     std::to_string(r.fragments.size()));
      if (const std::uint64_t n = get_u64(bytes, at + 16); n != r.runs)
        return at_offset(at + 16, "the end record counts " + std::to_string(n) +
                                      " runs, the file holds " + std::to_string(r.runs));
      if (at + kFragmentBinaryEndBytes != bytes.size())
        return at_offset(at + kFragmentBinaryEndBytes, "bytes after the end record");
      return r;
    }
    if (bytes.size() - at < kFragmentBinaryRunBytes)
      return at_offset(bytes.size(), "the file ends inside a run");
    const std::uint32_t seg = get_u32(bytes, at + 4);
    const std::uint32_t y = get_u32(bytes, at + 8);
    const std::uint32_t x = get_u32(bytes, at + 12);
    const std::uint32_t n = get_u32(bytes, at + 16);
    if (y >= h.height)
      return at_offset(at + 8, "row " + std::to_string(static_cast<std::int32_t>(y)) +
                                   " is outside the target's " + std::to_string(h.height));
    if (x >= h.width)
      return at_offset(at + 12, "column " + std::to_string(static_cast<std::int32_t>(x)) +
                                    " is outside the target's " + std::to_string(h.width));
    if (n < 1 || std::uint64_t{x} + n > h.width)
      return at_offset(at + 16, "a run of " + std::to_string(n) + " pixels from column " +
                                    std::to_string(x) + " does not fit a row of " +
                                    std::to_string(h.width));
    if (r.fragments.size() + n > max_fragments)
      return at_offset(at + 16, "more than " + std::to_string(max_fragments) + " fragments");
    const std::size_t masks = mask_block_bytes(h.mask_bytes, n);
    if (bytes.size() - at - kFragmentBinaryRunBytes < masks)
      return at_offset(bytes.size(), "the file ends inside a run's masks");
    Fragment first(prim, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y), 1,
                   seg == kFragmentBinaryNoSeg ? std::nullopt : std::optional<std::uint32_t>(seg));
    if (have_last && !(order_key(last) < order_key(first)))
      return at_offset(at, "a run that does not come after the previous one in (prim, y, x, seg) "
                           "order");
    const std::size_t mask_at = at + kFragmentBinaryRunBytes;
    for (std::uint32_t i = 0; i < n; ++i) {
      Fragment f = first;
      f.x = static_cast<std::int32_t>(x + i);
      if (h.mask_bytes != 0) {
        const std::size_t m_at = mask_at + std::size_t{i} * 2;
        f.mask = std::uint32_t{bytes[m_at]} | (std::uint32_t{bytes[m_at + 1]} << 8);
        if (f.mask == 0 || f.mask > max_mask)
          return at_offset(m_at, "mask " + std::to_string(f.mask) + " is not a nonzero mask of " +
                                     std::to_string(h.samples) + " samples");
      }
      r.fragments.push_back(f);
    }
    for (std::size_t p = mask_at + std::size_t{n} * h.mask_bytes; p < mask_at + masks; ++p) {
      if (bytes[p] != 0)
        return at_offset(p, "a run's padding is not 0");
    }
    last = r.fragments.back();
    have_last = true;
    ++r.runs;
    at = mask_at + masks;
  }
}

} // namespace rastrules::io
