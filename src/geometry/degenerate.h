#pragma once
// A figure that has no meaning (a segment of zero length, a circle of radius ≤ 0, a zero
// direction) is not a branch of the result: it is refused before any computation, with the name
// of the datum at fault, as the course names it (A, B, u, r, …).
#include <stdexcept>
#include <string>

namespace epure::geo {

class DegenerateFigure : public std::invalid_argument {
 public:
  DegenerateFigure(std::string field, const std::string& why)
      : std::invalid_argument(why), field_(std::move(field)) {}
  // The datum at fault, as named in the course and in the solve contract.
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

}  // namespace epure::geo
