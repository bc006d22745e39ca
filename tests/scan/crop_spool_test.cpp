// The review crops set aside on disk while a stack is read (src/scan/crop_spool.h).
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "scan/crop_spool.h"

using namespace epure::scan;
namespace fs = std::filesystem;

TEST_CASE("crop spool: every crop read back as added, in any order, and no file left in its directory") {
  const fs::path dir = fs::temp_directory_path() / "epure_crop_spool_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    CropSpool spool(dir);
    CHECK(fs::is_empty(dir));  // the file has no name from the start
    std::string big(100000, '\0');
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7 % 251);
    const CropRef a = spool.add("first");
    const CropRef b = spool.add(big);
    const CropRef none = spool.add("");
    const CropRef c = spool.add(std::string("\0\x89PNG", 5));
    CHECK(none.size == 0);
    CHECK(spool.read(none).empty());
    // read back out of order, and added to after a read
    CHECK(spool.read(c) == std::string("\0\x89PNG", 5));
    CHECK(spool.read(a) == "first");
    const CropRef d = spool.add("last");
    CHECK(spool.read(b) == big);
    CHECK(spool.read(d) == "last");
    CHECK(b.offset == a.offset + a.size);
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("crop spool: a directory that cannot hold it is named") {
  const fs::path dir = fs::temp_directory_path() / "epure_crop_spool_test_missing" / "nowhere";
  fs::remove_all(dir.parent_path());
  CHECK_THROWS_WITH_AS(CropSpool{dir}, doctest::Contains("epure_crop_spool_test_missing/nowhere"), std::runtime_error);
}
