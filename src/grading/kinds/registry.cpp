#include "grading/kinds/registry.h"
#include "grading/method_grader.h"

namespace epure::grading {

std::vector<const KindGrader*> all_graders() {
  std::vector<const KindGrader*> out;
  for (const auto* k : all_kinds())
    if (const auto* g = method_grader(*k)) out.push_back(g);
  return out;
}

const KindGrader* find_grader(std::string_view kind) {
  if (const auto* k = find_kind(kind)) return method_grader(*k);
  return nullptr;
}

}  // namespace epure::grading
