// SPDX-License-Identifier: MIT
// Strict streaming JSON reading, shared by the scene reader (scene_json.hpp) and the external
// driver's output reader (tools/driver, DRIVER.EXTERNAL.PROTOCOL): the JSON library's SAX
// parser, never a document tree. A JsonHandler sees each value as it is read, checks it against
// its schema and stops the parse at the first error, so that memory stays what the handler
// keeps (plus the token being read) and a bad input costs no more than its first bad value.
// Implements: SCENE.INPUT.ERRORS (the parser's part: JSON syntax, a raw NUL byte)

#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace rastrules::io {

enum class JsonKind { kNull, kBool, kInt, kUint, kFloat, kString, kObject, kArray };

// One value as the parser reports it: a scalar, or the start of an object or array (whose keys
// and elements follow, then end_object() or end_array()). An integer that an int64_t holds is
// kInt (i), a larger one kUint (u); text is a kFloat's number text or a kString's content, valid
// only until the handler returns.
struct JsonValue {
  JsonKind kind = JsonKind::kNull;
  bool b = false;
  std::int64_t i = 0;
  std::uint64_t u = 0;
  std::string_view text;
};

// rule: SCENE.NUMBER.FLOAT32
// A JSON value read as float32: an integer rounded once, another number correctly rounded from
// its text (decimal_to_float32, rastrules/io/scene_json.hpp), the strings "NaN", "Infinity" and
// "-Infinity" as those values; nullopt for anything else (a kFloat whose text is no number
// included).
[[nodiscard]] std::optional<float> json_float32(const JsonValue& v);

// An error of the JSON library's parser: its exception id (101 syntax, 406 a number beyond any
// number type, ...), its message ("[json.exception.parse_error.101] parse error at line 1,
// column 2: ...") and the last token read (a number's text for 406).
struct JsonSyntaxError {
  int id = 0;
  std::string what;
  std::string_view last_token;
};

// The schema side of a streaming read. Each function returns false to stop the parse; the
// handler then keeps its own error.
class JsonHandler {
public:
  virtual ~JsonHandler() = default;
  virtual bool value(const JsonValue& v) = 0;
  virtual bool key(std::string_view k) = 0;
  virtual bool end_object() = 0;
  virtual bool end_array() = 0;
  virtual bool syntax_error(const JsonSyntaxError& e) = 0;
};

// How a parse ended.
struct JsonParseEnd {
  // The text was one complete JSON value (and nothing but white space after it) that the
  // handler accepted throughout.
  bool ok = false;
  // The text holds a raw NUL byte, which the JSON library would take for the end of the input:
  // the parse stopped there (the handler saw only the text before it), and this is
  // nul_byte_problem's message for it. An error the handler or the parser found before the NUL
  // comes first in reading order; a syntax error caused by the text ending at the NUL is not
  // passed to the handler.
  std::optional<std::string> nul;
};

// Returns "parse error at line L, column C: a raw NUL byte, which JSON text cannot hold" for
// the first NUL byte of text, or nullopt. The JSON library's lexer would take it for the end of
// the input and accept a valid prefix followed by anything.
// rule: SCENE.INPUT.ERRORS
[[nodiscard]] std::optional<std::string> nul_byte_problem(std::string_view text);

// Parses text, whole in memory, with the strict parser (one value, no comments).
// rule: SCENE.INPUT.ERRORS
JsonParseEnd parse_json(std::string_view text, JsonHandler& handler);

// Pieces of JSON text, in order: each call returns the next bytes (valid until the next call),
// an empty view at the end of the text.
using JsonChunks = std::function<std::string_view()>;

// The same, reading the text piece by piece as next() gives it: only the current piece and the
// current token are held, never the whole text, and no piece is asked for after the parse stops.
// rule: SCENE.INPUT.ERRORS
JsonParseEnd parse_json(const JsonChunks& next, JsonHandler& handler);

} // namespace rastrules::io
