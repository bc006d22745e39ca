#pragma once
// A figure's fields as the solve contract reads them, whichever reader took them from the line
// (solve/line_reader.h): the values the checks need, and typed access that names the field at
// fault ("field 'r': expected a number, got a string"). A kind's solver reads its schema through
// Fields (exercises/kind_method.h), so the contract's field reads are the schema's.
#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string_view>

#include "geometry/decimal.h"
#include "geometry/vec.h"

namespace epure::solve {

// Bad input: the message names the field at fault ("field 'r': must be > 0").
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(std::string_view field, std::string_view why);

// The JSON types, as far as the contract's checks tell them apart.
enum class Type { null, boolean, number, string, array, object };
const char* type_name(Type t);

// One field's value, with what the checks need: a number, a string, or an array's size and its
// first elements (no figure has a longer array: a longer one is refused on its size alone). A
// number is the decimal its text writes (geometry/decimal.h; README, "What a number means"):
// every decision is exact for it.
struct Value {
  static constexpr std::size_t kItems = 3;
  Type type = Type::null;
  geo::Decimal number;
  std::string_view string;
  std::size_t size = 0;
  std::array<Type, kItems> item_types{};
  std::array<geo::Decimal, kItems> items{};
};

struct Field {
  std::string_view key;
  Value value;
};

// The figure's field named `key`, or null. A key given twice means its last value, as
// nlohmann::json reads it.
const Value* find(std::span<const Field> fields, std::string_view key);

// Reads the figure's fields, with an error that names the field for anything off.
class Fields {
 public:
  explicit Fields(std::span<const Field> figure) : figure_(figure) {}

  // Every field of the line, in its order.
  std::span<const Field> all() const { return figure_; }
  // The field, or null when the figure has none of that name.
  const Value* find(std::string_view name) const { return solve::find(figure_, name); }

  const Value& get(std::string_view name) const;
  double number(std::string_view name) const { return decimal(name).hi; }
  // The number as written: what the decisions are exact for.
  const geo::Decimal& decimal(std::string_view name) const;
  template <std::size_t N>
  std::array<double, N> numbers(std::string_view name) const {
    const auto d = decimals<N>(name);
    std::array<double, N> values{};
    for (std::size_t i = 0; i < N; ++i) values[i] = d[i].hi;
    return values;
  }
  template <std::size_t N>
  std::array<geo::Decimal, N> decimals(std::string_view name) const {
    static_assert(N <= Value::kItems);
    const Value& v = get(name);
    if (v.type != Type::array) fail(name, fmt::format("expected an array of {} numbers", N));
    if (v.size != N) fail(name, fmt::format("expected {} numbers, got {}", N, v.size));
    std::array<geo::Decimal, N> values{};
    for (std::size_t i = 0; i < N; ++i) values[i] = as_number(v.item_types[i], v.items[i], name, static_cast<int>(i));
    return values;
  }
  geo::DPoint2 dpoint2(std::string_view name) const { return decimals<2>(name); }
  geo::DPoint3 dpoint3(std::string_view name) const { return decimals<3>(name); }
  geo::Point2 point2(std::string_view name) const {
    auto v = numbers<2>(name);
    return {v[0], v[1]};
  }
  geo::Vec2 vec2(std::string_view name) const {
    auto v = numbers<2>(name);
    return {v[0], v[1]};
  }
  geo::Point3 point3(std::string_view name) const {
    auto v = numbers<3>(name);
    return {v[0], v[1], v[2]};
  }
  geo::Vec3 vec3(std::string_view name) const {
    auto v = numbers<3>(name);
    return {v[0], v[1], v[2]};
  }

 private:
  // index < 0: the field itself; else the array's element at that index
  static const geo::Decimal& as_number(Type type, const geo::Decimal& x, std::string_view name, int index);
  std::span<const Field> figure_;
};

}  // namespace epure::solve
