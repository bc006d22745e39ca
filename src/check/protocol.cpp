#include "check/protocol.h"

#include <cstring>

#include <fmt/format.h>

namespace epure::check {

namespace {

template <class T>
T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

std::optional<Fn> function_of(std::uint8_t n) {
  if (n < kFunctionCount) return static_cast<Fn>(n);
  return std::nullopt;
}

}  // namespace

std::array<char, kCaseRecordSize> encode_case(Fn fn, std::uint32_t seq, const Inputs& in) {
  std::array<char, kCaseRecordSize> r{};
  r[0] = 'C';
  r[1] = static_cast<char>(fn);
  std::memcpy(r.data() + 4, &seq, sizeof seq);
  std::memcpy(r.data() + 8, in.data(), sizeof(double) * kMaxInputs);
  return r;
}

std::vector<Record> ResultReader::feed(std::string_view bytes) {
  std::vector<Record> out;
  if (broken()) return out;
  buffer_.append(bytes);
  std::size_t at = 0;
  while (buffer_.size() - at >= kResultRecordSize) {
    auto r = decode(buffer_.data() + at);
    if (!r) {
      buffer_.clear();
      return out;
    }
    out.push_back(std::move(*r));
    at += kResultRecordSize;
  }
  buffer_.erase(0, at);
  return out;
}

std::optional<Record> ResultReader::decode(const char* p) {
  const char tag = p[0];
  const auto fn_byte = static_cast<std::uint8_t>(p[1]);
  const auto flag = static_cast<std::uint8_t>(p[2]);
  const auto seq = load<std::uint32_t>(p + 4);
  std::array<std::int64_t, kMaxOutputs> words{};
  std::memcpy(words.data(), p + 8, sizeof words);
  const std::optional<Fn> fn = function_of(fn_byte);
  auto bad = [&](std::string why) -> std::optional<Record> {
    error_ = std::move(why);
    return std::nullopt;
  };
  switch (tag) {
    case 'H':
      if (seq != kProtocolVersion) return bad(fmt::format("a hello of protocol version {}", seq));
      if (words[0] < 0 || words[0] >= (std::int64_t{1} << kFunctionCount))
        return bad("a hello naming functions that do not exist");
      return record::Hello{seq, static_cast<std::uint32_t>(words[0])};
    case 'R': {
      if (!fn) return bad(fmt::format("a result for function {}", fn_byte));
      if (flag > 1) return bad("a result whose boolean is neither 0 nor 1");
      record::Result r{*fn, seq, {}};
      r.outcome.hit = flag == 1;
      std::memcpy(r.outcome.out.data(), p + 8, sizeof r.outcome.out);
      return r;
    }
    case 'N':
      if (!fn && fn_byte != 255) return bad(fmt::format("a record for function {}", fn_byte));
      return record::NotWritten{fn, seq};
    case 'S':
      return record::Forbidden{fn, seq, static_cast<long>(words[0]), {words[1], words[2], words[3]}};
    case 'K':
      if (words[0] <= 0 || words[0] > 64) return bad("a signal number out of range");
      return record::Raised{fn, seq, static_cast<int>(words[0])};
    case 'G':
      if (words[0] <= 0 || words[0] > 64) return bad("a signal number out of range");
      return record::Fatal{fn, seq, static_cast<int>(words[0]), static_cast<int>(words[1]),
                           static_cast<std::uint64_t>(words[2]), flag == 1};
    default:
      return bad(fmt::format("a record of unknown type 0x{:02x}", static_cast<unsigned char>(tag)));
  }
}

}  // namespace epure::check
