// Work-fair sheets (issue 31): over both built-in courses, every difficulty and many seeds,
// every sheet of a set is worth the same total, its questions' points follow their work, the
// draw gives every sheet about the same work, and ticks (readable off the figure) stay small.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "exercises/points.h"
#include "exercises/worksheet.h"

namespace {

long long quarters(double points) { return std::llround(points / epure::kPointStep); }

struct Figures {
  double max_work_deviation = 0;  // |work − mean| / mean, over every sheet
  double max_tick_share = 0;      // ticks' points / the sheet's points
};

// `sheets` sheets of one set, every check on every sheet; the figures for the report.
Figures check_set(const epure::WorksheetSpec& spec, std::uint64_t seed, epure::Difficulty difficulty, int sheets) {
  epure::SetOptions options;
  options.difficulty = difficulty;
  epure::WorksheetSet set(spec, seed, options);
  const long long total = quarters(set.sheet_points());
  std::vector<double> work;
  Figures f;
  for (int i = 0; i < sheets; ++i) {
    const epure::Sheet sheet = set.next();
    CAPTURE(i);
    long long points = 0, ticks = 0;
    double w = 0;
    for (std::size_t e = 0; e < sheet.exercises.size(); ++e) {
      const auto& ex = sheet.exercises[e];
      long long own = 0;
      for (const auto& q : ex.questions) {
        CHECK(epure::on_point_step(q.points));
        own += quarters(q.points);
        if (epure::ticked(q)) ticks += quarters(q.points);
      }
      points += own;
      if (const auto& fixed = set.spec().exercises[e].points) CHECK(own == quarters(*fixed));  // kept
      for (const auto& [name, bw] : set.branch_work(static_cast<int>(e)))
        if (name == ex.branch) w += bw;
    }
    CHECK(points == total);
    work.push_back(w);

    f.max_tick_share = std::max(f.max_tick_share, static_cast<double>(ticks) / static_cast<double>(points));
  }
  double mean = 0;
  for (double w : work) mean += w;
  mean /= static_cast<double>(work.size());
  for (double w : work) f.max_work_deviation = std::max(f.max_work_deviation, std::abs(w - mean) / mean);
  return f;
}

}  // namespace

// Both built-in courses even out within 10 % of the set's mean (measured: the course 7.5 %, the
// course in space 3.8 %, whose template draws the sphere's long cases as often as the cube's
// miss: with the kinds' own proportions its floor was 13.7 %, templates/course-3d.toml).
constexpr double kWorkBound = 0.10;

TEST_CASE("work-fair sheets: same total, work within 10 % of the set's mean, ticks at most 15 %") {
  for (const auto& spec : epure::builtin_specs()) {
    Figures worst;
    for (const auto difficulty : {epure::Difficulty::easy, epure::Difficulty::standard, epure::Difficulty::hard})
      for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        CAPTURE(spec.source);
        CAPTURE(seed);
        CAPTURE(epure::to_string(difficulty));
        const Figures f = check_set(spec, seed, difficulty, 48);
        CHECK(f.max_work_deviation <= kWorkBound);
        CHECK(f.max_tick_share <= 0.15);
        worst.max_work_deviation = std::max(worst.max_work_deviation, f.max_work_deviation);
        worst.max_tick_share = std::max(worst.max_tick_share, f.max_tick_share);
      }
    MESSAGE(spec.source << ": max work deviation " << worst.max_work_deviation << ", max tick share "
                        << worst.max_tick_share);
  }
}
