// An exercise's points shared by the questions asked: exact totals, quarter points, a point's
// coordinates alike, deterministic; and every sheet of the course's set worth the same,
// exercise by exercise, whatever branch each drew.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>

#include "exercises/points.h"
#include "exercises/worksheet.h"

namespace {

using epure::Question;

Question question(std::string field, double weight, std::string group = {}) {
  Question q;
  q.field = std::move(field);
  q.points = weight;
  q.point_group = std::move(group);
  return q;
}

double sum(const std::vector<Question>& qs) {
  double s = 0;
  for (const auto& q : qs) s += q.points;
  return s;
}

// Points are whole quarters: compared as quarters, exactly.
long long quarters(double points) { return std::llround(points / epure::kPointStep); }

}  // namespace

TEST_CASE("spread_points shares an exercise's points in proportion to the weights") {
  SUBCASE("1. equal weights that divide evenly") {
    std::vector<Question> qs{question("a", 1), question("b", 1), question("c", 1), question("d", 1)};
    epure::spread_points(qs, 6);
    for (const auto& q : qs) CHECK(quarters(q.points) == 6);  // 1.5 each
  }
  SUBCASE("2. weights 2, 2, 1 of 5 points") {
    std::vector<Question> qs{question("t", 2), question("P.x", 1, "P"), question("P.y", 1, "P"), question("position", 1)};
    epure::spread_points(qs, 5);
    CHECK(quarters(qs[0].points) == 8);
    CHECK(quarters(qs[1].points) == 4);
    CHECK(quarters(qs[2].points) == 4);
    CHECK(quarters(qs[3].points) == 4);
  }
  SUBCASE("3. a remainder: the largest remainders get it, ties to the first asked") {
    std::vector<Question> qs{question("a", 1), question("b", 1), question("c", 1)};
    epure::spread_points(qs, 4);  // 16 quarters over 3: 6, 5, 5
    CHECK(quarters(qs[0].points) == 6);
    CHECK(quarters(qs[1].points) == 5);
    CHECK(quarters(qs[2].points) == 5);
  }
  SUBCASE("4. a point's coordinates always get the same share when the total allows") {
    std::vector<Question> qs{question("t", 1), question("I.x", 0.5, "I"), question("I.y", 0.5, "I")};
    epure::spread_points(qs, 2.75);  // 11 quarters: t 5 or 6, I even
    CHECK(qs[1].points == doctest::Approx(qs[2].points).epsilon(1e-15));
    CHECK(quarters(sum(qs)) == 11);
  }
  SUBCASE("5. an odd total over points only: exact sum, the odd quarter to the first coordinate") {
    std::vector<Question> qs{question("P.x", 0.5, "P"), question("P.y", 0.5, "P")};
    epure::spread_points(qs, 0.75);
    CHECK(quarters(qs[0].points) == 2);
    CHECK(quarters(qs[1].points) == 1);
  }
  SUBCASE("6. zero weights everywhere count as equal weights") {
    std::vector<Question> qs{question("a", 0), question("b", 0)};
    epure::spread_points(qs, 3);
    CHECK(quarters(qs[0].points) == 6);
    CHECK(quarters(qs[1].points) == 6);
  }
  SUBCASE("7. a zero weight beside others gets nothing") {
    std::vector<Question> qs{question("a", 0), question("b", 1)};
    epure::spread_points(qs, 3);
    CHECK(quarters(qs[0].points) == 0);
    CHECK(quarters(qs[1].points) == 12);
  }
  SUBCASE("8. no questions, zero total") {
    std::vector<Question> none;
    epure::spread_points(none, 4);
    CHECK(none.empty());
    std::vector<Question> qs{question("a", 1)};
    epure::spread_points(qs, 0);
    CHECK(quarters(qs[0].points) == 0);
  }
}

TEST_CASE("spread_points: many weights and totals, every share a quarter and the sum exact") {
  for (int seed = 0; seed < 500; ++seed) {
    CAPTURE(seed);
    std::vector<Question> qs;
    std::uint64_t x = 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(seed + 1);
    const int n = 1 + seed % 9;
    for (int i = 0; i < n; ++i) {
      x ^= x >> 31, x *= 0xBF58476D1CE4E5B9ULL, x ^= x >> 29;
      const double w = static_cast<double>(1 + x % 4) / 2;
      if (x % 3 == 0) {
        std::string g = "P";
        g += std::to_string(i);
        qs.push_back(question(g + ".x", w / 2, g));
        qs.push_back(question(g + ".y", w / 2, g));
      } else {
        std::string name = "q";
        name += std::to_string(i);
        qs.push_back(question(name, w));
      }
    }
    const double total = static_cast<double>(seed % 41) * epure::kPointStep;
    std::vector<Question> again = qs;
    epure::spread_points(qs, total);
    epure::spread_points(again, total);
    CHECK(quarters(sum(qs)) == quarters(total));
    for (std::size_t i = 0; i < qs.size(); ++i) {
      CHECK(epure::on_point_step(qs[i].points));
      CHECK(qs[i].points >= 0);
      CHECK(quarters(qs[i].points) == quarters(again[i].points));  // deterministic
    }
  }
}

TEST_CASE("every sheet of the course's set is worth the same; an exercise's points follow its branch") {
  const epure::WorksheetSpec course = epure::builtin_spec();
  epure::WorksheetSet set(course, 7);
  std::map<std::string, std::map<long long, int>> worth;  // kind/branch → its points seen
  std::map<std::string, long long> shortest, longest;     // kind → its branches' points
  for (int i = 0; i < 60; ++i) {
    const auto sheet = set.next();
    CAPTURE(i);
    long long total = 0;
    for (std::size_t e = 0; e < sheet.exercises.size(); ++e) {
      const auto& ex = sheet.exercises[e];
      const long long q = quarters(sum(ex.questions));
      total += q;
      // the projection's spec sets its points (5): kept on every sheet, whatever the branch
      if (course.exercises[e].points) CHECK(q == quarters(*course.exercises[e].points));
      auto [lo, fresh] = shortest.emplace(ex.kind, q);
      if (!fresh) lo->second = std::min(lo->second, q);
      auto [hi, fresh2] = longest.emplace(ex.kind, q);
      if (!fresh2) hi->second = std::max(hi->second, q);
    }
    CHECK(total == quarters(set.sheet_points()));
  }
  CHECK(quarters(set.sheet_points()) == quarters(43));  // the course's total, as before
  // a short branch earns less than a long one: the parallel segments (intersects? no, parallel:
  // 1 point of work in 6.5) well under the crossing ones
  CHECK(longest["segments"] >= 4 * shortest["segments"]);
  CHECK(longest["ray_square"] >= 4 * shortest["ray_square"]);
  CHECK(shortest["projection"] == longest["projection"]);
}
