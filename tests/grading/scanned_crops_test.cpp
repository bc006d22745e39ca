// The crops `epure scan --crops` writes, read back for the feedback sheets: a PNG is taken as it
// is with its size; a file that is not one, a missing one, or a name that would leave the
// directory gives none (and the sheet is still written).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "grading/scanned_crops.h"
#include "support/safe_file_name.h"
#include "support/tiny_png.h"

using namespace epure;
using namespace epure::grading;

namespace {

const std::string& kPng = test::kTinyPng;

void write(const std::filesystem::path& p, const std::string& bytes) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

}  // namespace

TEST_CASE("scanned crops: a PNG taken as it is, anything else left out") {
  const auto dir = std::filesystem::temp_directory_path() / "epure-scanned-crops-test";
  std::filesystem::remove_all(dir);
  write(dir / "1000-0005-000S" / "2.t.png", kPng);
  write(dir / "1000-0005-000S" / "2.P.png", "not a png");
  write(dir / "outside.png", kPng);
  const ScannedCrops crops(dir);
  const auto r = crops.crop("1000-0005-000S", "2.t");
  REQUIRE_FALSE(r.empty());
  CHECK(*r.png == kPng);
  CHECK(r.width_px == 4);
  CHECK(r.height_px == 2);
  CHECK(crops.crop("1000-0005-000S", "2.P").empty());    // said on stderr
  CHECK(crops.crop("1000-0005-000S", "3.t").empty());    // not scanned: no crop, nothing said
  CHECK(crops.crop("..", "outside").empty());            // never a path out of the directory
  CHECK(crops.crop("1000-0005-000S", "../outside").empty());
  CHECK(ScannedCrops({}).crop("1000-0005-000S", "2.t").empty());
  std::filesystem::remove_all(dir);
}

TEST_CASE("file names from outside data: ids only") {
  CHECK(safe_file_name("1000-0005-000S"));
  CHECK(safe_file_name("3.3.t"));
  CHECK(safe_file_name("P.dot"));
  CHECK_FALSE(safe_file_name(""));
  CHECK_FALSE(safe_file_name("."));
  CHECK_FALSE(safe_file_name(".."));
  CHECK_FALSE(safe_file_name(".hidden"));
  CHECK_FALSE(safe_file_name("a/b"));
  CHECK_FALSE(safe_file_name("a\\b"));
  CHECK_FALSE(safe_file_name("é"));
  CHECK_FALSE(safe_file_name(std::string(129, 'a')));
}

TEST_CASE("scanned crops: sized on paper at the resolution the PNG states, 216 dpi when it states none") {
  const auto dir = std::filesystem::temp_directory_path() / "epure-scanned-crops-dpi-test";
  std::filesystem::remove_all(dir);
  // kPng with a pHYs chunk of 108 dpi (4252 pixels a metre) after IHDR
  const std::string phys("\x00\x00\x00\x09pHYs\x00\x00\x10\x9c\x00\x00\x10\x9c\x01\x00\x00\x00\x00", 21);
  write(dir / "S" / "a.png", kPng.substr(0, 33) + phys + kPng.substr(33));
  write(dir / "S" / "b.png", kPng);
  const ScannedCrops crops(dir);
  CHECK(crops.crop("S", "a").natural_height_pt == doctest::Approx(2 * 72.0 / 108).epsilon(1e-3));
  CHECK(crops.crop("S", "b").natural_height_pt == doctest::Approx(2 * 72.0 / kUnstatedCropDpi));
  std::filesystem::remove_all(dir);
}
