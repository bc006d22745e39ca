#include "solve/line_reader.h"

#include <charconv>
#include <new>
#include <cstdint>
#include <algorithm>
#include <optional>
#include <string>

#include "support/portable.h"

namespace epure::solve {

namespace {

using nlohmann::json;

Type type_of(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return Type::null;
    case json::value_t::boolean: return Type::boolean;
    case json::value_t::string: return Type::string;
    case json::value_t::array: return Type::array;
    case json::value_t::object: return Type::object;
    default: return Type::number;
  }
}

// A number of a parsed document, as written: its text when the line's was kept (NumberTexts
// below), else the shortest decimal that gives its double (an integer's own digits).
geo::Decimal number_of(const json& j, const std::string* text) {
  const double x = j.get<double>();
  if (text) return geo::read_decimal(*text, x);
  if (j.is_number_integer()) {
    // an integer nlohmann read exactly: its digits, not its double's (2^63 − 1 is not a double)
    char buffer[24];
    const auto end = j.is_number_unsigned() ? std::to_chars(buffer, buffer + sizeof buffer, j.get<std::uint64_t>()).ptr
                                            : std::to_chars(buffer, buffer + sizeof buffer, j.get<std::int64_t>()).ptr;
    const geo::Decimal d = geo::read_decimal({buffer, static_cast<std::size_t>(end - buffer)}, x);
    if (d.form != geo::Decimal::Form::long_decimal) return d;  // at most 19 digits: keeps no view
  }
  return geo::written(x);
}

Value value_of(const json& j, const NumberTexts::Texts* texts) {
  Value v;
  v.type = type_of(j);
  const auto text = [&](std::size_t i) -> const std::string* {
    return texts && i < texts->size() && !(*texts)[i].empty() ? &(*texts)[i] : nullptr;
  };
  if (v.type == Type::number) v.number = number_of(j, text(0));
  if (v.type == Type::string) v.string = j.get_ref<const std::string&>();
  if (v.type == Type::array) {
    v.size = j.size();
    for (std::size_t i = 0; i < std::min(v.size, Value::kItems); ++i) {
      v.item_types[i] = type_of(j[i]);
      if (v.item_types[i] == Type::number) v.items[i] = number_of(j[i], text(i));
    }
  }
  return v;
}

// A JSON number's significant digits, when at most 19 (they fit 64 bits), and the power of ten
// of the last: ±digits·10^power.
struct Digits {
  bool negative = false;
  std::uint64_t digits = 0;
  int count = 0;  // significant digits
  int power = 0;
};
std::optional<Digits> digits_of(const char* p, const char* end) {
  Digits d;
  d.negative = p != end && *p == '-';
  if (d.negative) ++p;
  std::uint64_t digits = 0;
  int count = 0, power = 0;
  for (; p != end && *p != 'e' && *p != 'E'; ++p) {
    if (*p == '.') {
      power = -1;  // from now on, each digit is one more decimal
      continue;
    }
    if (digits != 0 || *p != '0') ++count;  // leading zeros are not significant
    digits = 10 * digits + static_cast<std::uint64_t>(*p - '0');
    if (power < 0) --power;
  }
  if (count > 19) return std::nullopt;  // below 10^19 < 2^64
  if (power < 0) ++power;               // the '.' itself counted one
  if (p != end) {
    ++p;  // 'e'
    const bool minus = *p == '-';
    if (*p == '-' || *p == '+') ++p;
    if (end - p > 3) return std::nullopt;
    int exponent = 0;
    for (; p != end; ++p) exponent = 10 * exponent + (*p - '0');
    power += minus ? -exponent : exponent;
  }
  d.digits = digits;
  d.count = count;
  d.power = power;
  return d;
}

// A number of at most 15 significant digits and a power of ten within ±22, as a worksheet
// writes them ("-2.5", "0.125", "3e2"): digits·10^k is then one exact double times or over
// another, a single correctly rounded operation, so it is the double strtod gives (Clinger's
// fast path). Nothing for anything longer: from_chars reads it.
std::optional<double> short_decimal(const Digits& d) {
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (d.count > 15) return std::nullopt;  // below 10^15 < 2^53: exact as a double
  if (d.power < -22 || d.power > 22) return std::nullopt;
  const double x = static_cast<double>(d.digits);
  const double value = d.power < 0 ? x / kPowers[-d.power] : x * kPowers[d.power];
  return d.negative ? -value : value;
}

// Reads the shape of every well-formed solve line (one flat object whose values are numbers,
// plain strings or arrays of at most three numbers) straight from the text, allocating nothing:
// a DOM per line would cost more than the geometry. Anything else (escapes, non-ASCII, nesting,
// other values, numbers beyond a double, bad syntax) it declines, and nlohmann::json reads the
// line: it knows every case and words the errors. What it accepts, it reads to the same values.
class FlatReader {
 public:
  static constexpr std::size_t kMaxFields = LineReader::kMaxFlatFields;

  // `room` for kMaxFields fields, constructed as they are read.
  FlatReader(std::string_view line, unsigned char* room)
      : p_(line.data()), end_(line.data() + line.size()), fields_(reinterpret_cast<Field*>(room)), room_(room) {}

  // The fields in the order of the line, or nothing when the line is not of the flat shape.
  std::optional<std::span<const Field>> read() {
    if (!object()) return std::nullopt;
    return std::span<const Field>(std::launder(fields_), count_);
  }

 private:
  bool object() {
    space();
    if (!eat('{')) return false;
    space();
    if (!eat('}')) {
      do {
        if (count_ == kMaxFields) return false;
        Field& f = *new (room_ + sizeof(Field) * count_++) Field{};
        space();
        if (!string(f.key)) return false;
        space();
        if (!eat(':')) return false;
        space();
        if (!value(f.value)) return false;
        space();
      } while (eat(','));
      if (!eat('}')) return false;
    }
    space();
    return p_ == end_;
  }

  bool value(Value& v) {
    if (p_ != end_ && *p_ == '"') {
      v.type = Type::string;
      return string(v.string);
    }
    if (eat('[')) {
      v.type = Type::array;
      space();
      if (eat(']')) return true;
      do {
        if (v.size == Value::kItems) return false;
        space();
        v.item_types[v.size] = Type::number;
        if (!number(v.items[v.size])) return false;
        ++v.size;
        space();
      } while (eat(','));
      return eat(']');
    }
    v.type = Type::number;
    return number(v.number);
  }

  // Printable ASCII only: no escape to decode, no UTF-8 to validate.
  bool string(std::string_view& s) {
    if (!eat('"')) return false;
    const char* begin = p_;
    for (; p_ != end_ && *p_ != '"'; ++p_) {
      const auto c = static_cast<unsigned char>(*p_);
      if (c < 0x20 || c >= 0x80 || c == '\\') return false;
    }
    if (p_ == end_) return false;
    s = {begin, static_cast<std::size_t>(p_ - begin)};
    ++p_;
    return true;
  }

  // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?: the decimal it writes (geometry/decimal.h),
  // a view of the line's text, and its double correctly rounded as strtod rounds it.
  bool number(geo::Decimal& d) {
    const char* begin = p_;
    double x = 0;
    std::optional<Digits> digits;
    if (!number(x, digits)) return false;
    // the digits already read, or the text again (more than 19 digits)
    d = digits ? geo::decimal_of_digits(digits->negative, digits->digits, digits->power, x)
               : geo::read_decimal({begin, static_cast<std::size_t>(p_ - begin)}, x);
    return true;
  }
  bool number(double& x, std::optional<Digits>& split) {
    const char* begin = p_;
    bool integer = true;
    eat('-');
    if (!eat('0') && !digits()) return false;
    if (eat('.')) {
      integer = false;
      if (!digits()) return false;
    }
    if (eat('e') || eat('E')) {
      integer = false;
      if (!eat('+')) eat('-');
      if (!digits()) return false;
    }
    split = digits_of(begin, p_);
    if (auto exact = split ? short_decimal(*split) : std::nullopt) {
      x = *exact;
    } else {
      // Out of range (1e400, 1e-400): nlohmann's own wording and value.
      auto [end, error] = portable::parse_double(begin, p_, x);
      if (error != std::errc() || end != p_) return false;
    }
    // nlohmann reads "-0" as the integer 0, which is +0.0.
    if (integer && x == 0) x = 0;
    return true;
  }

  bool digits() {
    const char* begin = p_;
    while (p_ != end_ && *p_ >= '0' && *p_ <= '9') ++p_;
    return p_ != begin;
  }
  bool eat(char c) {
    if (p_ == end_ || *p_ != c) return false;
    ++p_;
    return true;
  }
  void space() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\n' || *p_ == '\r')) ++p_;
  }

  const char* p_;
  const char* end_;
  Field* fields_;
  unsigned char* room_;
  std::size_t count_ = 0;
};

// nlohmann says "[json.exception.parse_error.101] parse error at line 1, column 30: ...": the
// part after the id.
std::string_view without_id(std::string_view what) {
  if (auto close = what.find("] "); close != std::string_view::npos) what.remove_prefix(close + 2);
  return what;
}

}  // namespace

// nlohmann's SAX interface: depth 1 is the object's fields, depth 2 an array's items.
struct NumberTextsReader {
  using json = nlohmann::json;
  NumberTexts& out;
  int depth = 0;
  NumberTexts::Texts* current = nullptr;  // the texts of the field being read
  std::size_t item = 0;

  bool number(const std::string* text) {
    if (!current) return true;
    if (depth == 1 && text) (*current)[0] = *text;
    if (depth == 2) {
      if (item < Value::kItems && text) (*current)[item] = *text;
      ++item;
    }
    return true;
  }
  bool other() {
    if (depth == 2) ++item;
    return true;
  }
  bool null() { return other(); }
  bool boolean(bool) { return other(); }
  bool number_integer(json::number_integer_t) { return number(nullptr); }
  bool number_unsigned(json::number_unsigned_t) { return number(nullptr); }
  bool number_float(json::number_float_t, const json::string_t& text) { return number(&text); }
  bool string(json::string_t&) { return other(); }
  bool binary(json::binary_t&) { return other(); }
  bool start_object(std::size_t) {
    other();
    ++depth;
    return true;
  }
  bool key(json::string_t& k) {
    if (depth != 1) return true;
    auto it = std::find_if(out.keys_.begin(), out.keys_.end(), [&](const auto& e) { return e.first == k; });
    if (it == out.keys_.end()) it = out.keys_.insert(out.keys_.end(), {k, {}});
    it->second = {};  // a key given twice: its last value
    current = &it->second;
    return true;
  }
  bool end_object() {
    --depth;
    return true;
  }
  bool start_array(std::size_t) {
    other();
    if (++depth == 2) item = 0;
    return true;
  }
  bool end_array() {
    --depth;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const json::exception&) { return false; }
};

void NumberTexts::read(std::string_view line) {
  keys_.clear();
  NumberTextsReader reader{*this};
  json::sax_parse(line.begin(), line.end(), &reader);
}

const NumberTexts::Texts* NumberTexts::of(std::string_view key) const {
  for (const auto& [k, texts] : keys_)
    if (k == key) return &texts;
  return nullptr;
}

std::vector<Field> fields_of(const json& object, const NumberTexts* texts) {
  std::vector<Field> fields;
  for (auto it = object.begin(); it != object.end(); ++it)
    fields.push_back({it.key(), value_of(*it, texts ? texts->of(it.key()) : nullptr)});
  return fields;
}

LineReader::LineReader(std::string_view line) {
  if (line.size() > kMaxLineBytes)
    throw InputError(fmt::format("line: longer than {} bytes (1 MiB), the most a line may hold", kMaxLineBytes));
  FlatReader reader(line, flat_);
  if (auto fields = reader.read()) {
    fields_ = *fields;
    return;
  }
  const json::parser_callback_t shallow = [](int depth, json::parse_event_t event, json&) {
    if (depth >= kMaxDepth && (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
      throw InputError(fmt::format("line: nested deeper than {} levels", kMaxDepth));
    return true;
  };
  try {
    document_ = json::parse(line.begin(), line.end(), shallow);
  } catch (const json::parse_error& e) {
    throw InputError(fmt::format("line: not valid JSON ({})", without_id(e.what())));
  } catch (const json::out_of_range& e) {
    // a number past the doubles' range (1e400): not valid as a double either
    throw InputError(fmt::format("line: not valid JSON ({})", without_id(e.what())));
  }
  if (!document_.is_object()) throw InputError("line: expected a JSON object");
  // nlohmann keeps a number's double, not its text: a second reading keeps the texts (NumberTexts)
  texts_.read(line);
  from_json_ = fields_of(document_, &texts_);
  fields_ = from_json_;
}

}  // namespace epure::solve
