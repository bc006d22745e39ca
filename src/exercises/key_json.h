#pragma once
// key.json: the answer key of a whole set, read by grading and platform exports. One object:
//   { "spec": {...}, "seed": S, "version": {...}, "sheets": [ { "id", "index", "exercises": [
//       { "n", "kind", "branch", "instance", "solution", "questions": [
//           { "id", "expected", "exact"?, "tolerance": {"rule", "rel"?, "abs"?, "why"},
//             "points", "point"? } ] } ] } ] }
// `instance` is exactly a solve input and `solution` exactly the solve output for it. Written
// sheet by sheet (a set of 10,000 sheets is never held in memory).
#include <fmt/format.h>

#include <string>

#include "exercises/worksheet.h"

namespace epure {

// Who has a sheet (`generate --roster`): recorded in key.json with the sheet.
struct SheetStudent {
  std::string number;  // as the roster writes it
  std::string name;
  std::string email;   // empty when the roster has none
};

class KeyJson {
 public:
  // Appends the opening of the object: spec, seed, version, and "sheets":[
  static void begin(fmt::memory_buffer& out, const WorksheetSet& set, std::string_view epure_version);
  // Appends one sheet (with a comma before it unless it is the first).
  // `student`: the roster's student who has it ("student": {"number", "name", "email"}).
  static void sheet(fmt::memory_buffer& out, const Sheet& sheet, bool first, const SheetStudent* student = nullptr);
  // Closes the array and the object.
  static void end(fmt::memory_buffer& out);
};

}  // namespace epure
