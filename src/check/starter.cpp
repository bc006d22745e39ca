#include "check/starter.h"

#include <stdexcept>

#include <fmt/format.h>

#include "embed/embedded.h"
#include "output/atomic_file.h"

namespace epure::check {

namespace {
constexpr const char* kNames[] = {"raytracer.c", "raytracer.h", "g2x.h", "g3x.h", "README.md"};
}

std::vector<std::pair<std::string, std::string>> starter_files(const std::string& language) {
  if (language != "en" && language != "fr")
    throw std::invalid_argument(fmt::format("no starter in '{}': en or fr", language));
  std::vector<std::pair<std::string, std::string>> files;
  for (const char* name : kNames) {
    const auto text = embedded_file(fmt::format("check/starter/{}/{}", language, name));
    if (!text) throw std::runtime_error(fmt::format("epure was built without templates/check/starter/{}/{}", language, name));
    files.emplace_back(name, std::string(*text));
  }
  return files;
}

std::vector<std::string> write_starter(const std::filesystem::path& dir, const std::string& language, bool overwrite) {
  const auto files = starter_files(language);
  std::filesystem::create_directories(dir);
  std::vector<std::string> kept;
  for (const auto& [name, text] : files) {
    if (!overwrite && std::filesystem::exists(dir / name)) {
      kept.push_back(name);
      continue;
    }
    output::write_file_atomically(dir / name, text);
  }
  return kept;
}

}  // namespace epure::check
