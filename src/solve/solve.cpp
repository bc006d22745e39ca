#include "solve/solve.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/degenerate.h"
#include "geometry/projection.h"
#include "geometry/ray_3d.h"
#include "geometry/ray_circle.h"
#include "geometry/ray_square.h"
#include "geometry/ray_transformed.h"
#include "geometry/segments.h"
#include "geometry/vectors.h"
#include "solve/json_out.h"
#include "support/portable.h"

namespace epure::solve {

namespace {

using nlohmann::json;
namespace geo = epure::geo;

[[noreturn]] void fail(std::string_view field, std::string_view why) {
  throw InputError(fmt::format("field '{}': {}", field, why));
}

// ---- A figure's fields, whichever reader took them from the line ----------------------------

// The JSON types, as far as the contract's checks tell them apart.
enum class Type { null, boolean, number, string, array, object };

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

// One field's value, with what the checks need: a number, a string, or an array's size and its
// first elements (no figure has a longer array: a longer one is refused on its size alone).
struct Value {
  static constexpr std::size_t kItems = 3;
  Type type = Type::null;
  double number = 0;
  std::string_view string;
  std::size_t size = 0;
  std::array<Type, kItems> item_types{};
  std::array<double, kItems> items{};
};

struct Field {
  std::string_view key;
  Value value;
};

Value value_of(const json& j) {
  Value v;
  v.type = type_of(j);
  if (v.type == Type::number) v.number = j.get<double>();
  if (v.type == Type::string) v.string = j.get_ref<const std::string&>();
  if (v.type == Type::array) {
    v.size = j.size();
    for (std::size_t i = 0; i < std::min(v.size, Value::kItems); ++i) {
      v.item_types[i] = type_of(j[i]);
      if (v.item_types[i] == Type::number) v.items[i] = j[i].get<double>();
    }
  }
  return v;
}

// The fields of a parsed JSON object (its keys are unique: nlohmann::json keeps the last value
// of a key given twice).
std::vector<Field> fields_of(const json& object) {
  std::vector<Field> fields;
  for (auto it = object.begin(); it != object.end(); ++it) fields.push_back({it.key(), value_of(*it)});
  return fields;
}

// The figure's field named `key`, or null. A key given twice means its last value, as
// nlohmann::json reads it.
const Value* find(std::span<const Field> fields, std::string_view key) {
  for (auto it = fields.rbegin(); it != fields.rend(); ++it)
    if (it->key == key) return &it->value;
  return nullptr;
}

// ---- The flat reader ------------------------------------------------------------------------

// A JSON number of at most 15 significant digits and a power of ten within ±22, as a worksheet
// writes them ("-2.5", "0.125", "3e2"): digits·10^k is then one exact double times or over
// another, a single correctly rounded operation, so it is the double strtod gives (Clinger's
// fast path). Nothing for anything longer: from_chars reads it.
std::optional<double> short_decimal(const char* p, const char* end) {
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
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
  if (count > 15) return std::nullopt;  // below 10^15 < 2^53: exact as a double
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
  if (power < -22 || power > 22) return std::nullopt;
  const double x = static_cast<double>(digits);
  const double value = power < 0 ? x / kPowers[-power] : x * kPowers[power];
  return negative ? -value : value;
}

// Reads the shape of every well-formed solve line (one flat object whose values are numbers,
// plain strings or arrays of at most three numbers) straight from the text, allocating nothing:
// a DOM per line would cost more than the geometry. Anything else (escapes, non-ASCII, nesting,
// other values, numbers beyond a double, bad syntax) it declines, and nlohmann::json reads the
// line: it knows every case and words the errors. What it accepts, it reads to the same values.
class FlatReader {
 public:
  static constexpr std::size_t kMaxFields = 16;

  explicit FlatReader(std::string_view line) : p_(line.data()), end_(line.data() + line.size()) {}

  // The fields in the order of the line, or nothing when the line is not of the flat shape.
  std::optional<std::span<const Field>> read() {
    if (!object()) return std::nullopt;
    return std::span<const Field>(fields_.data(), count_);
  }

 private:
  bool object() {
    space();
    if (!eat('{')) return false;
    space();
    if (!eat('}')) {
      do {
        if (count_ == kMaxFields) return false;
        Field& f = fields_[count_++];
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

  // -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?, correctly rounded as strtod rounds it.
  bool number(double& x) {
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
    if (auto exact = short_decimal(begin, p_)) {
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
  std::array<Field, kMaxFields> fields_;
  std::size_t count_ = 0;
};

// ---- Solving --------------------------------------------------------------------------------

// Reads the figure's fields, with an error that names the field for anything off.
class Fields {
 public:
  Fields(std::span<const Field> figure, Semantics semantics) : figure_(figure), semantics_(semantics) {}

  bool exact() const { return semantics_ == Semantics::exact; }

  const Value& get(const char* name) const {
    const Value* v = find(figure_, name);
    if (!v) fail(name, "missing");
    return *v;
  }

  double number(const char* name) const {
    const Value& v = get(name);
    return as_number(v.type, v.number, name, -1);
  }

  template <std::size_t N>
  std::array<double, N> numbers(const char* name) const {
    static_assert(N <= Value::kItems);
    const Value& v = get(name);
    if (v.type != Type::array) fail(name, fmt::format("expected an array of {} numbers", N));
    if (v.size != N) fail(name, fmt::format("expected {} numbers, got {}", N, v.size));
    std::array<double, N> values{};
    for (std::size_t i = 0; i < N; ++i)
      values[i] = as_number(v.item_types[i], v.items[i], name, static_cast<int>(i));
    return values;
  }

  geo::Point2 point2(const char* name) const {
    auto v = numbers<2>(name);
    return {v[0], v[1]};
  }
  geo::Vec2 vec2(const char* name) const {
    auto v = numbers<2>(name);
    return {v[0], v[1]};
  }
  geo::Point3 point3(const char* name) const {
    auto v = numbers<3>(name);
    return {v[0], v[1], v[2]};
  }
  geo::Vec3 vec3(const char* name) const {
    auto v = numbers<3>(name);
    return {v[0], v[1], v[2]};
  }

 private:
  static double as_number(Type type, double x, const char* name, int index) {
    if (type != Type::number) {
      if (index < 0) fail(name, fmt::format("expected a number, got {}", type_name(type)));
      fail(name, fmt::format("expected numbers, got {} at index {}", type_name(type), index));
    }
    if (!std::isfinite(x)) fail(name, "not a finite number");
    return x;
  }
  std::span<const Field> figure_;
  Semantics semantics_;
};

// Every number of a result is checked before it is written: data near the limits of double
// (1e300 squared) overflows, and the text must never say inf or nan.
class Result {
 public:
  Result(fmt::memory_buffer& out, std::string_view kind) : start_(out.size()), out_(out), w_(out) {
    w_.begin_object().field("kind", kind);
  }
  Result& number(std::string_view k, double x) {
    check(x, k);
    w_.field(k, x);
    return *this;
  }
  Result& boolean(std::string_view k, bool b) {
    w_.field(k, b);
    return *this;
  }
  Result& string(std::string_view k, std::string_view s) {
    w_.field(k, s);
    return *this;
  }
  template <class P>
  Result& point(std::string_view k, const P& p) {
    w_.key(k).begin_array();
    for (double c : coordinates(p)) {
      check(c, k);
      w_.number(c);
    }
    w_.end_array();
    return *this;
  }
  template <int Dim>
  Result& faces(const geo::FaceSet<Dim>& set) {
    w_.key("faces").begin_array();
    set.for_each([&](geo::Face f) { w_.string(geo::face_name(f)); });
    w_.end_array();
    return *this;
  }
  template <class Hit>
  Result& hit(const std::optional<Hit>& h, double length = 1) {
    boolean("hit", h.has_value());
    if (h) number("t", h->t * length).point("I", h->I).point("N", h->N);
    return *this;
  }
  void end() { w_.end_object(); }

 private:
  static std::array<double, 2> coordinates(geo::Point2 p) { return {p.x, p.y}; }
  static std::array<double, 2> coordinates(geo::Vec2 v) { return {v.x, v.y}; }
  static std::array<double, 3> coordinates(geo::Point3 p) { return {p.x, p.y, p.z}; }
  static std::array<double, 3> coordinates(geo::Vec3 v) { return {v.x, v.y, v.z}; }
  void check(double x, std::string_view k) {
    if (!std::isfinite(x)) {
      out_.resize(start_);
      fail(k, "result overflows a double: the figure's coordinates are too large");
    }
  }
  std::size_t start_;
  fmt::memory_buffer& out_;
  JsonWriter w_;
};

void solve_vectors(const Fields& f, Result& r) {
  // in space when u has three components: u∧v is then a vector and the angle unsigned
  if (const Value& u = f.get("u"); u.type == Type::array && u.size == 3) {
    auto w = geo::compare_vectors_3d(f.vec3("u"), f.vec3("v"));
    r.number("dot", w.dot).point("cross", w.cross).number("norm_u", w.norm_u).number("norm_v", w.norm_v);
    r.number("cos", w.cos).number("sin", w.sin).number("angle_deg", w.angle_deg);
    r.boolean("collinear", w.collinear).boolean("orthogonal", w.orthogonal);
    return;
  }
  auto v = geo::compare_vectors(f.vec2("u"), f.vec2("v"));
  r.number("dot", v.dot).number("cross", v.cross).number("norm_u", v.norm_u).number("norm_v", v.norm_v);
  r.number("cos", v.cos).number("sin", v.sin).number("angle_deg", v.angle_deg);
}

void solve_projection(const Fields& f, Result& r) {
  // the fields read in the call itself, as before the exact kernel, so that a line missing two
  // of them names the same one
  auto p = f.exact() ? geo::project_exact(f.point2("A"), f.point2("B"), f.point2("C"))
                     : geo::project(f.point2("A"), f.point2("B"), f.point2("C"));
  r.number("t", p.t).point("P", p.P).string("position", geo::to_string(p.position));
}

void solve_segments(const Fields& f, Result& r) {
  auto s = f.exact() ? geo::intersect_segments_exact(f.point2("A"), f.point2("B"), f.point2("C"),
                                                    f.point2("D"))
                     : geo::intersect_segments(f.point2("A"), f.point2("B"), f.point2("C"),
                                               f.point2("D"));
  r.boolean("intersects", s.intersects());
  if (!s.intersects()) r.string("reason", geo::to_string(s.relation));
  if (s.t_ab) r.number("t_ab", *s.t_ab).number("t_cd", *s.t_cd);
  if (s.I) r.point("I", *s.I);
}

// The ray as given, its direction only rescaled by a power of two (exact). Normalising it would
// turn it by up to ε around A, which a figure 1e8 away sees as a shift of 1e-8, and an exact
// tangent as a near one. The core's t is then in units of that direction: times its length
// gives the distance the contract asks for.
template <class Ray, class Point, class Vec>
std::pair<Ray, double> raw_ray(Point A, Vec u) {
  const Vec direction = geo::rescaled(u);
  return {Ray{A, direction}, geo::norm(direction)};
}

// The same values for the keys and for `epure solve`, whichever kernel decided (geometry's
// printed_values: within 4 ulps of the figure's scale).
template <class Round, class Ray, class Ball>
void write_round(const Round& c, const Ray& ray, const Ball& ball, Result& r, double length) {
  const auto printed = geo::printed_values(ray, ball, c, length);
  r.number("t_proj", printed.t_proj).number("d2", c.d2).boolean("inside", c.inside);
  r.boolean("hit", c.hit.has_value());
  if (c.hit) r.number("t", printed.t).point("I", printed.I).point("N", printed.N);
  if (c.reason) r.string("reason", geo::to_string(*c.reason));
}

void solve_ray_circle(const Fields& f, Result& r) {
  // Read every field before solving, so that a missing one is reported before a degenerate one.
  auto A = f.point2("A");
  auto u = f.vec2("u");
  auto C = f.point2("C");
  double radius = f.number("r");
  const auto [ray, length] = raw_ray<geo::Ray2>(A, u);
  const geo::Circle circle{C, radius};
  write_round(f.exact() ? geo::intersect_exact(ray, circle) : geo::intersect(ray, circle), ray, circle, r,
              length);
}

void solve_ray_square(const Fields& f, Result& r) {
  auto A = f.point2("A");
  auto u = f.vec2("u");
  const auto [ray, length] = raw_ray<geo::Ray2>(A, u);
  auto s = f.exact() ? geo::intersect_canonical_square_exact(ray) : geo::intersect_canonical_square(ray);
  r.faces(s.faces).boolean("inside", s.inside).hit(s.hit, length);
}

void solve_ray_ellipse(const Fields& f, Result& r) {
  auto A = f.point2("A");
  auto u = f.vec2("u");
  auto C = f.point2("C");
  auto radii = f.numbers<2>("radii");
  double angle = f.number("angle");
  const auto [ray, length] = raw_ray<geo::Ray2>(A, u);
  const geo::Ellipse ellipse{C, radii[0], radii[1], angle};
  auto e = f.exact() ? geo::intersect_exact(ray, ellipse) : geo::intersect(ray, ellipse);
  r.boolean("inside", e.inside).hit(e.hit, length);
}

void solve_ray_rectangle(const Fields& f, Result& r) {
  auto A = f.point2("A");
  auto u = f.vec2("u");
  auto C = f.point2("C");
  auto half = f.numbers<2>("half");
  double angle = f.number("angle");
  const auto [ray, length] = raw_ray<geo::Ray2>(A, u);
  const geo::Rectangle rectangle{C, half[0], half[1], angle};
  auto e = f.exact() ? geo::intersect_exact(ray, rectangle) : geo::intersect(ray, rectangle);
  r.boolean("inside", e.inside).hit(e.hit, length);
}

void solve_ray_sphere(const Fields& f, Result& r) {
  auto A = f.point3("A");
  auto u = f.vec3("u");
  auto C = f.point3("C");
  double radius = f.number("r");
  const auto [ray, length] = raw_ray<geo::Ray3>(A, u);
  const geo::Sphere sphere{C, radius};
  write_round(f.exact() ? geo::intersect_exact(ray, sphere) : geo::intersect(ray, sphere), ray, sphere, r,
              length);
}

void solve_ray_cube(const Fields& f, Result& r) {
  auto A = f.point3("A");
  auto u = f.vec3("u");
  const auto [ray, length] = raw_ray<geo::Ray3>(A, u);
  auto c = f.exact() ? geo::intersect_canonical_cube_exact(ray) : geo::intersect_canonical_cube(ray);
  r.faces(c.faces).boolean("inside", c.inside).hit(c.hit, length);
}

using Solver = void (*)(const Fields&, Result&);

Solver solver_for(std::string_view kind) {
  static constexpr std::pair<std::string_view, Solver> table[] = {
      {"vectors", solve_vectors},         {"projection", solve_projection},
      {"segments", solve_segments},       {"ray_circle", solve_ray_circle},
      {"ray_square", solve_ray_square},   {"ray_ellipse", solve_ray_ellipse},
      {"ray_rectangle", solve_ray_rectangle}, {"ray_sphere", solve_ray_sphere},
      {"ray_cube", solve_ray_cube},
  };
  for (const auto& [name, solver] : table)
    if (name == kind) return solver;
  return nullptr;
}

void solve(std::span<const Field> figure, fmt::memory_buffer& out, Semantics semantics) {
  Fields fields(figure, semantics);
  const Value& kind = fields.get("kind");
  if (kind.type != Type::string)
    fail("kind", fmt::format("expected a string, got {}", type_name(kind.type)));
  const std::string_view name = kind.string;
  Solver solver = solver_for(name);
  if (!solver) fail("kind", fmt::format("unknown kind '{}'", name));

  const std::size_t start = out.size();
  try {
    Result result(out, name);
    solver(fields, result);
    result.end();
  } catch (const geo::DegenerateFigure& e) {
    out.resize(start);
    fail(e.field(), e.what());
  } catch (...) {
    out.resize(start);
    throw;
  }
}

}  // namespace

void solve_figure(const json& figure, fmt::memory_buffer& out, Semantics semantics) {
  if (!figure.is_object()) throw InputError("line: expected a JSON object");
  // Views into `figure`, which outlives them.
  solve(fields_of(figure), out, semantics);
}

std::string solve_line(std::string_view line, fmt::memory_buffer& out) {
  return solve_line(line, out, Semantics::worksheet);
}

std::string solve_line(std::string_view line, fmt::memory_buffer& out, Semantics semantics) {
  std::string message;
  const std::size_t start = out.size();
  try {
    if (line.size() > kMaxLineBytes)
      throw InputError(fmt::format("line: longer than {} bytes (1 MiB), the most a line may hold", kMaxLineBytes));
    FlatReader reader(line);
    if (auto fields = reader.read()) {
      solve(*fields, out, semantics);
    } else {
      const json::parser_callback_t shallow = [](int depth, json::parse_event_t event, json&) {
        if (depth >= kMaxDepth && (event == json::parse_event_t::object_start || event == json::parse_event_t::array_start))
          throw InputError(fmt::format("line: nested deeper than {} levels", kMaxDepth));
        return true;
      };
      json figure = json::parse(line.begin(), line.end(), shallow);
      solve_figure(figure, out, semantics);
    }
    return {};
  } catch (const json::parse_error& e) {
    // nlohmann says "[json.exception.parse_error.101] parse error at line 1, column 30: ...":
    // keep the part after the id.
    std::string_view what = e.what();
    if (auto close = what.find("] "); close != std::string_view::npos) what.remove_prefix(close + 2);
    message = fmt::format("line: not valid JSON ({})", what);
  } catch (const json::out_of_range& e) {
    // a number past the doubles' range (1e400): not valid as a double either
    std::string_view what = e.what();
    if (auto close = what.find("] "); close != std::string_view::npos) what.remove_prefix(close + 2);
    message = fmt::format("line: not valid JSON ({})", what);
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = fmt::format("line: {}", e.what());
  }
  out.resize(start);
  JsonWriter(out).begin_object().field("error", std::string_view(message)).end_object();
  return message;
}

}  // namespace epure::solve
