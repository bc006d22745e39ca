// key.json (src/grading/answer_key.cpp): a KeyError that names the file (and the sheet and field
// where it can), never nlohmann's own exceptions; a key read has sheets under canonical ids, each
// found by its id, and questions whose ids start with their exercise's number.
#include <cmath>
#include <cstdint>

#include "fuzz_support.h"
#include "grading/answer_key.h"

using namespace epure;
using namespace epure::grading;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  AnswerKey key;
  try {
    key = read_key_json(text, "key.json");
  } catch (const KeyError& e) {
    const std::string_view what = e.what();
    fuzz::check(fuzz::starts_with(what, "key.json: ") && what.size() > 10, "a key error does not name the file", what);
    fuzz::check(what.find("[json.exception") == std::string_view::npos || what.find("not valid JSON") != std::string_view::npos,
                "a key error is nlohmann's raw text", what);
    return 0;
  }
  fuzz::check(!key.sheets().empty(), "a key read with no sheet");
  for (const SheetKey& s : key.sheets()) {
    fuzz::check(key.find(s.id) == &s, "a sheet is not found by its id", s.id);
    fuzz::check(s.sheet.str() == s.id, "a sheet id is not canonical", s.id);
    fuzz::check(std::isfinite(s.max_points) && s.max_points >= 0, "max_points not a finite number ≥ 0", s.id);
    for (const ExerciseKey& e : s.exercises) {
      fuzz::check(e.hot.size() == e.questions.size(), "packed questions lost", s.id);
      for (std::size_t i = 0; i < e.questions.size(); ++i) {
        const QuestionKey& q = e.questions[i];
        fuzz::check(!e.number.empty() && fuzz::starts_with(q.id, e.number + "."),
                    "a question id without its exercise's number", q.id);
        fuzz::check(q.id.size() == e.number.size() + 1 + q.field.size(), "a question's field is not its id's rest", q.id);
        fuzz::check(e.find(q.field) >= 0, "a question is not found by its field", q.id);
        fuzz::check(q.rule.rel >= 0 && q.rule.abs >= 0 && q.points >= 0, "a negative tolerance or points", q.id);
      }
    }
  }
  return 0;
}
