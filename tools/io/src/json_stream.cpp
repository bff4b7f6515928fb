// SPDX-License-Identifier: MIT
// Strict streaming JSON reading over the JSON library's SAX parser (json_stream.hpp).
// Implements: SCENE.INPUT.ERRORS (the parser's part: JSON syntax, a raw NUL byte)

#include "rastrules/io/json_stream.hpp"
#include "rastrules/io/scene_json.hpp"

#include <algorithm>
#include <cstddef>
#include <istream>
#include <limits>
#include <streambuf>
#include <utility>

#include <nlohmann/json.hpp>

namespace rastrules::io {
namespace {

std::string nul_message(std::size_t line, std::size_t column) {
  return "parse error at line " + std::to_string(line) + ", column " + std::to_string(column) +
         ": a raw NUL byte, which JSON text cannot hold";
}

// The JSON library's SAX interface, each event passed on to a JsonHandler. `end` is the number
// of bytes before the NUL byte that ends the text early, when it has one: the parser's error
// for reaching that end is the NUL's, which the caller reports.
class SaxAdapter {
public:
  using json = nlohmann::json;

  SaxAdapter(JsonHandler& h, const std::optional<std::size_t>& nul_at) : h_(h), nul_at_(nul_at) {}

  bool null() { return h_.value(JsonValue{JsonKind::kNull, false, 0, 0, {}}); }
  bool boolean(bool b) { return h_.value(JsonValue{JsonKind::kBool, b, 0, 0, {}}); }
  bool number_integer(json::number_integer_t i) {
    return h_.value(JsonValue{JsonKind::kInt, false, i, 0, {}});
  }
  // The library reports every non-negative integer here; those an int64_t holds go on as kInt.
  bool number_unsigned(json::number_unsigned_t u) {
    if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      return h_.value(JsonValue{JsonKind::kInt, false, static_cast<std::int64_t>(u), 0, {}});
    return h_.value(JsonValue{JsonKind::kUint, false, 0, u, {}});
  }
  bool number_float(json::number_float_t, const json::string_t& s) {
    return h_.value(JsonValue{JsonKind::kFloat, false, 0, 0, s});
  }
  bool string(json::string_t& s) { return h_.value(JsonValue{JsonKind::kString, false, 0, 0, s}); }
  bool binary(json::binary_t&) { return false; } // JSON text has no binary values
  bool start_object(std::size_t) { return h_.value(JsonValue{JsonKind::kObject, false, 0, 0, {}}); }
  bool start_array(std::size_t) { return h_.value(JsonValue{JsonKind::kArray, false, 0, 0, {}}); }
  bool key(json::string_t& k) { return h_.key(k); }
  bool end_object() { return h_.end_object(); }
  bool end_array() { return h_.end_array(); }

  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& ex) {
    // The parser counts the end of the input as one more character read: an error there was
    // caused by the NUL byte, which is the error to report.
    if (nul_at_ && position > *nul_at_)
      return false;
    return h_.syntax_error(JsonSyntaxError{ex.id, ex.what(), last_token});
  }

private:
  JsonHandler& h_;
  const std::optional<std::size_t>& nul_at_;
};

// The stream the parser reads: the pieces of a JsonChunks, up to the first NUL byte, whose line
// and column it keeps.
class ChunkBuffer : public std::streambuf {
public:
  explicit ChunkBuffer(const JsonChunks& next) : next_(next) {}

  std::optional<std::size_t> nul_at; // bytes before the first NUL byte, once it is read
  std::string nul;                   // its message

protected:
  int_type underflow() override {
    if (gptr() < egptr())
      return traits_type::to_int_type(*gptr());
    if (nul_at || ended_)
      return traits_type::eof();
    const std::string_view piece = next_();
    if (piece.empty()) {
      ended_ = true;
      return traits_type::eof();
    }
    const std::size_t stop = piece.find('\0');
    const std::string_view before = piece.substr(0, stop); // the whole piece when it has no NUL
    for (std::size_t at = before.find('\n'); at != std::string_view::npos;
         at = before.find('\n', at + 1)) {
      ++lines_;
      line_start_ = read_ + at + 1;
    }
    read_ += before.size();
    if (stop != std::string_view::npos) {
      nul_at = read_;
      nul = nul_message(lines_ + 1, read_ - line_start_ + 1);
    }
    if (before.empty())
      return traits_type::eof();
    // The parser only reads (no putback into the buffer), so the piece is never written.
    char* begin = const_cast<char*>(before.data());
    setg(begin, begin, begin + before.size());
    return traits_type::to_int_type(*gptr());
  }

private:
  const JsonChunks& next_;
  bool ended_ = false;
  std::size_t read_ = 0;       // bytes given to the parser so far
  std::size_t lines_ = 0;      // newlines among them
  std::size_t line_start_ = 0; // offset of the first byte of the current line
};

} // namespace

// rule: SCENE.INPUT.ERRORS
std::optional<std::string> nul_byte_problem(std::string_view text) {
  const std::size_t at = text.find('\0');
  if (at == std::string_view::npos)
    return std::nullopt;
  const std::string_view before = text.substr(0, at);
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  const std::size_t last_newline = before.rfind('\n');
  const std::size_t column =
      at - (last_newline == std::string_view::npos ? 0 : last_newline + 1) + 1;
  return nul_message(line, column);
}

// rule: SCENE.INPUT.ERRORS
JsonParseEnd parse_json(std::string_view text, JsonHandler& handler) {
  JsonParseEnd end;
  std::optional<std::size_t> nul_at;
  if (const std::size_t at = text.find('\0'); at != std::string_view::npos) {
    nul_at = at;
    end.nul = nul_byte_problem(text);
    text = text.substr(0, at);
  }
  SaxAdapter sax(handler, nul_at);
  end.ok = nlohmann::json::sax_parse(text.begin(), text.end(), &sax,
                                     nlohmann::json::input_format_t::json,
                                     /*strict=*/true, /*ignore_comments=*/false);
  return end;
}

// rule: SCENE.INPUT.ERRORS
JsonParseEnd parse_json(const JsonChunks& next, JsonHandler& handler) {
  ChunkBuffer buffer(next);
  std::istream in(&buffer);
  SaxAdapter sax(handler, buffer.nul_at);
  JsonParseEnd end;
  end.ok = nlohmann::json::sax_parse(in, &sax, nlohmann::json::input_format_t::json,
                                     /*strict=*/true, /*ignore_comments=*/false);
  if (buffer.nul_at)
    end.nul = std::move(buffer.nul);
  return end;
}

// rule: SCENE.NUMBER.FLOAT32
std::optional<float> json_float32(const JsonValue& v) {
  switch (v.kind) {
  case JsonKind::kInt:
    return static_cast<float>(v.i); // one correct rounding
  case JsonKind::kUint:
    return static_cast<float>(v.u); // one correct rounding
  case JsonKind::kFloat:
    return decimal_to_float32(v.text);
  case JsonKind::kString:
    if (v.text == "NaN")
      return std::numeric_limits<float>::quiet_NaN();
    if (v.text == "Infinity")
      return std::numeric_limits<float>::infinity();
    if (v.text == "-Infinity")
      return -std::numeric_limits<float>::infinity();
    return std::nullopt;
  default:
    return std::nullopt;
  }
}

} // namespace rastrules::io
