#pragma once
// The crops review.html shows (the uncertain fields'), set aside on disk while the stack is read
// and read back one at a time when the page is written: a class's stack holds a few crops a page,
// and keeping them in memory made the scan's memory grow with the pages (bench/README.md,
// "Scan"). The file is removed from its directory as soon as it is open, so no run, not even one
// that crashes, leaves it behind.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace epure::scan {

// Where a crop lies in its spool; `size` 0: no crop.
struct CropRef {
  std::uint64_t offset = 0;
  std::uint32_t size = 0;
};

class CropSpool {
 public:
  // Opens an anonymous file in `dir` (which must exist); throws std::runtime_error naming it.
  explicit CropSpool(const std::filesystem::path& dir);
  ~CropSpool();
  CropSpool(const CropSpool&) = delete;
  CropSpool& operator=(const CropSpool&) = delete;

  // Appends the bytes; throws std::runtime_error when they cannot be written. Not thread-safe.
  CropRef add(std::string_view bytes);
  // The bytes at `ref`; throws std::runtime_error when they cannot be read back.
  std::string read(CropRef ref) const;

 private:
  std::filesystem::path dir_;
  std::FILE* file_ = nullptr;
  std::uint64_t end_ = 0;
};

}  // namespace epure::scan
