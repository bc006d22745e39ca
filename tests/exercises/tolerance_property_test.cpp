// The tolerances, held to what the sheet tells a student (method.h: write each answer to 2
// decimals, carry on with 4 significant digits), over every kind, branch and difficulty and many
// seeds:
// - a student who works exactly as told is always accepted;
// - for |value| ≥ 0.1, no tolerance exceeds 5 % of the value, once the answer's own rounding to
//   2 decimals (δ = 0.005, itself 5 % of 0.1) is set aside, and the whole tolerance stays within
//   5 % for |value| ≥ 0.2;
// - the classic slips are always refused: a sign, two coordinates swapped, and every named
//   mistake of the kind (a forgotten square root, û not normalised, …) wherever it moves an
//   answer by more than 5 % of it and by more than two hundredths.
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/kind_support.h"
#include "exercises/method.h"
#include "exercises/texts.h"
#include "support/drawn_instances.h"

using namespace epure;

namespace {

constexpr int kSeeds = 40;
constexpr int kDecimals = 2;
constexpr double kOwnRounding = 0.005;  // ½·10^−2

double round_to(double x, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

// The grading rule of an isclose question (grading/marking.cpp), written again.
bool accepts(const Question& q, double given) {
  const double expected = std::get<double>(q.expected);
  return std::abs(given - expected) <= std::max(q.tolerance.rel * std::abs(expected), q.tolerance.abs);
}

const Question* find(const ExerciseInstance& inst, const std::string& field) {
  for (const auto& q : inst.questions)
    if (q.field == field) return &q;
  return nullptr;
}

// A run's numeric answers by question field ("I" gives "I.x" and "I.y").
std::map<std::string, double> numbers_of(const std::vector<method::Recorded<method::Traced>>& run) {
  std::map<std::string, double> out;
  for (const auto& a : run) {
    if (a.type == method::AnswerType::number) out[std::string(a.id)] = a.x.v;
    if (a.type == method::AnswerType::point) {
      out[std::string(std::string_view(method::coordinate_name(a.id, 'x')))] = a.x.v;
      out[std::string(std::string_view(method::coordinate_name(a.id, 'y')))] = a.y.v;
    }
  }
  return out;
}

struct Worst {
  double ratio = 0;
  std::string where;
  void see(double r, const std::string& w) {
    if (r > ratio) ratio = r, where = w;
  }
};

}  // namespace

TEST_CASE("tolerances: a student who works as told is accepted, within 5 %, slips refused") {
  long answers = 0, as_told = 0, slips = 0, large = 0, over_5 = 0;
  Worst carried, whole;
  for (const ExerciseKind* kind : all_kinds()) {
    if (kind->questions().empty()) continue;
    CAPTURE(kind->name());
    test::for_each_drawn(*kind, kSeeds, kDecimals, 104729u, 17, [&](const std::string& branch, Difficulty level, int seed,
                                                                      const ExerciseInstance& inst) {
          CAPTURE(inst.instance);
          const auto data = kind->read_instance(nlohmann::json::parse(inst.instance));

          // as told: every answer it reaches is accepted, written to 2 decimals
          for (const auto& [field, value] : numbers_of(kind->evaluate_as_told(data, kDecimals))) {
            const Question* q = find(inst, field);
            if (!q || !std::holds_alternative<double>(q->expected)) continue;
            CAPTURE(field);
            CAPTURE(value);
            CHECK(accepts(*q, round_to(value, kDecimals)));
            ++as_told;
          }

          for (const auto& q : inst.questions) {
            if (!std::holds_alternative<double>(q.expected)) continue;
            REQUIRE(q.tolerance.kind == ToleranceRule::Kind::isclose);
            const double v = std::get<double>(q.expected);
            ++answers;
            if (std::abs(v) < 0.1) continue;
            ++large;
            CAPTURE(q.field);
            CAPTURE(v);
            CAPTURE(q.tolerance.abs);
            const std::string where = fmt::format("{} {} {} seed {}: {} = {}", kind->name(), branch,
                                                  static_cast<int>(level), seed, q.field, v);
            const double beyond_own = (q.tolerance.abs - kOwnRounding) / std::abs(v);
            carried.see(beyond_own, where);
            whole.see(q.tolerance.abs / std::abs(v), where);
            if (q.tolerance.abs > 0.05 * std::abs(v)) ++over_5;
            CHECK(beyond_own <= 0.05);
            if (std::abs(v) >= 0.2) CHECK(q.tolerance.abs <= 0.05 * std::abs(v));
            // a sign slip
            CHECK_FALSE(accepts(q, -v));
            ++slips;
          }

          // two coordinates swapped
          for (const auto& q : inst.questions) {
            if (q.point_group.empty() || !q.field.ends_with(".x")) continue;
            const Question* qy = find(inst, q.point_group + ".y");
            if (!qy) continue;
            const double x = std::get<double>(q.expected), y = std::get<double>(qy->expected);
            if (std::abs(x - y) < 0.05 * std::max({std::abs(x), std::abs(y), 0.1})) continue;
            CAPTURE(q.field);
            CHECK_FALSE((accepts(q, y) && accepts(*qy, x)));
            ++slips;
          }

          // every named mistake, where it moves an answer by more than 5 % of it
          for (auto code : kind->mistakes()) {
            CAPTURE(code);
            for (const auto& [field, wrong] : numbers_of(kind->evaluate(data, nullptr, code, kDecimals))) {
              const Question* q = find(inst, field);
              if (!q || !std::holds_alternative<double>(q->expected)) continue;
              const double v = std::get<double>(q->expected);
              // (a value written to 2 decimals cannot tell apart what differs by a few hundredths)
              if (std::abs(wrong - v) <= std::max(0.05 * std::abs(v), 4 * kOwnRounding)) continue;
              CAPTURE(field);
              CAPTURE(wrong);
              CHECK_FALSE(accepts(*q, round_to(wrong, kDecimals)));
              ++slips;
            }
          }
    });
  }
  MESSAGE(fmt::format("{} numeric answers ({} with |v| ≥ 0.1), {} worked as told, {} slips refused; "
                      "tolerance beyond the answer's own rounding at most {:.2f} % ({}); whole "
                      "tolerance at most {:.2f} % ({}), over 5 % for {} answers (all below 0.2)",
                      answers, large, as_told, slips, 100 * carried.ratio, carried.where, 100 * whole.ratio,
                      whole.where, over_5));
  CHECK(as_told > 1000);
  CHECK(slips > 1000);
}
