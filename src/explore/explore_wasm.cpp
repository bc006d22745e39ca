// The explorer's core as a WebAssembly module (embind): explorer.h's functions, by name, for the
// page's script (src/explore/page.html). Built by em++ only (src/explore/wasm.cmake).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>

#include "explore/explorer.h"

namespace {

namespace ex = epure::explore;

std::string solve(const std::string& line) { return ex::solve(line); }
std::string kinds() { return ex::kinds(); }
std::string words(const std::string& language) { return ex::words(language); }
std::string starting_instance(const std::string& kind) { return ex::starting_instance(kind); }
// The view's three texts as byte views of the module's memory, valid until the next call: the
// page decodes each with one TextDecoder call. (Returned as std::string, embind first walks every
// byte of a 20-50 kB figure in JavaScript, looking for NULs: a tenth of a move's core time.)
ex::ViewParts last_view;
emscripten::val bytes_of(const std::string& s) {
  return emscripten::val(emscripten::typed_memory_view(s.size(), reinterpret_cast<const unsigned char*>(s.data())));
}
emscripten::val view_parts(const std::string& instance, const std::string& language, int n, const std::string& frozen,
                           const std::string& label) {
  last_view = ex::view_parts(instance, language, n, frozen, label);
  emscripten::val out = emscripten::val::object();
  out.set("head", bytes_of(last_view.head));
  out.set("svg", bytes_of(last_view.svg));
  out.set("steps", bytes_of(last_view.steps));
  return out;
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
  emscripten::function("viewParts", &view_parts);
  emscripten::function("drag", &drag);
  emscripten::function("nudge", &nudge);
}
