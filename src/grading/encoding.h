#pragma once
// Spreadsheets on Windows still save "CSV" in Windows-1252 unless told "CSV UTF-8": a name
// like "Élise" then arrives as one byte 0xC9. Such text is not valid UTF-8; it is read as
// Windows-1252 instead, and the run says so once.
#include <span>
#include <string>
#include <string_view>

namespace epure::grading {

bool valid_utf8(std::string_view s);
// Whether every cell is valid UTF-8 (the cells of one record, checked in one pass when they lie
// in order in one buffer).
bool all_valid_utf8(std::span<const std::string_view> cells);
// Windows-1252 bytes as UTF-8 (the five unassigned bytes become U+FFFD).
std::string cp1252_to_utf8(std::string_view s);

}  // namespace epure::grading
