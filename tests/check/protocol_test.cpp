// The harness's records, read as they come, whatever comes (check/protocol.h).
#include <doctest/doctest.h>

#include <cstring>

#include "check/protocol.h"

using namespace epure::check;

namespace {
std::string result_record(char tag, std::uint8_t fn, std::uint8_t flag, std::uint32_t seq, std::array<double, 6> out) {
  std::string r(kResultRecordSize, '\0');
  r[0] = tag;
  r[1] = static_cast<char>(fn);
  r[2] = static_cast<char>(flag);
  std::memcpy(r.data() + 4, &seq, 4);
  std::memcpy(r.data() + 8, out.data(), 48);
  return r;
}
}  // namespace

TEST_CASE("records arrive whole, split, or several at once") {
  std::array<double, 6> hello{};
  std::int64_t mask = 0b101;
  std::memcpy(hello.data(), &mask, 8);
  const std::string bytes = result_record('H', 0, 0, kProtocolVersion, hello) +
                            result_record('R', 2, 1, 7, {1.5, -2, 0.6, 0.8, 0, 0});
  ResultReader reader;
  std::vector<Record> got;
  for (char c : bytes) {  // one byte at a time
    auto r = reader.feed(std::string_view(&c, 1));
    got.insert(got.end(), r.begin(), r.end());
  }
  REQUIRE(got.size() == 2);
  CHECK(std::get<record::Hello>(got[0]).defined == 0b101);
  const auto& res = std::get<record::Result>(got[1]);
  CHECK(res.fn == Fn::circle);
  CHECK(res.seq == 7);
  CHECK(res.outcome.hit);
  CHECK(res.outcome.out[0] == 1.5);
  CHECK_FALSE(reader.broken());
}

TEST_CASE("a malformed record breaks the reader for good") {
  ResultReader reader;
  CHECK(reader.feed(result_record('X', 0, 0, 0, {})).empty());
  CHECK(reader.broken());
  CHECK(reader.feed(result_record('R', 0, 1, 0, {})).empty());
  ResultReader bad_fn;
  bad_fn.feed(result_record('R', 40, 1, 0, {}));
  CHECK(bad_fn.broken());
  ResultReader bad_flag;
  bad_flag.feed(result_record('R', 1, 7, 0, {}));
  CHECK(bad_flag.broken());
  ResultReader bad_version;
  bad_version.feed(result_record('H', 0, 0, 99, {}));
  CHECK(bad_version.broken());
}

TEST_CASE("a case is written as the harness reads it") {
  Inputs in{};
  in[0] = 3.25;
  in[9] = -1;
  const auto r = encode_case(Fn::sphere, 42, in);
  CHECK(r[0] == 'C');
  CHECK(r[1] == static_cast<char>(Fn::sphere));
  std::uint32_t seq;
  std::memcpy(&seq, r.data() + 4, 4);
  CHECK(seq == 42);
  double last;
  std::memcpy(&last, r.data() + 8 + 9 * 8, 8);
  CHECK(last == -1);
}
