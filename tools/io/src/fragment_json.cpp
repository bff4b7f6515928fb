// SPDX-License-Identifier: MIT
// The fragment list output.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP,
//             SCENE.OUTPUT.MSAA

#include "rastrules/io/fragment_json.hpp"

#include <array>
#include <charconv>
#include <string>

namespace rastrules::io {
namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 16;

template <class Int>
void append_int(std::string& out, Int v) {
  std::array<char, 24> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), r.ptr);
}

// Appends one fragment object on its own line.
void append_fragment(std::string& out, const Fragment& f, bool first) {
  out += first ? "\n  {\"prim\": " : ",\n  {\"prim\": ";
  append_int(out, f.prim);
  out += ", \"x\": ";
  append_int(out, f.x);
  out += ", \"y\": ";
  append_int(out, f.y);
  out += ", \"mask\": ";
  append_int(out, f.mask);
  // rule: SCENE.PRIM.LINE_STRIP
  if (f.seg) {
    out += ", \"seg\": ";
    append_int(out, *f.seg);
  }
  // rule: SCENE.OUTPUT.MSAA
  if (f.sample) {
    out += ", \"sample\": ";
    append_int(out, *f.sample);
  }
  if (f.helper) out += ", \"helper\": true";
  // rule: SCENE.OUTPUT.COVERAGE
  if (f.coverage_q16) {
    out += ", \"coverage\": ";
    out += format_coverage(*f.coverage_q16);
  }
  // rule: SCENE.OUTPUT.MSAA
  if (f.centroid) {
    const auto c = centroid_sixteenths(f.x, f.y, f.centroid->offset);
    out += ", \"centroid\": [" + format_sixteenths(c[0]) + ", " + format_sixteenths(c[1]) + "]";
  }
  if (f.derivatives) {
    const EvalDerivatives& d = *f.derivatives;
    out += ", \"ddx\": [" + format_sixteenths(d.ddx_x) + ", " + format_sixteenths(d.ddx_y) + "]";
    out += ", \"ddy\": [" + format_sixteenths(d.ddy_x) + ", " + format_sixteenths(d.ddy_y) + "]";
  }
  out += "}";
}

}  // namespace

// rule: SCENE.OUTPUT.COVERAGE
std::string format_coverage(std::uint32_t coverage_q16) {
  // q / 2^16 = q * 5^16 / 10^16: the digits of q * 5^16 with the point 16 places from the
  // right, trailing zeros dropped. Exact for every q (at most 16 fraction digits).
  constexpr std::uint64_t kFive16 = 152587890625u; // 5^16
  const std::uint64_t whole = coverage_q16 >> 16;
  const std::uint64_t frac = (coverage_q16 & 0xffffu) * kFive16; // < 10^16
  std::string out = std::to_string(whole);
  out += '.';
  if (frac == 0)
    return out + "0";
  std::string digits = std::to_string(frac);
  digits.insert(0, 16 - digits.size(), '0');
  while (digits.back() == '0')
    digits.pop_back();
  return out + digits;
}

// rule: SCENE.OUTPUT.MSAA
std::string format_sixteenths(std::int64_t sixteenths) {
  // v / 16 = v * 625 / 10^4: at most 4 fraction digits, exact.
  const bool negative = sixteenths < 0;
  const std::uint64_t mag = negative ? 0 - static_cast<std::uint64_t>(sixteenths)
                                     : static_cast<std::uint64_t>(sixteenths);
  std::string out = (negative ? "-" : "") + std::to_string(mag >> 4) + ".";
  const std::uint64_t frac = (mag & 15u) * 625u;
  if (frac == 0) return out + "0";
  std::string digits = std::to_string(frac);
  digits.insert(0, 4 - digits.size(), '0');
  while (digits.back() == '0') digits.pop_back();
  return out + digits;
}

std::array<std::int64_t, 2> centroid_sixteenths(std::int32_t x, std::int32_t y, SampleOffset o) {
  return {std::int64_t{x} * 16 + 8 + o.x, std::int64_t{y} * 16 + 8 + o.y};
}

FragmentWriter::FragmentWriter(std::FILE* out) : out_(out) {
  buffer_.reserve(kFlushBytes + 128);
  buffer_ += "{\"fragments\": [";
}

// rule: SCENE.OUTPUT.FRAGMENTS
bool FragmentWriter::add(const Fragment& f) {
  if (count_ != 0 && !fragment_before(last_, f))
    return false;
  append_fragment(buffer_, f, count_ == 0);
  last_ = f;
  ++count_;
  if (buffer_.size() >= kFlushBytes) flush_buffer();
  return true;
}

bool FragmentWriter::finish() {
  buffer_ += count_ == 0 ? "]}\n" : "\n]}\n";
  flush_buffer();
  if (std::fflush(out_) != 0) failed_ = true;
  return !failed_;
}

void FragmentWriter::flush_buffer() {
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), out_) != buffer_.size()) {
    failed_ = true;
  }
  buffer_.clear();
}

std::string fragments_to_json(const std::vector<Fragment>& fragments) {
  std::string out = "{\"fragments\": [";
  for (std::size_t n = 0; n < fragments.size(); ++n) {
    append_fragment(out, fragments[n], n == 0);
  }
  out += fragments.empty() ? "]}\n" : "\n]}\n";
  return out;
}

}  // namespace rastrules::io
