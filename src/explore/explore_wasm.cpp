// The explorer's core as a WebAssembly module (embind): explorer.h's functions, by name, for the
// page's script (src/explore/page.html). Built by em++ only (src/explore/wasm.cmake).
#include <emscripten/bind.h>

#include <string>

#include "explore/explorer.h"

namespace {

namespace ex = epure::explore;

std::string solve(const std::string& line) { return ex::solve(line); }
std::string kinds() { return ex::kinds(); }
std::string words(const std::string& language) { return ex::words(language); }
std::string starting_instance(const std::string& kind) { return ex::starting_instance(kind); }
std::string view(const std::string& instance, const std::string& language, int n, const std::string& frozen) {
  return ex::view(instance, language, n, frozen);
}
std::string drag(const std::string& instance, const std::string& handle, double x, double y,
                 const std::string& frame, bool snap, bool height) {
  return ex::drag(instance, handle, x, y, frame, snap, height);
}
std::string nudge(const std::string& instance, const std::string& handle, int dx, int dy, int dz, bool snap) {
  return ex::nudge(instance, handle, dx, dy, dz, snap);
}

}  // namespace

EMSCRIPTEN_BINDINGS(epure) {
  emscripten::function("solve", &solve);
  emscripten::function("kinds", &kinds);
  emscripten::function("words", &words);
  emscripten::function("startingInstance", &starting_instance);
  emscripten::function("view", &view);
  emscripten::function("drag", &drag);
  emscripten::function("nudge", &nudge);
}
