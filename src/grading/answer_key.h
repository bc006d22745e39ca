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
#include "exercises/method.h"
#include "exercises/spec.h"
#include "grading/faces.h"

namespace epure::grading {

class KindGrader;

// What a question expects, read from the type of its `expected` value: the method's answer types
// (exercises/method.h), of which a key's question is never a point (a point is asked as its
// coordinates, each a number; `point` is read as a number where a switch must name it).
using AnswerType = method::AnswerType;

// What marking reads for every answer comes first, in one cache line: a large key is read
// sheet after sheet, each row of answers touching another sheet's questions.
struct QuestionKey {
  AnswerType type = AnswerType::number;
  bool boolean = false;
  FaceBits faces = 0;  // a set of face names
  int partner = -1;    // a point marked as a whole (rule distance): its other coordinate
  double number = 0;
  double points = 1;
  ToleranceRule rule;
  std::uint32_t field_hash = 0;  // of `field`, for ExerciseKey::find
  std::string id;     // "2.P.x"
  std::string field;  // "P.x"
  std::string word;   // a contract word: "before", "miss", …
  std::optional<std::string> exact;
  std::string point;  // "2.P" for a coordinate of a point, else empty
};

// FNV-1a of a field name, as QuestionKey::field_hash holds it.
inline std::uint32_t field_hash(std::string_view s) {
  std::uint32_t h = 2166136261u;
  for (char c : s) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return h;
}

// The part of a question marking reads for every answer, packed: an exercise's questions side
// by side in a few cache lines (a large key is read sheet after sheet, each row of answers
// touching another sheet).
struct HotQuestion {
  double number = 0;
  double points = 1;
  double rel = 0, abs = 0;
  double follow_abs = 0;  // 0: abs (key.json's tolerance.follow_abs)
  const char* word = nullptr;  // the contract word's static spelling (words.h), compared by address
  int partner = -1;
  std::uint32_t field_hash = 0;
  AnswerType type = AnswerType::number;
  ToleranceRule::Kind rule = ToleranceRule::Kind::exact;
  bool boolean = false;
  FaceBits faces = 0;
};

struct ExerciseKey {
  int n = 0;
  std::string number;  // what its question ids start with: key.json's "number", else n ("3.3", "2")
  std::string kind;
  std::string branch;
  nlohmann::json instance;  // exactly a solve input
  nlohmann::json solution;  // exactly the solve output for it
  std::vector<QuestionKey> questions;
  std::vector<HotQuestion> hot;  // questions[i] packed, made by read_sheet_json
  std::vector<std::uint32_t> field_hashes;  // hot[i].field_hash side by side: find() scans one cache line
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
  std::optional<double> scale;  // the spec's `scale`: marks also out of this (20)
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
  // A sheet's place in sheets().
  std::size_t index_of(const SheetKey& sheet) const { return static_cast<std::size_t>(&sheet - sheets_.data()); }
  // Every question id of every sheet, in report order (by exercise, then as the sheets ask).
  const std::vector<std::string>& question_ids() const { return question_ids_; }
  // Ids that were asked for but could not be rebuilt (--spec), with why.
  const std::map<std::string, std::string>& refused() const { return refused_; }
  // The id a column named the way sets numbered their questions before exercise numbers
  // (place on the sheet, "6.t" for the ellipse's t where it is now 3.3.t) stands for, or null
  // (also null for every name when no exercise's number differs from its place): answers
  // collected with an older template still grade. Such a name may be another question's id
  // ("4.t" was the circle's t, it is now the square's): only_by_place tells the header apart.
  const std::string* id_of_place_name(std::string_view name) const;
  // Whether `name` is a place name and no question's id ("1.dot", "6.t"): a header holding one
  // is read by place, all of it.
  bool only_by_place(std::string_view name) const;
  // Whether `number` starts some question id of the key ("3.3", "P", "2").
  bool has_number(std::string_view number) const;

  // Adds a sheet (its graders prepared) and merges its question ids into the report order.
  void add(SheetKey sheet);
  void refuse(std::string id, std::string why) { refused_.emplace(std::move(id), std::move(why)); }

 private:
  std::vector<SheetKey> sheets_;
  // Sheet ids → place in sheets_, open addressing (sheet index + 1, 0 for an empty slot): every
  // row of answers looks its sheet up twice (the counting pass and the marking pass), and
  // std::unordered_map's node chasing and division were 6 % of a run.
  std::vector<std::uint32_t> slots_;
  void rehash(std::size_t slots);
  std::vector<std::string> question_ids_;
  std::vector<int> question_places_;  // question_ids_[i]'s exercise place n, for the report order
  std::map<std::string, std::string, std::less<>> place_names_;  // "6.t" → "3.3.t"
  std::map<std::string, int, std::less<>> numbers_;
  std::map<std::string, std::string> refused_;
};

// Limits on what key.json may hold (README, "Limits"): `epure generate` writes at most
// kMaxSheets sheets (about 13 kB each for the course), nested 7 levels deep.
inline constexpr std::size_t kMaxKeyBytes = std::size_t(1) << 30;  // 1 GiB
inline constexpr int kMaxKeyDepth = 64;

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
