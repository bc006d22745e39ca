// Strict UTF-8 (RFC 3629) and the writer's U+FFFD: what tests/fuzz found taken as UTF-8.
#include <doctest/doctest.h>

#include "grading/encoding.h"
#include "grading/expression.h"
#include "solve/json_out.h"

using namespace epure::grading;

TEST_CASE("valid_utf8 follows RFC 3629: no overlong form, no surrogate, nothing past U+10FFFF") {
  CHECK(valid_utf8("L\xc3\xa9o \xe2\x88\x9a" "11 \xf0\x9f\x98\x80"));  // é, √, an emoji
  CHECK(valid_utf8("\xed\x9f\xbf"));       // U+D7FF, the last before the surrogates
  CHECK(valid_utf8("\xf4\x8f\xbf\xbf"));   // U+10FFFF
  CHECK_FALSE(valid_utf8("\xed\xa0\x80"));  // U+D800, a surrogate
  CHECK_FALSE(valid_utf8("\xe0\x80\x80"));  // an overlong NUL
  CHECK_FALSE(valid_utf8("\xf0\x80\x80\x80"));
  CHECK_FALSE(valid_utf8("\xf4\x90\x80\x80"));  // past U+10FFFF
  CHECK_FALSE(valid_utf8("\xc0\xaf"));
  // read as Windows-1252 instead, and valid then
  CHECK(valid_utf8(cp1252_to_utf8("\xed\xa0\x80")));
}

TEST_CASE("JSON strings are written as UTF-8: a byte that starts no character is U+FFFD") {
  fmt::memory_buffer out;
  epure::JsonWriter(out).begin_object().field("error", std::string_view("last read: '\"ray\xd5'")).end_object();
  CHECK(std::string(out.data(), out.size()) == R"({"error":"last read: '\"ray\ufffd'"})");
  out.clear();
  epure::JsonWriter(out).begin_object().field("name", std::string_view("Zo\xc3\xa9 \xed\xa0\x80")).end_object();
  CHECK(std::string(out.data(), out.size()) == "{\"name\":\"Zo\xc3\xa9 \\ufffd\\ufffd\\ufffd\"}");
}

TEST_CASE("blanks around a typed number are no part of it (the fast paths and the parser agree)") {
  const auto a = parse_number("1.5e-3");
  const auto b = parse_number(" 1.5e-3\t");
  REQUIRE(a.ok);
  REQUIRE(b.ok);
  CHECK(a.value == b.value);
}
