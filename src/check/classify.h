#pragma once
// Naming a classic bug: the models of bug_models.h are run on the cases the student's function
// answered, and a bug (or two together) is named when its answers are the student's:
//
//   - it explains at least 90 % of the student's wrong answers (the same decision, the same
//     point and normal within the case's tolerance), and at least one;
//   - its own wrong answers fall where the student's are (at most 5 % of them on cases the
//     student got right): a bug that fails where the student does not is not theirs.
//
// The single bugs are tried first, then pairs; the candidate that explains the most wins (ties:
// the course's order). Nothing is named when nothing fits.
#include <optional>
#include <vector>

#include "check/bug_models.h"
#include "check/functions.h"

namespace epure::check {

struct Classification {
  std::vector<Bug> bugs;   // empty: no bug named
  std::size_t explained = 0;  // wrong answers the bugs explain
};

// `cases` and `got` side by side (a case not answered: nothing); `right[i]` the judge's verdict.
Classification classify(Fn fn, const std::vector<Case>& cases, const std::vector<std::optional<Outcome>>& got,
                        const std::vector<bool>& right);

}  // namespace epure::check
