#pragma once
// The answer key grading marks against: key.json as `epure generate` writes it
// (exercises/key_json.h), or the same sheets rebuilt from a spec and their ids (the seed travels
// in each id). key.json is read sheet by sheet, each sheet's JSON dropped once converted, so a
// key of 10,000 sheets is never held as a JSON tree.
#include <nlohmann/json.hpp>

#include <any>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/sheet_id.h"
#include "exercises/spec.h"
#include "grading/faces.h"

namespace epure::grading {

class KindGrader;

// What a question expects, read from the type of its `expected` value.
enum class AnswerType { number, boolean, word, faces };

struct QuestionKey {
  std::string id;     // "2.P.x"
  std::string field;  // "P.x"
  AnswerType type = AnswerType::number;
  double number = 0;
  bool boolean = false;
  std::string word;    // a contract word: "before", "miss", …
  FaceBits faces = 0;  // a set of face names
  std::optional<std::string> exact;
  ToleranceRule rule;
  double points = 1;
  std::string point;  // "2.P" for a coordinate of a point, else empty
};

struct ExerciseKey {
  int n = 0;
  std::string kind;
  std::string branch;
  nlohmann::json instance;  // exactly a solve input
  nlohmann::json solution;  // exactly the solve output for it
  std::vector<QuestionKey> questions;
  const KindGrader* grader = nullptr;  // null for a kind grading has no knowledge of
  std::any prepared;                   // the grader's reading of the instance, made once

  // The index of the question asking `field` ("t", "P.x"), or −1 when this sheet does not ask it.
  int find(std::string_view field) const;
};

struct SheetKey {
  std::string id;  // canonical spelling, "1000-0001-000X"
  SheetId sheet;
  std::vector<ExerciseKey> exercises;
  double max_points = 0;
};

struct KeyInfo {
  std::string source;  // where the key came from, for messages
  std::string title;
  std::string language = "en";
  int decimals = 2;
  bool follow_through = true;
  std::string spec_text;    // the spec the set was drawn from, as written (rebuilds diagrams)
  std::string spec_source;  // its file name when it was written
  std::uint64_t seed = 0;
  std::string epure_version;
  int draw_version = kDrawVersion;
};

// A key that cannot be read: the message names the file and, where it can, the sheet and field.
class KeyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class AnswerKey {
 public:
  KeyInfo info;

  const std::vector<SheetKey>& sheets() const { return sheets_; }
  // The sheet of a canonical id, or null.
  const SheetKey* find(std::string_view canonical_id) const;
  // Every question id of every sheet, in report order (by exercise, then as the sheets ask).
  const std::vector<std::string>& question_ids() const { return question_ids_; }
  // Ids that were asked for but could not be rebuilt (--spec), with why.
  const std::map<std::string, std::string>& refused() const { return refused_; }

  // Adds a sheet (its graders prepared) and merges its question ids into the report order.
  void add(SheetKey sheet);
  void refuse(std::string id, std::string why) { refused_.emplace(std::move(id), std::move(why)); }

 private:
  std::vector<SheetKey> sheets_;
  std::unordered_map<std::string, std::size_t> by_id_;
  std::vector<std::string> question_ids_;
  std::map<std::string, std::string> refused_;
};

// Reads key.json. Throws KeyError "<source>: …" for a file that is not a key; a key from
// another epure version is read (it carries every number and rule grading needs) and its
// versions are left in `info` for the caller to compare.
AnswerKey read_key_json(std::string_view text, std::string_view source);

// One sheet object of key.json (as KeyJson::sheet writes it), converted.
SheetKey read_sheet_json(const nlohmann::json& sheet, std::string_view source);

// The keys of the given sheets, rebuilt from the spec (ids grouped by seed, rebuilt in index
// order). Ids drawn by another generator version are refused, with the reason, not rebuilt.
AnswerKey key_from_spec(const WorksheetSpec& spec, const std::vector<SheetId>& ids,
                        std::string_view epure_version);

}  // namespace epure::grading
