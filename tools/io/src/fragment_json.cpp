// SPDX-License-Identifier: MIT
// The fragment list output.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP,
//             SCENE.OUTPUT.MSAA, SCENE.OUTPUT.PIPELINE, SCENE.OUTPUT.AREA

#include "rastrules/io/fragment_json.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "rastrules/io/scene_json.hpp"

namespace rastrules::io {
namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 16;

// The digits of the fraction frac / 10^places (frac < 10^places) after the decimal point,
// trailing zeros dropped; "0" for zero.
std::string fraction_digits(std::uint64_t frac, std::size_t places) {
  if (frac == 0)
    return "0";
  std::string digits = std::to_string(frac);
  digits.insert(0, places - digits.size(), '0');
  while (digits.back() == '0')
    digits.pop_back();
  return digits;
}

template <class Int> void append_int(std::string& out, Int v) {
  std::array<char, 24> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), r.ptr);
}

// The fixed fields of a fragment's line, formatted into a buffer on the stack and appended to
// the output once (a string append per field was most of a render's time).
class LineBuffer {
public:
  template <std::size_t N> void text(const char (&s)[N]) {
    std::memcpy(buf_.data() + n_, s, N - 1);
    n_ += N - 1;
  }
  template <class Int> void number(Int v) {
    n_ = static_cast<std::size_t>(
        std::to_chars(buf_.data() + n_, buf_.data() + buf_.size(), v).ptr - buf_.data());
  }
  void append_to(std::string& out) const { out.append(buf_.data(), n_); }
  [[nodiscard]] std::size_t size() const { return n_; }
  // Copies the text but its first `skip` characters to p; returns the end of the copy.
  char* copy_to(char* p, std::size_t skip) const {
    std::memcpy(p, buf_.data() + skip, n_ - skip);
    return p + (n_ - skip);
  }

private:
  // The longest line: the texts below (93 bytes) and six numbers of at most 11 characters.
  std::array<char, 192> buf_; // only the first n_ are written and read
  std::size_t n_ = 0;
};

// Appends one fragment object on its own line, without its closing brace; part: the pipeline
// fragment's part (SCENE.OUTPUT.PIPELINE), written after prim.
void append_fragment_fields(std::string& out, const Fragment& f, bool first,
                            std::optional<std::uint32_t> part = std::nullopt) {
  LineBuffer line;
  if (first)
    line.text("\n  {\"prim\": ");
  else
    line.text(",\n  {\"prim\": ");
  line.number(f.prim);
  // rule: SCENE.OUTPUT.PIPELINE
  if (part) {
    line.text(", \"part\": ");
    line.number(*part);
  }
  line.text(", \"x\": ");
  line.number(f.x);
  line.text(", \"y\": ");
  line.number(f.y);
  line.text(", \"mask\": ");
  line.number(f.mask);
  // rule: SCENE.PRIM.LINE_STRIP
  if (f.seg) {
    line.text(", \"seg\": ");
    line.number(*f.seg);
  }
  // rule: SCENE.OUTPUT.MSAA
  if (f.sample) {
    line.text(", \"sample\": ");
    line.number(*f.sample);
  }
  if (f.helper)
    line.text(", \"helper\": true");
  line.append_to(out);
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
  // rule: SCENE.OUTPUT.AREA
  if (f.area) {
    out += ", \"area\": \"" + f.area.text() + "\"";
    if (const std::string bound = f.area.bound_text(); !bound.empty())
      out += ", \"area_bound\": \"" + bound + "\""; // rule: PATH.AREA.CURVE
    out += ", \"alpha\": " + std::to_string(f.area.alpha());
  }
}

// Appends one fragment object on its own line.
void append_fragment(std::string& out, const Fragment& f, bool first) {
  append_fragment_fields(out, f, first);
  out += "}";
}

} // namespace

// rule: SCENE.OUTPUT.FRAGMENTS
void RunText::append(std::string& out, std::uint32_t prim, std::int32_t y, std::int32_t x,
                     std::uint32_t n, bool first) {
  if (x < 0) { // never from a target's pixels; the plain way
    for (std::uint32_t k = 0; k < n; ++k) {
      append_fragment(out, Fragment(prim, static_cast<std::int32_t>(std::int64_t{x} + k), y, 1),
                      first && k == 0);
    }
    return;
  }
  if (!has_prim_ || prim != prim_) {
    constexpr std::string_view kOpen = ",\n  {\"prim\": ";
    constexpr std::string_view kX = ", \"x\": ";
    char* p = std::copy(kOpen.begin(), kOpen.end(), head_.data());
    p = std::to_chars(p, head_.data() + head_.size(), prim).ptr;
    head_n_ = static_cast<std::size_t>(std::copy(kX.begin(), kX.end(), p) - head_.data());
    prim_ = prim;
    has_prim_ = true;
  }
  // The row's tail, padded so that it is copied in one fixed-size move (as are the head and the
  // digits: a variable-length memcpy a piece was half of a thread's time).
  constexpr std::size_t kPiece = 32; // every piece is at most 30 bytes
  std::array<char, kPiece> tail{};
  std::size_t tail_n = 0;
  {
    constexpr std::string_view kY = ", \"y\": ";
    constexpr std::string_view kMask = ", \"mask\": 1}";
    char* t = std::copy(kY.begin(), kY.end(), tail.data());
    t = std::to_chars(t, tail.data() + tail.size(), y).ptr;
    tail_n = static_cast<std::size_t>(std::copy(kMask.begin(), kMask.end(), t) - tail.data());
  }
  // The digits of x + k, right-aligned in digits[16 - len, 16), followed by 16 bytes of
  // padding.
  std::array<char, 2 * 16> digits{};
  const auto r = std::to_chars(digits.data(), digits.data() + 16, x);
  std::size_t len = static_cast<std::size_t>(r.ptr - digits.data());
  std::memmove(digits.data() + 16 - len, digits.data(), len);
  // Lines are made in a buffer on the stack (with room for three whole pieces past its end)
  // and appended to out when it is nearly full.
  std::array<char, 8192 + 3 * kPiece> buf;
  char* const full = buf.data() + 8192;
  char* p = buf.data();
  for (std::uint32_t k = 0; k < n; ++k) {
    if (p >= full) {
      out.append(buf.data(), p);
      p = buf.data();
    }
    const std::size_t skip = k == 0 && first ? 1 : 0; // the first line without its comma
    std::memcpy(p, head_.data() + skip, kPiece);
    p += head_n_ - skip;
    std::memcpy(p, digits.data() + 16 - len, 16);
    p += len;
    std::memcpy(p, tail.data(), kPiece);
    p += tail_n;
    // x + k + 1
    std::size_t i = 16;
    while (i > 16 - len && digits[i - 1] == '9')
      digits[--i] = '0';
    if (i > 16 - len) {
      ++digits[i - 1];
    } else {
      ++len;
      digits[16 - len] = '1';
    }
  }
  out.append(buf.data(), p);
}

namespace {

// A float that reads back as itself: the shortest round-trip decimal (SCENE.NUMBER.FLOAT32);
// NaN and infinities, which the kernel never produces, as strings so that the JSON stays valid.
std::string value_text(float v) {
  const std::string s = format_float(v);
  return std::isfinite(v) ? s : "\"" + s + "\"";
}

// Whether a pipeline fragment (with data d, or none) matches the fields: one value per
// attribute and one depth per sample of its mask, none of either for a fragment the depth test
// killed (PIPE.DEPTH.KILL: passed 0 on a covered fragment); without data, no field asked for.
bool matches(const Fragment& f, const pipe::FragmentData* d, const PipeOutputFields& fields) {
  if (d == nullptr)
    return fields.attributes.empty() && !fields.depth;
  if (fields.depth && !f.helper && d->passed == 0)
    return d->attr.empty() && d->depth.empty();
  if (d->attr.size() != fields.attributes.size())
    return false;
  if (fields.depth)
    return d->depth.size() == static_cast<std::size_t>(std::popcount(f.mask));
  return d->depth.empty();
}

// Whether pipeline fragment a (of part part_a) comes strictly before b: (prim, part, y, x, seg,
// sample), a missing part first.
bool pipe_before(const Fragment& a, std::optional<std::uint32_t> part_a, const Fragment& b,
                 std::optional<std::uint32_t> part_b) {
  if (a.prim != b.prim)
    return a.prim < b.prim;
  if (part_a != part_b)
    return part_a < part_b;
  return fragment_before(a, b);
}

// rule: SCENE.OUTPUT.PIPELINE
void append_pipe_fragment(std::string& out, const Fragment& f, const pipe::FragmentData* d,
                          bool first, const PipeOutputFields& fields) {
  append_fragment_fields(out, f, first, d != nullptr ? d->part : std::nullopt);
  if (d != nullptr && d->bary) {
    out += ", \"bary\": [";
    for (const std::int64_t e : d->bary->e) {
      append_int(out, e);
      out += ", ";
    }
    append_int(out, d->bary->area);
    out += "]";
  }
  if (d == nullptr) {
    out += "}";
    return;
  }
  const bool killed = fields.depth && !f.helper && d->passed == 0;
  if (!fields.attributes.empty() && !killed) {
    out += ", \"attr\": {";
    for (std::size_t k = 0; k < fields.attributes.size(); ++k) {
      out +=
          (k == 0 ? "" : ", ") + json_string(fields.attributes[k]) + ": " + value_text(d->attr[k]);
    }
    out += "}";
  }
  if (fields.depth) {
    if (!killed) {
      out += ", \"depth\": [";
      for (std::size_t k = 0; k < d->depth.size(); ++k) {
        out += (k == 0 ? "" : ", ") + depth_text(d->depth[k], *fields.depth);
      }
      out += "]";
    }
    out += ", \"passed\": ";
    append_int(out, d->passed);
  }
  out += "}";
}

} // namespace

// rule: SCENE.OUTPUT.COVERAGE
std::string format_coverage(std::uint32_t coverage_q16) {
  // q / 2^16 = q * 5^16 / 10^16: the digits of q * 5^16 with the point 16 places from the
  // right, trailing zeros dropped. Exact for every q (at most 16 fraction digits).
  constexpr std::uint64_t kFive16 = 152587890625u; // 5^16
  const std::uint64_t whole = coverage_q16 >> 16;
  const std::uint64_t frac = (coverage_q16 & 0xffffu) * kFive16; // < 10^16
  return std::to_string(whole) + "." + fraction_digits(frac, 16);
}

// rule: SCENE.OUTPUT.MSAA
std::string format_sixteenths(std::int64_t sixteenths) {
  // v / 16 = v * 625 / 10^4: at most 4 fraction digits, exact.
  const bool negative = sixteenths < 0;
  const std::uint64_t mag = negative ? 0 - static_cast<std::uint64_t>(sixteenths)
                                     : static_cast<std::uint64_t>(sixteenths);
  const std::uint64_t frac = (mag & 15u) * 625u;
  return (negative ? "-" : "") + std::to_string(mag >> 4) + "." + fraction_digits(frac, 4);
}

std::array<std::int64_t, 2> centroid_sixteenths(std::int32_t x, std::int32_t y, SampleOffset o) {
  return {std::int64_t{x} * 16 + 8 + o.x, std::int64_t{y} * 16 + 8 + o.y};
}

FragmentWriter::FragmentWriter(std::FILE* out) : out_(out) {
  buffer_.reserve(kFlushBytes + 128);
  buffer_ += "{\"fragments\": [";
}

FragmentWriter::FragmentWriter(std::FILE* out, PipeOutputFields fields) : FragmentWriter(out) {
  fields_ = std::move(fields);
}

// rule: SCENE.OUTPUT.PIPELINE
bool FragmentWriter::add(const Fragment& f, const pipe::FragmentData* data) {
  const std::optional<std::uint32_t> part = data != nullptr ? data->part : std::nullopt;
  if (count_ != 0 && !pipe_before(last_, last_part_, f, part))
    return false;
  if (!matches(f, data, fields_))
    return false;
  append_pipe_fragment(buffer_, f, data, count_ == 0, fields_);
  last_ = f;
  last_part_ = part;
  ++count_;
  if (buffer_.size() >= kFlushBytes)
    flush_buffer();
  return true;
}

// rule: SCENE.OUTPUT.FRAGMENTS
bool FragmentWriter::add(const Fragment& f) {
  if (count_ != 0 && !fragment_before(last_, f))
    return false;
  append_fragment(buffer_, f, count_ == 0);
  last_ = f;
  ++count_;
  if (buffer_.size() >= kFlushBytes)
    flush_buffer();
  return true;
}

bool FragmentWriter::add_run(std::uint32_t prim, std::int32_t y, std::int32_t x, std::uint32_t n) {
  if (count_ != 0 && !fragment_before(last_, Fragment(prim, x, y, 1)))
    return false;
  run_text_.append(buffer_, prim, y, x, n, count_ == 0);
  count_ += n;
  last_ = Fragment(prim, static_cast<std::int32_t>(std::int64_t{x} + n - 1), y, 1);
  if (buffer_.size() >= kFlushBytes)
    flush_buffer();
  return true;
}

void FragmentWriter::encode(const Fragment& f, std::string& out) {
  append_fragment(out, f, false);
}

bool FragmentWriter::add_without_text(const Fragment& f) {
  if (count_ != 0 && !fragment_before(last_, f))
    return false;
  last_ = f;
  ++count_;
  return true;
}

bool FragmentWriter::add_without_text(const BatchSummary& batch) {
  if (batch.count == 0)
    return true;
  if (!batch.in_order || (count_ != 0 && !fragment_before(last_, batch.first)))
    return false;
  last_ = batch.last;
  count_ += batch.count;
  return true;
}

void FragmentWriter::add_encoded_text(std::string_view text) {
  if (text.empty())
    return;
  if (!text_started_) {
    text_started_ = true;
    text.remove_prefix(1); // encode's ',' before the first fragment
  }
  // Short texts gather in the buffer; a long one (a threaded render's unit) goes out without a
  // copy.
  if (text.size() < kFlushBytes / 4 && buffer_.size() + text.size() < kFlushBytes) {
    buffer_ += text;
    return;
  }
  flush_buffer();
  if (std::fwrite(text.data(), 1, text.size(), out_) != text.size())
    failed_ = true;
}

bool FragmentWriter::finish() {
  buffer_ += count_ == 0 ? "]}\n" : "\n]}\n";
  flush_buffer();
  if (std::fflush(out_) != 0)
    failed_ = true;
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

PipeOutputFields pipe_output_fields(const Scene& s) {
  PipeOutputFields fields;
  for (const pipe::AttributeDecl& a : s.attributes)
    fields.attributes.push_back(a.name);
  if (s.depth)
    fields.depth = s.conventions.depth;
  return fields;
}

std::optional<std::string> pipe_fragments_to_json(const std::vector<Fragment>& fragments,
                                                  const std::vector<pipe::FragmentData>& data,
                                                  const PipeOutputFields& fields) {
  if (!data.empty() && data.size() != fragments.size())
    return std::nullopt;
  const auto data_of = [&](std::size_t n) { return data.empty() ? nullptr : &data[n]; };
  const auto part_of = [&](std::size_t n) {
    return data.empty() ? std::optional<std::uint32_t>() : data[n].part;
  };
  std::string out = "{\"fragments\": [";
  for (std::size_t n = 0; n < fragments.size(); ++n) {
    if (n != 0 && !pipe_before(fragments[n - 1], part_of(n - 1), fragments[n], part_of(n))) {
      return std::nullopt;
    }
    if (!matches(fragments[n], data_of(n), fields))
      return std::nullopt;
    append_pipe_fragment(out, fragments[n], data_of(n), n == 0, fields);
  }
  out += fragments.empty() ? "]}\n" : "\n]}\n";
  return out;
}

// rule: SCENE.OUTPUT.PIPELINE
std::string depth_text(const pipe::DepthValue& d, pipe::DepthFormat format) {
  if (format == pipe::DepthFormat::kD32F)
    return value_text(d.f);
  std::string out;
  append_int(out, d.unorm);
  return out;
}

// rule: SCENE.OUTPUT.PIPELINE
bool write_depth_buffer(std::FILE* out, std::int32_t width, std::int32_t height,
                        std::uint32_t samples, pipe::DepthFormat format,
                        const std::vector<pipe::DepthValue>& buffer) {
  const std::size_t row = static_cast<std::size_t>(width < 0 ? 0 : width) * samples;
  if (height < 0 || buffer.size() != row * static_cast<std::size_t>(height))
    return false;
  std::string text = "{\"format\": \"" + std::string(depth_format_name(format)) +
                     "\", \"width\": " + std::to_string(width) +
                     ", \"height\": " + std::to_string(height) +
                     ", \"samples\": " + std::to_string(samples) + ", \"depth\": [";
  bool ok = true;
  for (std::size_t i = 0; i < buffer.size(); ++i) {
    text += i == 0 ? "\n  " : (i % row == 0 ? ",\n  " : ", ");
    text += depth_text(buffer[i], format);
    if (text.size() >= kFlushBytes) {
      ok = std::fwrite(text.data(), 1, text.size(), out) == text.size() && ok;
      text.clear();
    }
  }
  text += buffer.empty() ? "]}\n" : "\n]}\n";
  ok = std::fwrite(text.data(), 1, text.size(), out) == text.size() && ok;
  return std::fflush(out) == 0 && ok;
}

} // namespace rastrules::io
