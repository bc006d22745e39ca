#include "scan/crop_spool.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace epure::scan {

CropSpool::CropSpool(const std::filesystem::path& dir) : dir_(dir) {
  const std::filesystem::path path = dir / fmt::format(".epure-review-crops.{}.tmp", static_cast<long>(::getpid()));
  file_ = std::fopen(path.c_str(), "w+b");
  if (!file_)
    throw std::runtime_error(fmt::format("cannot write a temporary file in '{}': {}", dir.string(), std::strerror(errno)));
  // the open file lives on without its name (POSIX): nothing to remove later
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

CropSpool::~CropSpool() {
  if (file_) std::fclose(file_);
}

CropRef CropSpool::add(std::string_view bytes) {
  if (bytes.empty()) return {};
  if (std::fseek(file_, 0, SEEK_END) != 0 || std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    throw std::runtime_error(fmt::format("cannot write a temporary file in '{}': {}", dir_.string(), std::strerror(errno)));
  const CropRef ref{end_, static_cast<std::uint32_t>(bytes.size())};
  end_ += bytes.size();
  return ref;
}

std::string CropSpool::read(CropRef ref) const {
  std::string bytes(ref.size, '\0');
  if (ref.size == 0) return bytes;
  if (std::fseek(file_, static_cast<long>(ref.offset), SEEK_SET) != 0 || std::fread(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    throw std::runtime_error(fmt::format("cannot read back a temporary file in '{}'", dir_.string()));
  return bytes;
}

}  // namespace epure::scan
