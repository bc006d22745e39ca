#pragma once
// Numbers as students type them: decimal point or comma ("2.17", "2,17"), a true minus sign,
// fractions ("3/4") and the exact forms the key prints ("5-sqrt(11)", "√11", "2*sqrt(3)/3",
// "(5 − 2√2)/3", "2√3"). A tiny recursive-descent parser: the grammar is five rules, and no
// packaged expression library reads √, a decimal comma and implicit products together.
//
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '×' | '·' | '/' | '÷') unary | implicit-factor)*
//   unary   := ('+' | '-') unary | power
//   power   := atom ('^' unary | '²')?
//   atom    := number | '(' sum ')' | ('sqrt' | '√' | 'racine') atom | 'pi' | 'π'
//
// A leading '≈', '~' or '=' is skipped (copied from the key's "≈ 2.17"), and so is a unit of
// degrees after the number ("50,91°", "−71,57 °", "50.91 deg", "50,91 degrés").
#include <string_view>

namespace epure::grading {

struct ParsedNumber {
  bool ok = false;
  double value = 0;
  std::string_view why;  // when not ok: "number", "division_by_zero", "negative_root"
};

// The fast path first (a plain decimal, from_chars), the parser only when that fails.
ParsedNumber parse_number(std::string_view text);

}  // namespace epure::grading
