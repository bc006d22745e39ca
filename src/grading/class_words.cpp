#include "grading/class_words.h"

#include <fmt/format.h>

#include "exercises/worksheet.h"

namespace epure::grading {

ClassWords::ClassWords(const AnswerKey& key, const Texts& texts) : texts_(texts) {
  if (key.info.spec_text.empty()) return;
  try {
    spec_ = parse_spec(key.info.spec_text, key.info.source + " (spec)");
  } catch (const std::exception&) {
    // a spec that no longer reads: exercises are then "Exercise n"
  }
}

std::string ClassWords::exercise(int n) const {
  const auto slot = static_cast<std::size_t>(n - 1);
  if (spec_ && n >= 1 && slot < spec_->exercises.size()) return exercise_label(*spec_, slot, texts_);
  return texts_.format("common.exercise_label", {{"n", std::to_string(n)}});
}

std::string ClassWords::title(std::string_view kind) const {
  const std::string key = fmt::format("{}.title", kind);
  return texts_.has(key) ? texts_.get(key) : std::string(kind);
}

std::string ClassWords::name(std::string_view table, std::string_view code) const {
  const std::string key = fmt::format("grading.{}.{}", table, code);
  return texts_.has(key) ? texts_.get(key) : std::string(code);
}

std::string ClassWords::branch(std::string_view code) const { return name("branch", code); }
std::string ClassWords::mistake(std::string_view code) const { return name("mistake_name", code); }
std::string ClassWords::flag(std::string_view code) const {
  auto it = flags_.find(code);
  if (it == flags_.end()) it = flags_.emplace(std::string(code), name("flag_name", code)).first;
  return it->second;
}

}  // namespace epure::grading
