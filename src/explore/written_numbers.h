#pragma once
// The numbers of an instance as they were written. The explorer's core reads an instance into a
// kind's data, which are doubles, and writes it back (the view's canonical instance, a drag's
// result) from those doubles: a number written with more digits than its double holds
// (0.1000000000000000055511151231257827, a coordinate of 20 significant digits) would come back
// shortened, and `epure solve`, which decides on the decimals written (README, "What a number
// means"), would then be handed another figure. These functions carry the written text along.
#include <string>
#include <string_view>

namespace epure::explore {

// `canonical` (a flat JSON object: the core's writing of an instance) with each number that has
// the same double as the number written at the same place in `written` (the same field, the same
// array item) given as `written` writes it; the other numbers, the fields' order and the rest of
// the text as `canonical` has them. `canonical` is returned as it is when `written` is not a JSON
// object. The numbers' texts are read by the reader `epure solve` uses (solve::NumberTexts).
std::string with_written_numbers(std::string_view canonical, std::string_view written);

}  // namespace epure::explore
