#pragma once
// The second look at an exercise with wrong answers, as a careful teacher gives it: a kind's
// grader (kind_grader.h) walks its method in order and, for each wrong answer, asks whether it
// is what the student's own earlier answers give (follow-through credit) or what a classic
// mistake gives (a named mistake). Only answers marked wrong are ever changed.
//
// A wrong answer "is" a value when it lies within kMatchFactor times the key's tolerance of it:
// the student's earlier values are rounded, and so is everything they computed from them.
#include <optional>
#include <span>
#include <string_view>

#include "exercises/numbers.h"
#include "geometry/vec.h"
#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

// Twice the key's tolerance: a later answer computed from a rounded wrong value carries that
// rounding on top of its own, which the key's tolerance (derived for the right values) covers
// about once more.
inline constexpr double kMatchFactor = 2.0;

// Whether `given` is within `factor` times the question's tolerance of `target`.
bool within(const QuestionKey& q, double given, double target, double factor = 1.0);

class ExerciseReview {
 public:
  ExerciseReview(const ExerciseKey& key, std::span<QuestionMark> marks, bool follow_through,
                 NumberStyle numbers, int decimals);

  const ExerciseKey& key() const { return key_; }
  int decimals() const { return decimals_; }
  bool follow_through() const { return follow_through_; }

  // ---- what the student answered (readable answers only)
  bool asked(std::string_view field) const { return key_.find(field) >= 0; }
  std::optional<double> number(std::string_view field) const;
  std::optional<geo::Point2> point(std::string_view group) const;  // both coordinates
  std::optional<bool> boolean(std::string_view field) const;
  std::optional<FaceBits> faces(std::string_view field) const;
  std::optional<std::string_view> word(std::string_view field) const;
  // Marked right (by the key or by follow-through).
  bool right(std::string_view field) const;
  bool right_point(std::string_view group) const { return right_coordinates(group, 2); }
  // Wrong and not yet explained: what the calls below may still act on.
  bool open(std::string_view field) const;

  // ---- follow-through: `from` lists the earlier fields the value was computed from, by
  // space ("t_proj d2"); credit needs at least one of them answered wrong, so that a sloppy
  // answer next to right earlier ones is never excused.
  bool follow(std::string_view field, double value, std::string_view from,
              std::string_view mistake = {});
  // A point (in the plane "I" with I.x and I.y; in space "I" with I.x, I.y and I.z), as a whole
  // when its key marks it by distance, else coordinate by coordinate.
  bool follow_point(std::string_view group, std::span<const double> value, std::string_view from,
                    std::string_view mistake = {});
  bool follow_point(std::string_view group, geo::Point2 value, std::string_view from, std::string_view mistake = {}) {
    const double xy[2] = {value.x, value.y};
    return follow_point(group, xy, from, mistake);
  }
  bool follow_boolean(std::string_view field, bool value, std::string_view from,
                      std::string_view mistake = {});
  bool follow_word(std::string_view field, std::string_view word, std::string_view from,
                   std::string_view mistake = {});
  bool follow_faces(std::string_view field, FaceBits value, std::string_view from, std::string_view mistake = {});

  // ---- named mistakes: the wrong answer is what `value` gives.
  bool mistake(std::string_view field, double value, std::string_view code);
  // Named on the whole point: every coordinate fits the mistake, the right ones included.
  bool mistake_point(std::string_view group, std::span<const double> value, std::string_view code);
  bool mistake_point(std::string_view group, geo::Point2 value, std::string_view code) {
    const double xy[2] = {value.x, value.y};
    return mistake_point(group, xy, code);
  }
  // Whether what the student gave for the point fits `value` (coordinates left blank fit).
  bool fits_point(std::string_view group, std::span<const double> value) const;
  // Whether what the student gave for `field` fits `value`, or was left blank or unreadable.
  bool fits(std::string_view field, double value) const;
  bool mistake_faces(std::string_view field, FaceBits value, std::string_view code);
  bool mistake_word(std::string_view field, std::string_view word, std::string_view code);

 private:
  bool open_at(int i) const;
  // The questions of a point's coordinates, in axis order; false when one is not asked.
  bool coordinates_of(std::string_view group, std::size_t count, int* at) const;
  const QuestionMark* readable_at(int i, AnswerType type) const;
  QuestionMark* mark(std::string_view field);
  const QuestionMark* mark(std::string_view field) const;
  bool right_coordinates(std::string_view group, int count) const;
  bool some_wrong(std::string_view from) const;
  std::string describe(std::string_view from) const;
  void credit(int index, std::string_view from, std::string_view mistake, double value);

  const ExerciseKey& key_;
  std::span<QuestionMark> marks_;
  bool follow_through_;
  NumberStyle numbers_;
  int decimals_;
};

}  // namespace epure::grading
