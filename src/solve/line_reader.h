#pragma once
// Reading one line of `epure solve` into its fields (solve/fields.h): the line's text is read
// flat, allocating nothing, when it has the shape of every well-formed solve line (one flat
// object of numbers, plain strings and short arrays of numbers); anything else goes through
// nlohmann::json, which knows every case and words the errors. Either way the fields hold the
// same values. The number reading (how a decimal becomes a double) lives here and only here.
#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <type_traits>
#include <string_view>
#include <vector>

#include "solve/fields.h"

namespace epure::solve {

// Limits on a line (README, "Limits"): a figure is a few hundred bytes and two levels deep.
inline constexpr std::size_t kMaxLineBytes = std::size_t(1) << 20;  // 1 MiB
inline constexpr int kMaxDepth = 32;

// The texts of the numbers of a line's top-level fields (a number, or an array's first
// numbers), which a parsed document has lost: nlohmann::json keeps a number's double. Read by
// nlohmann's SAX parser, which hands over each float's text; a key given twice keeps its last.
class NumberTexts {
 public:
  using Texts = std::array<std::string, Value::kItems>;  // "" where no float was written
  // Reads a line nlohmann::json has already parsed (nothing is reported: it is valid).
  void read(std::string_view line);
  const Texts* of(std::string_view key) const;

 private:
  std::vector<std::pair<std::string, Texts>> keys_;
  friend struct NumberTextsReader;
};

// The fields of a parsed JSON object (its keys are unique: nlohmann::json keeps the last value
// of a key given twice), each number as its text in `texts` writes it, else as the shortest
// decimal of its double. Views into `object` and `texts`, which must outlive them.
std::vector<Field> fields_of(const nlohmann::json& object, const NumberTexts* texts = nullptr);

// One line read. Throws InputError for a line that is not one JSON object within the limits:
// "line: not valid JSON (…)", "line: expected a JSON object", "line: nested deeper than …".
class LineReader {
 public:
  static constexpr std::size_t kMaxFlatFields = 16;

  explicit LineReader(std::string_view line);
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  // The figure's fields, in the order of the line; views into the line (or the parsed
  // document), valid while both live.
  std::span<const Field> fields() const { return fields_; }

 private:
  // Room for the flat reading's fields, each constructed as it is read: a Field holds four
  // decimals (geometry/decimal.h), and constructing sixteen per line cost a tenth of the time.
  static_assert(std::is_trivially_destructible_v<Field>);
  alignas(Field) unsigned char flat_[sizeof(Field) * kMaxFlatFields];
  nlohmann::json document_;        // only for a line the flat reading declined
  NumberTexts texts_;              // its numbers' texts
  std::vector<Field> from_json_;
  std::span<const Field> fields_;
};

}  // namespace epure::solve
