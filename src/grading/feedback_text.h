#pragma once
// The sentences a student reads about each answer, from templates/text/<lang>/grading.toml:
// the expected answer as the key prints it, what they gave, and why it is right or wrong (the
// named mistake, the follow-through it earned). Written only when an output asks for them.
#include <string>
#include <string_view>

#include "exercises/numbers.h"
#include "exercises/texts.h"
#include "grading/answer_key.h"
#include "grading/marks.h"

namespace epure::grading {

class FeedbackText {
 public:
  // Throws std::invalid_argument for a language without texts.
  FeedbackText(std::string_view language, int decimals);

  const Texts& texts() const { return texts_; }
  const NumberStyle& numbers() const { return numbers_; }

  // The key's answer: "0.26 (= 16/61)", "yes", "between A and B", "+x, −y", "none".
  std::string expected(const QuestionKey& q) const;
  // The student's answer as written, or an empty string when not answered.
  std::string given(const QuestionMark& m) const { return std::string(m.given.raw); }
  // The student's answer in the sheet's words: a yes/no, a choice or a set of sides as the
  // sheet prints it ("outside" typed on a French sheet reads "à l’extérieur"); a number, or an
  // answer that could not be read, as written.
  std::string given_shown(const QuestionKey& q, const QuestionMark& m) const;
  // The verdict's word in the language ("right", "juste", …).
  const std::string& verdict(Verdict v) const;
  // Why, as a sentence that stands alone (expected and given included): empty for a right
  // answer typed as asked (one read from the neighbouring cell, or corrected, says so). Plain text (plain_text below), for JSON and terminals: no label markup.
  std::string sentence(const QuestionKey& q, const QuestionMark& m) const;
  // Why, for a page that already shows the answer and the expected one beside it: the named
  // mistake, the follow-through, why a cell was unreadable; empty when there is nothing more.
  // RichText, with the templates' label markup, for the SVG feedback sheets.
  std::string explanation(const QuestionKey& q, const QuestionMark& m) const;
  // A number as the language writes it, to the key's decimals ("2,17").
  std::string number(double x) const { return numbers_.rounded(x, decimals_); }
  // Points without trailing zeros ("1", "0.5", "0,5").
  std::string points(double x) const;

 private:
  std::string compose(const QuestionKey& q, const QuestionMark& m, bool whole, bool plain) const;

  const Texts& texts_;
  NumberStyle numbers_;
  int decimals_;
};

// A machine exact form for people: "(5-2*sqrt(2))/3" → "(5 − 2√2)/3".
std::string pretty_exact(std::string_view machine);

// The label markup of the templates (render/scene.h: t_{ab}, r^{2}, \vec{AB}, and the escapes
// \{ \} \\) as plain text, for readers that do not draw it (JSON, CSV, a terminal):
//   a subscript     x_{u} → x_u,  t_{proj} → t_proj (letters and digits, as the question ids
//                   spell them: 2.t_proj), A_{1 2} → A_(1 2) (anything else, in parentheses);
//   a superscript   r^{2} → r², S^{−1} → S⁻¹, (M^{−1})^{T} → (M⁻¹)ᵀ when every character has a
//                   Unicode superscript (digits, + − = ( ) n i T), else r^{ab} → r^(ab);
//   a vector        \vec{AB} → vec(AB) (an arrow over letters has no plain form that every
//                   font and terminal shows);
//   an escape       \{ → {.
// Unbalanced markup is kept as written, as the renderer draws it.
std::string plain_text(std::string_view rich);

// Text put into RichText as itself (a student's answer): { } and \ escaped.
std::string rich_escape(std::string_view text);

}  // namespace epure::grading
