#pragma once
// The records between epure check and the harness (templates/check/harness.c), fixed-size and in
// native byte order (both ends on one machine). Cases go to the harness on its fd 0 (88 bytes
// each); records come back on its fd 3 (56 bytes each): a hello with the functions the file
// defines, a result per case, or why the process is about to end.
//
// What comes back is written by a process running a student's code, which can write anything on
// that descriptor: ResultReader takes any bytes, in any pieces, and says a protocol error rather
// than trust them (tests/fuzz/harness_protocol_fuzz.cpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "check/functions.h"

namespace epure::check {

inline constexpr std::uint32_t kProtocolVersion = 1;
inline constexpr std::size_t kCaseRecordSize = 88;
inline constexpr std::size_t kResultRecordSize = 56;

// A case, ready to write on the harness's fd 0.
std::array<char, kCaseRecordSize> encode_case(Fn fn, std::uint32_t seq, const Inputs& in);

namespace record {
struct Hello {
  std::uint32_t version;
  std::uint32_t defined;  // bit i: function i is defined by the file
};
struct Result {
  Fn fn;
  std::uint32_t seq;
  Outcome outcome;
};
struct NotWritten {  // the function's body is still TO_WRITE(...)
  std::optional<Fn> fn;  // nothing: called outside any call of the harness (a constructor)
  std::uint32_t seq;
};
struct Forbidden {  // a system call the filter does not allow
  std::optional<Fn> fn;
  std::uint32_t seq;
  long syscall_number;
  std::array<std::int64_t, 3> args;
};
struct Raised {  // a signal the process sent itself (abort, raise)
  std::optional<Fn> fn;
  std::uint32_t seq;
  int signal;
};
struct Fatal {  // a fatal signal (invalid memory access, stack overflow, division trap)
  std::optional<Fn> fn;
  std::uint32_t seq;
  int signal;
  int code;
  std::uint64_t address;
  bool stack_overflow;
};
}  // namespace record

using Record =
    std::variant<record::Hello, record::Result, record::NotWritten, record::Forbidden, record::Raised, record::Fatal>;

// Reads records from the bytes as they arrive.
class ResultReader {
 public:
  // Appends bytes; returns the complete records they finish. After a malformed record the reader
  // is broken for good (error() says why) and returns nothing more.
  std::vector<Record> feed(std::string_view bytes);
  const std::string& error() const { return error_; }
  bool broken() const { return !error_.empty(); }
  // Bytes of a record begun but not finished.
  std::size_t pending() const { return buffer_.size(); }

 private:
  std::optional<Record> decode(const char* bytes);
  std::string buffer_;
  std::string error_;
};

}  // namespace epure::check
