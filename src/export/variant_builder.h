#pragma once
// One sheet's exercise as a platform's question (export_set.h: Variant): its statement, images
// and answer fields as the sheet prints them, each part with the key's value and rule, and the
// named mistakes' values from the kind's one method run with each mistake switched on.
#include "export/export_set.h"
#include "grading/answer_key.h"
#include "grading/feedback_text.h"

namespace epure::exporting {

class VariantBuilder {
 public:
  VariantBuilder(const grading::FeedbackText& feedback, int decimals, ImageFormat images)
      : feedback_(feedback), decimals_(decimals), images_(images) {}

  Variant build(const grading::SheetKey& sheet, const grading::ExerciseKey& ex, const ExerciseInstance& inst,
                const std::string& title) const;

 private:
  struct Runs;
  Runs evaluate(const ExerciseKind* kind, const grading::ExerciseKey& ex) const;
  std::string sentence(const grading::QuestionKey& q, std::string_view code, double value) const;
  // A field the sheet prints and this case does not ask (its id starts with `number`, the
  // exercise's number in the key).
  Part not_asked(const ExerciseKind* kind, const render::AnswerField& field, const std::string& id,
                 const std::string& number) const;
  std::vector<Option> yes_no() const;
  std::vector<Option> choice_options(const ExerciseKind* kind, std::string_view field) const;
  std::vector<Option> side_options(const ExerciseKind* kind, std::string_view field) const;
  std::string wording(std::string_view word) const;
  Part part(const ExerciseKind* kind, const grading::QuestionKey& q, const Runs& runs) const;
  Image image(const render::Scene& scene, const std::string& stem) const;

  const grading::FeedbackText& feedback_;
  int decimals_;
  ImageFormat images_;
};

}  // namespace epure::exporting
