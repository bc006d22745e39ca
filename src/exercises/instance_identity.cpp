#include "exercises/instance_identity.h"

#include <fmt/format.h>

#include <iterator>
#include <stdexcept>

#include "solve/json_out.h"
#include "solve/solve.h"

namespace epure::kinds {

namespace {

std::string number_text(double x) {
  if (x == 0) x = 0;  // one spelling for ±0
  return fmt::format("{}", x);
}

}  // namespace

InstanceWriter::InstanceWriter(std::string_view kind) {
  fmt::memory_buffer buf;
  JsonWriter(buf).begin_object().field("kind", kind);
  text_.assign(buf.data(), buf.size());  // "{"kind":"…"" — closed by finish()
}

InstanceWriter& InstanceWriter::number(std::string_view field, double x) {
  text_ += fmt::format(",\"{}\":{}", field, number_text(x));
  return *this;
}
InstanceWriter& InstanceWriter::pair(std::string_view field, double a, double b) {
  fmt::format_to(std::back_inserter(text_), ",\"{}\":[{},{}]", field, number_text(a), number_text(b));
  return *this;
}
InstanceWriter& InstanceWriter::triple(std::string_view field, double a, double b, double c) {
  fmt::format_to(std::back_inserter(text_), ",\"{}\":[{},{},{}]", field, number_text(a), number_text(b), number_text(c));
  return *this;
}
InstanceWriter& InstanceWriter::point(std::string_view field, geo::Point2 p) { return pair(field, p.x, p.y); }
InstanceWriter& InstanceWriter::vec(std::string_view field, geo::Vec2 v) { return pair(field, v.x, v.y); }
std::string InstanceWriter::finish() { return text_ + "}"; }

std::string solve_instance(std::string_view instance) {
  fmt::memory_buffer out;
  std::string error = solve::solve_line(instance, out);
  if (!error.empty())
    throw std::logic_error(fmt::format("generated instance refused by solve: {} ({})", error, instance));
  return std::string(out.data(), out.size());
}

std::string number_of(const ExerciseContext& ctx) { return ctx.number.empty() ? std::to_string(ctx.n) : ctx.number; }

std::optional<ExerciseInstance> already_taken(const ExerciseContext& ctx, std::string instance) {
  const std::uint64_t f = fingerprint(instance);
  if (!ctx.taken || !ctx.taken->contains(f)) return std::nullopt;
  ExerciseInstance inst;
  inst.n = ctx.n;
  inst.number = number_of(ctx);
  inst.branch = ctx.branch;
  inst.instance = std::move(instance);
  inst.fingerprint = f;
  return inst;
}

std::uint64_t fingerprint(std::string_view text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace epure::kinds
