#pragma once
// What every fuzz target shares: an invariant that does not hold is a crash libFuzzer keeps
// (the input is saved as crash-*, and goes to tests/fuzz/corpus/<target>/ once fixed).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace epure::fuzz {

[[noreturn]] inline void broken(std::string_view what, std::string_view detail = {}) {
  std::fprintf(stderr, "fuzz invariant broken: %.*s\n  %.*s\n", int(what.size()), what.data(),
               int(detail.size() > 2000 ? 2000 : detail.size()), detail.data());
  std::abort();
}

inline void check(bool ok, std::string_view what, std::string_view detail = {}) {
  if (!ok) broken(what, detail);
}

inline bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace epure::fuzz
