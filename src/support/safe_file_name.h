#pragma once
// Whether a name read from outside data (a sheet or question id from a key, a layout or an
// answers file) may become a file name as it is: letters, digits, '.', '-' and '_', not
// starting with '.', at most 128 bytes. Any other never becomes a path (no "../", no '/').
#include <string_view>

namespace epure {

inline bool safe_file_name(std::string_view name) {
  if (name.empty() || name.size() > 128 || name.front() == '.') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    if (!ok) return false;
  }
  return true;
}

}  // namespace epure
