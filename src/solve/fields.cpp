#include "solve/fields.h"

#include <cmath>

namespace epure::solve {

void fail(std::string_view field, std::string_view why) {
  throw InputError(fmt::format("field '{}': {}", field, why));
}

const char* type_name(Type t) {
  switch (t) {
    case Type::null: return "null";
    case Type::boolean: return "a boolean";
    case Type::string: return "a string";
    case Type::array: return "an array";
    case Type::object: return "an object";
    default: return "a number";
  }
}

const Value* find(std::span<const Field> fields, std::string_view key) {
  for (auto it = fields.rbegin(); it != fields.rend(); ++it)
    if (it->key == key) return &it->value;
  return nullptr;
}

const Value& Fields::get(std::string_view name) const {
  const Value* v = find(name);
  if (!v) fail(name, "missing");
  return *v;
}

const geo::Decimal& Fields::decimal(std::string_view name) const {
  const Value& v = get(name);
  return as_number(v.type, v.number, name, -1);
}

const geo::Decimal& Fields::as_number(Type type, const geo::Decimal& x, std::string_view name, int index) {
  if (type != Type::number) {
    if (index < 0) fail(name, fmt::format("expected a number, got {}", type_name(type)));
    fail(name, fmt::format("expected numbers, got {} at index {}", type_name(type), index));
  }
  if (!std::isfinite(x.hi)) fail(name, "not a finite number");
  if (x.form == geo::Decimal::Form::beyond)
    fail(name, fmt::format("more than {} significant digits, or a digit below 1e{}: beyond exact decisions",
                           geo::Decimal::kMaxDigits, geo::Decimal::kMinExponent));
  return x;
}

}  // namespace epure::solve
