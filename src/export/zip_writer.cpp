#include "export/zip_writer.h"

#include <fmt/format.h>
#include <zip.h>

#include <memory>
#include <set>

#include "export/export_set.h"

namespace epure::exporting {

namespace {

// 1980-01-01 00:00:00 as MS-DOS packs it: date (year − 1980) << 9 | month << 5 | day, time 0.
constexpr zip_uint16_t kDosDate = (0 << 9) | (1 << 5) | 1;
constexpr zip_uint16_t kDosTime = 0;

[[noreturn]] void fail(std::string_view what, zip_error_t* error) {
  const std::string message = fmt::format("zip archive: {}: {}", what, zip_error_strerror(error));
  zip_error_fini(error);
  throw ExportError(message);
}

[[noreturn]] void fail(std::string_view what, zip_t* archive) {
  const std::string message = fmt::format("zip archive: {}: {}", what, zip_strerror(archive));
  zip_discard(archive);
  throw ExportError(message);
}

}  // namespace

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  std::set<std::string_view> names;
  for (const auto& e : entries)
    if (!names.insert(e.name).second) throw ExportError(fmt::format("zip archive: the name {} twice", e.name));

  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!buffer) fail("a buffer", &error);
  zip_source_keep(buffer);  // kept past zip_close, to read the archive back
  const auto free_buffer = std::unique_ptr<zip_source_t, void (*)(zip_source_t*)>(buffer, zip_source_free);
  zip_t* archive = zip_open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (!archive) fail("opening", &error);
  for (const auto& e : entries) {
    // the data is read at zip_close, from `entries`, which outlives it
    zip_source_t* data = zip_source_buffer(archive, e.bytes.data(), e.bytes.size(), 0);
    if (!data) fail(e.name, archive);
    const zip_int64_t index = zip_file_add(archive, e.name.c_str(), data, ZIP_FL_ENC_UTF_8);
    if (index < 0) {
      zip_source_free(data);
      fail(e.name, archive);
    }
    const auto i = static_cast<zip_uint64_t>(index);
    if (zip_file_set_dostime(archive, i, kDosTime, kDosDate, 0) < 0) fail(e.name, archive);
    if (zip_set_file_compression(archive, i, ZIP_CM_DEFLATE, 9) < 0) fail(e.name, archive);
    if (zip_file_set_external_attributes(archive, i, 0, ZIP_OPSYS_UNIX, 0100644u << 16) < 0) fail(e.name, archive);
  }
  if (zip_close(archive) < 0) fail("writing", archive);

  std::string out;
  if (zip_source_open(buffer) < 0 || zip_source_seek(buffer, 0, SEEK_END) < 0)
    throw ExportError(fmt::format("zip archive: reading it back: {}", zip_error_strerror(zip_source_error(buffer))));
  const zip_int64_t size = zip_source_tell(buffer);
  if (size < 0 || zip_source_seek(buffer, 0, SEEK_SET) < 0)
    throw ExportError(fmt::format("zip archive: reading it back: {}", zip_error_strerror(zip_source_error(buffer))));
  out.resize(static_cast<std::size_t>(size));
  if (zip_source_read(buffer, out.data(), static_cast<zip_uint64_t>(size)) != size)
    throw ExportError(fmt::format("zip archive: reading it back: {}", zip_error_strerror(zip_source_error(buffer))));
  zip_source_close(buffer);
  zip_error_fini(&error);
  return out;
}

}  // namespace epure::exporting
