#pragma once
// `epure starter`: what students start from, in their language: raytracer.c (each function's
// prototype as the course writes it, with its contract), raytracer.h, the g2x.h and g3x.h headers
// (the course's types and helpers), and a README. From templates/check/starter/<lang>/.
#include <filesystem>
#include <string>
#include <vector>

namespace epure::check {

// The starter's files, by name, for a language ("en", "fr"); throws std::invalid_argument for
// another language.
std::vector<std::pair<std::string, std::string>> starter_files(const std::string& language);

// Writes them into `dir` (created). A file already there is left alone unless `overwrite`:
// returns the names not written because they were there.
std::vector<std::string> write_starter(const std::filesystem::path& dir, const std::string& language, bool overwrite);

}  // namespace epure::check
