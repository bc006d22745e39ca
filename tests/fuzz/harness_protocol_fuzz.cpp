// The records a student's program sends back (src/check/protocol.cpp), which the student's code
// can write anything into: never throws; the same bytes give the same records whatever the
// pieces they arrive in; records come only from whole 56-byte blocks; once broken, the reader
// says why and gives nothing more; every record decoded is within range (a function number
// known, a signal in 1..64, a hello of this protocol version).
#include <cstdint>
#include <variant>

#include "check/protocol.h"
#include "fuzz_support.h"

using namespace epure;
using namespace epure::check;

namespace {

bool in_range(const Record& r) {
  if (const auto* h = std::get_if<record::Hello>(&r)) return h->version == kProtocolVersion && h->defined < (1u << kFunctionCount);
  if (const auto* k = std::get_if<record::Raised>(&r)) return k->signal >= 1 && k->signal <= 64;
  if (const auto* g = std::get_if<record::Fatal>(&r)) return g->signal >= 1 && g->signal <= 64;
  if (const auto* res = std::get_if<record::Result>(&r)) return static_cast<int>(res->fn) < kFunctionCount;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // the first byte chooses how the rest is cut into pieces
  const std::size_t step = 1 + data[0] % 97;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  ResultReader whole, pieces;
  const std::vector<Record> all = whole.feed(bytes);
  std::vector<Record> cut;
  for (std::size_t at = 0; at < bytes.size(); at += step) {
    auto r = pieces.feed(bytes.substr(at, step));
    cut.insert(cut.end(), r.begin(), r.end());
  }
  fuzz::check(all.size() == cut.size() && whole.broken() == pieces.broken(), "the pieces change what is read");
  fuzz::check(all.size() <= bytes.size() / kResultRecordSize, "more records than whole blocks");
  for (const Record& r : all) fuzz::check(in_range(r), "a record out of range");
  if (whole.broken()) {
    fuzz::check(!whole.error().empty(), "broken without a reason");
    fuzz::check(whole.feed(bytes).empty(), "records after the reader broke");
  } else {
    fuzz::check(whole.pending() == bytes.size() % kResultRecordSize, "bytes lost or kept twice");
  }
  return 0;
}
