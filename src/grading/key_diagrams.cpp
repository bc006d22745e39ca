#include "grading/key_diagrams.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace epure::grading {

namespace {

// Collisions between sheets are rare: a set moves to attempt 1, seldom further.
constexpr int kAttempts = 8;

}  // namespace

KeyDiagrams::KeyDiagrams(const AnswerKey& key, std::string language) {
  if (key.info.draw_version != kDrawVersion) {
    why_not_ = fmt::format("the key was drawn by generator version {}, this epure draws version {}",
                           key.info.draw_version, kDrawVersion);
    return;
  }
  if (key.info.spec_text.empty()) {
    why_not_ = "the key does not carry the text of its spec";
    return;
  }
  try {
    spec_ = parse_spec(key.info.spec_text, key.info.source + " (spec)");
    language_ = std::move(language);
  } catch (const std::exception& e) {
    why_not_ = fmt::format("the key's spec cannot be read: {}", e.what());
  }
}

std::optional<ExerciseInstance> KeyDiagrams::try_set(WorksheetSet& set, const SheetKey& sheet, std::size_t e) {
  const ExerciseKey& ex = sheet.exercises[e];
  const int slot = ex.n - 1;
  if (slot < 0 || static_cast<std::size_t>(slot) >= set.spec().exercises.size()) return std::nullopt;
  if (set.spec().exercises[static_cast<std::size_t>(slot)].kind != ex.kind) return std::nullopt;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    ExerciseInstance inst;
    try {
      inst = set.draw(sheet.sheet.index, slot, attempt, ex.branch);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (nlohmann::json::parse(inst.instance) != ex.instance) continue;
    return inst;
  }
  return std::nullopt;
}

std::optional<render::Figure> KeyDiagrams::figure(const SheetKey& sheet, std::size_t e) {
  auto inst = instance(sheet, e);
  if (!inst) return std::nullopt;
  for (auto& block : inst->key.blocks)
    if (auto* figure = std::get_if<render::Figure>(&block)) return std::move(*figure);
  return std::nullopt;
}

std::optional<ExerciseInstance> KeyDiagrams::instance(const SheetKey& sheet, std::size_t e) {
  if (!spec_) return std::nullopt;
  auto& sets = sets_[sheet.sheet.seed];
  if (sets.empty()) {
    try {
      SetOptions options;
      options.language = language_;
      sets.emplace_back(*spec_, sheet.sheet.seed, options);
      for (Difficulty d : {Difficulty::easy, Difficulty::standard, Difficulty::hard}) {
        options.difficulty = d;
        sets.emplace_back(*spec_, sheet.sheet.seed, options);
      }
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (preferred_ < sets.size())
    if (auto s = try_set(sets[preferred_], sheet, e)) return s;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (i == preferred_) continue;
    if (auto s = try_set(sets[i], sheet, e)) {
      preferred_ = i;
      return s;
    }
  }
  return std::nullopt;
}

}  // namespace epure::grading
