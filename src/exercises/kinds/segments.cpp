// Exercise 2 of the course: do the segments [AB] and [CD] intersect? With 2D cross products
// only: AB∧CD = 0 means parallel lines (collinear when C is on (AB) too); otherwise the lines
// cross at P = A + t_ab·AB = C + t_cd·CD with
//   t_ab = AC∧CD / AB∧CD   and   t_cd = AC∧AB / AB∧CD,
// and the segments intersect when both parameters lie in [0, 1].
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "exercises/kind_method.h"
#include "geometry/segments.h"

namespace epure::kinds {

namespace {

using geo::Point2;
using geo::SegmentRelation;
using geo::Vec2;

struct Data {
  Point2 A, B, C, D;
};

// The drawing area of the data, and the wider one the lines' crossing may fall in (its label
// still fits the figure).
constexpr double kXMax = 10, kYMax = 8, kSlack = 1;

bool in_area(Point2 p, double slack = 0) {
  return p.x >= -slack && p.x <= kXMax + slack && p.y >= -slack && p.y <= kYMax + slack;
}

// Easy crossings: t = p/n with n among these stops within two decimals.
constexpr std::int64_t kEasyDenominators[] = {1, 2, 4, 5};

// A primitive integer direction with components in [−3, 3].
Vec2 small_direction(Rng& rng) {
  for (;;) {
    const std::int64_t x = rng.integer(-3, 3), y = rng.integer(-3, 3);
    if ((x != 0 || y != 0) && std::gcd(x, y) == 1) return {static_cast<double>(x), static_cast<double>(y)};
  }
}

// The exact forms the key's figure shows.
struct Exact {
  std::optional<exact::Surd> t_ab, t_cd, x, y;  // (x, y): the lines' crossing
};

using method::AnswerType;
constexpr std::string_view kReasons[] = {"outside", "parallel", "collinear"};

// AB∧CD below this fraction of ‖AB‖‖CD‖ is zero: grid data make it exactly zero or at least
// 1e-2 of the product, so the cut-off only absorbs the binary rounding of decimal data.
constexpr double kParallelSine = 1e-9;

// The course's exercise 2, written once (method.h).
struct SegmentsMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "segments";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("B", d.B);
    v("C", d.C);
    v("D", d.D);
  }

  static constexpr method::QuestionDecl kQuestions[] = {{"intersects", AnswerType::boolean},
                                                        {"t_ab", AnswerType::number},
                                                        {"t_cd", AnswerType::number},
                                                        {"I", AnswerType::point},
                                                        {"reason", AnswerType::choice, method::kTickWork, kReasons}};

  // what the exercise adds to the sheet's total when the spec does not set its points (points.h:
  // the sheet's questions share that total by their work)
  static constexpr double kPoints = 4;

  static constexpr std::string_view kMistakes[] = {"t_swapped", "cross_sign"};

  // The student's hand method, in the course's order: AB∧CD (zero: parallel, and collinear when
  // AC∧AB is zero too), AC∧CD, AC∧AB, then t_ab and t_cd by division, then I = A + t_ab·AB.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using method::magnitude;
    const auto A = m.in(d.A), B = m.in(d.B), C = m.in(d.C), D = m.in(d.D);
    const auto zero = m.in(0.0), one = m.in(1.0), sine = m.in(kParallelSine);
    const auto AB = m.note("AB", B - A), CD = m.note("CD", D - C), AC = m.note("AC", C - A);
    const auto ab_cd = m.round("ab_cd", cross(AB, CD));
    const auto ac_cd = m.round("ac_cd", m.mistake("cross_sign", cross(AC, CD), cross(CD, AC)));
    const auto ac_ab = m.round("ac_ab", m.mistake("cross_sign", cross(AC, AB), cross(AB, AC)));
    const auto parallel = less(magnitude(ab_cd), sine * norm(AB) * norm(CD));
    if (parallel) {
      const auto collinear = less(magnitude(ac_ab), sine * norm(AB) * (norm(AC) + one));
      m.boolean("intersects", method::Cond{false, parallel.deps});
      m.choice("reason", method::pick(collinear, "collinear", "parallel"));
      return;
    }
    const auto t_ab = m.number("t_ab", m.round("t_ab", m.mistake("t_swapped", ac_cd / ab_cd, ac_ab / ab_cd)));
    const auto t_cd = m.number("t_cd", m.round("t_cd", m.mistake("t_swapped", ac_ab / ab_cd, ac_cd / ab_cd)));
    const auto P = m.note("P", A + t_ab * AB);
    auto on_segment = [&](const auto& t) { return !less(t, zero) && !less(one, t); };
    const auto intersects = m.boolean("intersects", on_segment(t_ab) && on_segment(t_cd));
    if (!intersects) {
      m.choice("reason", method::Word{"outside", intersects.deps});
      return;
    }
    m.point("I", P);
  }

  // the solve contract (solve/solve.h)
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto s = geo::intersect_segments_exact(f.dpoint2("A"), f.dpoint2("B"), f.dpoint2("C"), f.dpoint2("D"));
    r.boolean("intersects", s.intersects());
    if (!s.intersects()) r.string("reason", geo::to_string(s.relation));
    if (s.t_ab) r.number("t_ab", *s.t_ab).number("t_cd", *s.t_cd);
    if (s.I) r.point("I", *s.I);
  }

  static CoreAnswers core(const Data& d) {
    const auto s = geo::intersect_segments_exact(geo::written_point(d.A), geo::written_point(d.B), geo::written_point(d.C), geo::written_point(d.D));
    CoreAnswers a;
    a.boolean("intersects", s.intersects());
    if (s.t_ab) a.number("t_ab", *s.t_ab).number("t_cd", *s.t_cd);
    if (s.I) a.point("I", *s.I);
    if (!s.intersects()) a.choice("reason", geo::to_string(s.relation));
    return a;
  }
};

// A parameter on a tick of the key's figure: "t_{ab} = 0.25" when exact within the decimals,
// "t_{ab} ≈ 0.43" otherwise.
std::string parameter_label(const ExerciseContext& ctx, std::string_view name, double t,
                            const std::optional<exact::Surd>& e) {
  if (terminates_within(e, ctx.decimals)) return fmt::format("{} = {}", name, ctx.numbers.datum(t, ctx.decimals));
  return fmt::format("{} ≈ {}", name, ctx.numbers.rounded(t, ctx.decimals));
}

class Segments final : public MethodKind<SegmentsMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    // collinear is available on request: the course only names it in passing
    return {{"intersects", 2}, {"outside", 1}, {"parallel", 1}, {"collinear", 0}};
  }
  std::map<std::string, double> default_constraints() const override {
    // t_margin: a parameter inside [0, 1] stays this far from 0 and 1; outside_margin: one
    // outside stays this far beyond; max_t: parameters within [1 − max_t, max_t]; min_angle_deg:
    // the lines' angle when they cross; min_length: of each segment; parallel_gap: between
    // parallel lines; min_separation: between any two of A, B, C, D (their labels);
    // outside_clearance: between the lines' crossing outside the segments and A, B, C, D (the
    // crossing carries three labels).
    return {{"t_margin", 0.15},     {"outside_margin", 0.25}, {"max_t", 2.5},
            {"min_angle_deg", 20.0}, {"min_length", 3.0},      {"parallel_gap", 1.0},
            {"min_separation", 1.0}, {"outside_clearance", 1.5}};
  }
  std::vector<DrawnField> drawn() const override { return {{"I", 0, {}}}; }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    SegmentRelation wanted;
    if (ctx.branch == "intersects") wanted = SegmentRelation::intersects;
    else if (ctx.branch == "outside") wanted = SegmentRelation::outside;
    else if (ctx.branch == "parallel") wanted = SegmentRelation::parallel;
    else if (ctx.branch == "collinear") wanted = SegmentRelation::collinear;
    else throw std::invalid_argument(fmt::format("segments: no branch '{}'", ctx.branch));
    const bool crossing = wanted == SegmentRelation::intersects || wanted == SegmentRelation::outside;

    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    // hard: closer to the ends, to parallel and to each other, but safely away
    const double t_margin = constraint(ctx, *this, "t_margin") / (hard ? 3 : 1);
    const double outside_margin = constraint(ctx, *this, "outside_margin") / (hard ? 2 : 1);
    const double max_t = constraint(ctx, *this, "max_t");
    const double min_sin = std::sin(constraint(ctx, *this, "min_angle_deg") / (hard ? 2 : 1) *
                                    std::numbers::pi / 180);
    const double min_length = constraint(ctx, *this, "min_length");
    const double parallel_gap = constraint(ctx, *this, "parallel_gap") / (hard ? 2 : 1);
    const double min_separation = constraint(ctx, *this, "min_separation");
    const double outside_clearance = constraint(ctx, *this, "outside_clearance");
    const int per_unit = hard ? 10 : 1;

    const auto random_point = [&]() -> Point2 {
      return {grid_value(rng, 0, kXMax, level), grid_value(rng, 0, kYMax, level)};
    };
    // A parameter is fine inside [0, 1] away from its ends, or clearly beyond them.
    const auto parameter_ok = [&](double t) {
      if (t < 1 - max_t || t > max_t) return false;
      if (t >= t_margin && t <= 1 - t_margin) return true;
      return t <= -outside_margin || t >= 1 + outside_margin;
    };

    const auto draw = [&]() -> std::optional<Data> {
      Data x;
      if (crossing && level == Difficulty::easy) {
        // From the crossing P on the grid: A = P − p·d, B = A + n·d, so t_ab = p/n exactly.
        const Point2 P{grid_value(rng, 0, kXMax, level), grid_value(rng, 0, kYMax, level)};
        const auto place = [&](Point2& from, Point2& to) {
          const Vec2 dir = small_direction(rng);
          const bool inside = wanted == SegmentRelation::intersects || rng.chance(0.5);
          std::int64_t n = kEasyDenominators[rng.integer(0, std::size(kEasyDenominators) - 1)];
          if (inside && n < 2) n = 2;  // 0 < p < n needs room
          const auto lo = static_cast<std::int64_t>(std::ceil((1 - max_t) * static_cast<double>(n)));
          const auto hi = static_cast<std::int64_t>(std::floor(max_t * static_cast<double>(n)));
          const std::int64_t p = inside ? rng.integer(1, n - 1) : rng.integer(lo, hi);
          from = P - static_cast<double>(p) * dir;
          to = from + static_cast<double>(n) * dir;
        };
        place(x.A, x.B);
        place(x.C, x.D);
      } else if (crossing) {
        x = {random_point(), random_point(), random_point(), random_point()};
      } else {
        // AB on the grid, CD = k·w with w the shortest grid vector along AB.
        x.A = random_point();
        x.B = random_point();
        const std::int64_t gx = std::llround((x.B.x - x.A.x) * per_unit),
                           gy = std::llround((x.B.y - x.A.y) * per_unit);
        const std::int64_t g = std::gcd(gx, gy);
        if (g == 0) return std::nullopt;
        const std::int64_t wx = gx / g, wy = gy / g;
        const auto k_max = static_cast<std::int64_t>(
            std::floor(kXMax * per_unit / static_cast<double>(std::max(std::abs(wx), std::abs(wy)))));
        if (k_max < 1) return std::nullopt;
        const std::int64_t k = rng.integer(1, k_max) * (rng.chance(0.5) ? -1 : 1);
        if (wanted == SegmentRelation::parallel) {
          x.C = random_point();
        } else {
          // C = A + m·w, with m such that C stays in the area
          const std::int64_t m_max = static_cast<std::int64_t>(std::floor(
              (kXMax + kYMax) * per_unit / static_cast<double>(std::max(std::abs(wx), std::abs(wy)))));
          const std::int64_t m = rng.integer(-m_max, m_max);
          x.C = {static_cast<double>(std::llround(x.A.x * per_unit) + m * wx) / per_unit,
                 static_cast<double>(std::llround(x.A.y * per_unit) + m * wy) / per_unit};
        }
        x.D = {static_cast<double>(std::llround(x.C.x * per_unit) + k * wx) / per_unit,
               static_cast<double>(std::llround(x.C.y * per_unit) + k * wy) / per_unit};
      }

      const Point2 points[4] = {x.A, x.B, x.C, x.D};
      for (int i = 0; i < 4; ++i) {
        if (!in_area(points[i])) return std::nullopt;
        for (int j = 0; j < i; ++j)
          if (geo::norm(points[i] - points[j]) < min_separation) return std::nullopt;
      }
      if (geo::norm(x.B - x.A) < min_length || geo::norm(x.D - x.C) < min_length) return std::nullopt;

      const auto s = geo::intersect_segments_exact(geo::written_point(x.A), geo::written_point(x.B), geo::written_point(x.C), geo::written_point(x.D));
      if (s.relation != wanted) return std::nullopt;
      if (crossing) {
        if (std::abs(s.ab_cross_cd) < min_sin * geo::norm(s.AB) * geo::norm(s.CD)) return std::nullopt;
        if (!parameter_ok(*s.t_ab) || !parameter_ok(*s.t_cd)) return std::nullopt;
        const Point2 P = x.A + *s.t_ab * s.AB;
        if (!in_area(P, kSlack)) return std::nullopt;
        if (wanted == SegmentRelation::outside)
          for (const Point2& p : points)
            if (geo::norm(P - p) < outside_clearance) return std::nullopt;
      }
      if (wanted == SegmentRelation::parallel && std::abs(s.ac_cross_ab) < parallel_gap * geo::norm(s.AB))
        return std::nullopt;
      return x;
    };
    const Data d = draw_until(20000, fmt::format("segments, branch {} (parameters, angle, lengths, gap, separation)", ctx.branch),
                              draw);
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto s = geo::intersect_segments_exact(geo::written_point(d.A), geo::written_point(d.B), geo::written_point(d.C), geo::written_point(d.D));
    const bool crossing = s.t_ab.has_value();

    const auto sheet_figure = [&](const KeySolution&) { return render::Figure{question_scene(d, ctx), 0.55}; };
    Begun begun = begin_sections(d, ctx, sheet_figure);
    ExerciseInstance& inst = begun.inst;
    const KeySolution& key = begun.key;
    const Questions& q = key.questions;
    Exact e;
    Point2 P{};  // where the lines cross
    if (crossing) {
      e = {key.exact("t_ab"), key.exact("t_cd"), key.exact_x("P"), key.exact_y("P")};
      P = s.I ? *s.I : key.point("P");
    }

    inst.key.add(render::Paragraph{T.format("segments.step.vectors", {{"AB", N.point(s.AB.x, s.AB.y)},
                                                                       {"CD", N.point(s.CD.x, s.CD.y)},
                                                                       {"AC", N.point(s.AC.x, s.AC.y)}})});
    // the cross products are exact decimals of the data: written out in full
    inst.key.add(render::Paragraph{T.format("segments.step.denominator", {{"ab_cd", N.datum(s.ab_cross_cd)}})});
    if (crossing) {
      inst.key.add(render::Paragraph{T.get("segments.step.lines_cross")});
      inst.key.add(render::Paragraph{T.format(
          "segments.step.numerators", {{"ac_cd", N.datum(s.ac_cross_cd)}, {"ac_ab", N.datum(s.ac_cross_ab)}})});
      inst.key.add(render::Paragraph{T.format("segments.step.t_ab", {{"t_ab", equals_value(ctx, *s.t_ab, e.t_ab)}})});
      inst.key.add(render::Paragraph{T.format("segments.step.t_cd", {{"t_cd", equals_value(ctx, *s.t_cd, e.t_cd)}})});
      const TextVars at = {{"P", equals_point(ctx, P, e.x, e.y)}};
      if (s.intersects()) {
        inst.key.add(render::Paragraph{T.format("segments.step.intersects", at)});
      } else {
        const bool ab_out = *s.t_ab < 0 || *s.t_ab > 1, cd_out = *s.t_cd < 0 || *s.t_cd > 1;
        const char* which = ab_out && cd_out ? "both" : ab_out ? "ab" : "cd";
        inst.key.add(render::Paragraph{T.format(fmt::format("segments.step.outside.{}", which), at)});
      }
    } else {
      inst.key.add(render::Paragraph{T.format(fmt::format("segments.step.{}", geo::to_string(s.relation)),
                                              {{"ac_ab", N.datum(s.ac_cross_ab)}})});
    }
    inst.key.add(render::Figure{key_scene(d, s, P, e, ctx), 0.45});
    add_lines(inst.key, q);
    return std::move(inst);
  }

  static render::Panel data_panel(const Data& d, const std::optional<Point2>& P) {
    std::vector<render::P2> shown = {p2(d.A), p2(d.B), p2(d.C), p2(d.D)};
    // room around the crossing for its label and both parameters' labels
    if (P)
      for (double dx : {-2.5, 2.5})
        for (double dy : {-1.5, 1.5}) shown.push_back({P->x + dx, P->y + dy});
    render::Panel panel;
    panel.view = view_around(shown, 1.0, 5.0);
    panel.add(render::Grid{1, true});
    return panel;
  }

  static void add_data(render::Panel& panel, const Data& d) {
    panel.add(render::Segment{p2(d.A), p2(d.B), render::Role::data});
    panel.add(render::Segment{p2(d.C), p2(d.D), render::Role::data});
    panel.add(render::PointMark{p2(d.A), render::Role::data, render::Label{"A", p2(d.A)}});
    panel.add(render::PointMark{p2(d.B), render::Role::data, render::Label{"B", p2(d.B)}});
    panel.add(render::PointMark{p2(d.C), render::Role::data, render::Label{"C", p2(d.C)}});
    panel.add(render::PointMark{p2(d.D), render::Role::data, render::Label{"D", p2(d.D)}});
  }

  render::Scene question_scene(const Data& d, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("segments.title");
    s.description = ctx.texts.get("segments.figure.question");
    render::Panel panel = data_panel(d, std::nullopt);
    add_data(panel, d);
    s.panels.push_back(std::move(panel));
    return s;
  }

  render::Scene key_scene(const Data& d, const geo::SegmentIntersection& x, Point2 P, const Exact& e,
                          const ExerciseContext& ctx) const {
    const bool crossing = x.t_ab.has_value();
    render::Scene s;
    s.title = ctx.texts.get("segments.title");
    s.description = ctx.texts.get(fmt::format("segments.figure.key.{}", geo::to_string(x.relation)));
    render::Panel panel = data_panel(d, crossing ? std::optional<Point2>(P) : std::nullopt);
    // the supporting lines: the construction
    panel.add(render::Line{p2(d.A), p2(d.B), render::Role::construction});
    if (x.relation != SegmentRelation::collinear)
      panel.add(render::Line{p2(d.C), p2(d.D), render::Role::construction});
    add_data(panel, d);
    if (crossing) {
      // both parameters where the lines cross; the point is the answer only when it is on both
      const render::Role role = x.intersects() ? render::Role::result : render::Role::construction;
      panel.add(render::Tick{p2(P), p2(x.AB), parameter_label(ctx, "t_{ab}", *x.t_ab, e.t_ab), role});
      panel.add(render::Tick{p2(P), p2(x.CD), parameter_label(ctx, "t_{cd}", *x.t_cd, e.t_cd), role});
      panel.add(render::PointMark{p2(P), role, render::Label{x.intersects() ? "I" : "P", p2(P), render::Side::auto_, role}});
    }
    s.panels.push_back(std::move(panel));
    return s;
  }
};

}  // namespace

const ExerciseKind& segments_kind() { return the_kind<Segments>(); }

}  // namespace epure::kinds
