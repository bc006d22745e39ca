// A crop file read back for a feedback sheet (src/grading/scanned_crops.cpp, over
// support/png_size.h), and the names that may become its path (support/safe_file_name.h):
// never an exception; a crop taken is the file's bytes as they are, with the size its PNG
// header gives, within kMaxPngSide; bytes that are not a PNG give none; a name accepted as a
// file name holds no '/' and is no "." or ".." and starts with no '.'.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "fuzz_support.h"
#include "grading/scanned_crops.h"
#include "support/png_size.h"
#include "support/safe_file_name.h"

using namespace epure;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  if (safe_file_name(bytes))
    fuzz::check(bytes.find('/') == std::string::npos && bytes.front() != '.' && bytes.find('\0') == std::string::npos,
                "a name accepted that could leave its directory", bytes);
  static const fs::path dir = fs::temp_directory_path() / ("epure-fuzz-crop-" + std::to_string(::getpid()));
  fs::create_directories(dir / "S");
  {
    std::ofstream out(dir / "S" / "q.png", std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  try {
    const render::Raster r = grading::ScannedCrops(dir).crop("S", "q");
    const auto header = png_size(bytes);
    fuzz::check(r.empty() == !header, "a crop taken for bytes that are not a PNG, or refused for a PNG header");
    if (!r.empty()) {
      fuzz::check(*r.png == bytes, "a crop's bytes are not the file's");
      fuzz::check(r.width_px == header->width && r.height_px == header->height && r.width_px >= 1 && r.height_px >= 1 &&
                      r.width_px <= static_cast<int>(kMaxPngSide) && r.height_px <= static_cast<int>(kMaxPngSide),
                  "a crop's size is not its header's");
    }
    fuzz::check(grading::ScannedCrops(dir).crop("..", "q").empty() && grading::ScannedCrops(dir).crop("S", "../S/q").empty(),
                "a crop read through a name that leaves the directory");
  } catch (const std::exception& e) {
    fuzz::broken("an exception", e.what());
  }
  return 0;
}
