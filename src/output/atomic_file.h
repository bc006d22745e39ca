#pragma once
// Files are written whole or not at all: the bytes go to a temporary file beside the target,
// which is flushed and renamed over it (rename is atomic on one file system). A crash leaves at
// worst a stray *.tmp file, never a half file that looks whole.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace epure::output {

class AtomicFile {
 public:
  // Opens "<path>.<pid>.tmp" for writing; throws std::runtime_error naming the path.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();  // not committed: the temporary is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view bytes);
  // Rewrites bytes already written, from `offset` (the file's end does not move); throws
  // std::runtime_error naming the path.
  void overwrite(std::uint64_t offset, std::string_view bytes);
  // Flushes, closes and renames over the target; throws std::runtime_error on any failure.
  void commit();

 private:
  std::filesystem::path path_, temp_;
  std::FILE* file_ = nullptr;
};

// The whole file in one call.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace epure::output
