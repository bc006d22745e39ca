#pragma once
// A zip archive built in memory, byte-identical for the same entries: entries in the order
// they are added, every timestamp 1980-01-01 00:00 (the earliest DOS date, set as a DOS date so
// that the time zone plays no part), deflated at level 9. Written with libzip (Debian's
// libzip-dev): it builds an archive in a memory buffer (zip_source_buffer_create), so the
// caller writes it atomically, and it sets DOS timestamps directly (zip_file_set_dostime).
#include <string>
#include <string_view>
#include <vector>

namespace epure::exporting {

struct ZipEntry {
  std::string name;   // "items/1000-0001-000X-2.xml"
  std::string bytes;
};

// The archive's bytes. Throws ExportError when libzip fails, or for a repeated name.
std::string zip_archive(const std::vector<ZipEntry>& entries);

}  // namespace epure::exporting
