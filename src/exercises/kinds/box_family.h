#pragma once
// The course's exercise 4 as one figure family, written once over the number type and the
// dimension: a ray and the canonical box [-1,1]^Dim (the square; in space, "cet algo se
// généralise très simplement en 3D avec le cube canonique (6 faces)", the cube; through its
// canonical frame, the rectangle). The faces whose closed outer half-space holds A are the
// candidates (at most Dim); on each the ray heads into (û·n < 0), (A + t·û)·n = 1 gives
// t = (1 − A·n)/(û·n), and the crossing is the hit when its other coordinates lie in [-1, 1].
// From inside, the ray leaves through the face it reaches first among those it heads to
// (û·n > 0). N is the normal of the face I lies on.
//
// A kind of this family (the square's file, the cube's) is its name, its draw and its scenes;
// the schema, the questions, the method with its mistakes, the key's worked steps, the solve
// contract and the draw's clearances are the family's. The rectangle's file runs
// the face-by-face search (search_faces) and the normal of the face hit (face_normal) in its
// canonical frame.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "exercises/kind_method.h"
#include "exercises/kinds/dimension.h"
#include "exercises/kinds/ray_branch.h"
#include "geometry/box_faces.h"
#include "geometry/ray_3d.h"
#include "geometry/ray_square.h"
#include "solve/result.h"

namespace epure::kinds::box {

using geo::Face;
using method::Shown;

// |u·n| below this fraction of ‖u‖ is zero: what the binary rounding of cos 90° or sin 180°
// leaves (about 1e-17) where a ray carried into the canonical frame runs along a face's
// direction, never a real crossing. Data on a grid give u·n exactly 0 or far from it.
inline constexpr double kAlongFace = 1e-12;

// The words a method's worked steps use for a face, by the kind's texts (`step.<word>`): the
// square's "side…", the cube's "face…", the rectangle's "side.…". An empty word: no such step.
struct FaceTexts {
  std::string_view exit;   // from inside: a face the ray heads to, crossed at t
  std::string_view face;   // from outside: a candidate, its normal and u·n
  std::string_view away;   // a candidate the ray does not head into
  std::string_view cross;  // a candidate it heads into: t and the crossing
  std::string_view on, off;
  Shown number = Shown::value;  // how the steps show a number and a point
  Shown point = Shown::point;
};

// The names of these faces, in their order (geometry/box_faces.h spells them).
template <std::size_t N>
constexpr std::array<std::string_view, N> names_of(const Face (&faces)[N]) {
  std::array<std::string_view, N> names{};
  for (std::size_t i = 0; i < N; ++i) names[i] = geo::face_name(faces[i]);
  return names;
}

// What differs between the plane and space: the core's types (dimension.h; here the result),
// the faces in the contract's order, the names of the method's steps on each (recorded steps
// keep views of them), and how a point is asked (in the plane one point answer "I"; in space
// three numbers).
template <int Dim>
struct Space;

template <>
struct Space<2> : Dimension<2> {
  using Result = geo::RaySquare;
  static constexpr Face kFaces[] = {{0, +1}, {1, +1}, {0, -1}, {1, -1}};
  static constexpr auto kFaceNames = names_of(kFaces);
  static constexpr std::string_view kAxes[] = {"x", "y"};
  static constexpr std::string_view kStepA[] = {"A.x", "A.y"};
  static constexpr std::string_view kStepUn[] = {"u_n.+x", "u_n.+y", "u_n.-x", "u_n.-y"};
  static constexpr std::string_view kStepT[] = {"t.+x", "t.+y", "t.-x", "t.-y"};
  static constexpr Name kStepJ[] = {"J.+x", "J.+y", "J.-x", "J.-y"};
  static constexpr Name kStepN[] = {"n.+x", "n.+y", "n.-x", "n.-y"};
  // |the other coordinate| of the crossing, which the key compares with 1
  static constexpr std::string_view kStepOff[] = {"off.+x", "off.+y", "off.-x", "off.-y"};
  static constexpr Name u_hat = "u_hat", I = "I", N = "N";
  static constexpr method::QuestionDecl kQuestions[] = {
      {"faces", method::AnswerType::faces, method::kTickWork, kFaceNames},
      {"inside", method::AnswerType::boolean},
      {"hit", method::AnswerType::boolean},   {"t", method::AnswerType::number},
      {"I", method::AnswerType::point},       {"N", method::AnswerType::point}};
  static constexpr FaceTexts kTexts = {"exit_side", "side", "side_away", "side_cross", "side_on", "side_off"};
};

template <>
struct Space<3> : Dimension<3> {
  using Result = geo::RayCube;
  static constexpr Face kFaces[] = {{0, +1}, {1, +1}, {2, +1}, {0, -1}, {1, -1}, {2, -1}};
  static constexpr auto kFaceNames = names_of(kFaces);
  static constexpr std::string_view kAxes[] = {"x", "y", "z"};
  static constexpr std::string_view kStepA[] = {"A.x", "A.y", "A.z"};
  static constexpr std::string_view kStepUn[] = {"u_n.+x", "u_n.+y", "u_n.+z", "u_n.-x", "u_n.-y", "u_n.-z"};
  static constexpr std::string_view kStepT[] = {"t.+x", "t.+y", "t.+z", "t.-x", "t.-y", "t.-z"};
  static constexpr Name kStepJ[] = {{"J.+x.x", "J.+x.y", "J.+x.z"}, {"J.+y.x", "J.+y.y", "J.+y.z"},
                                    {"J.+z.x", "J.+z.y", "J.+z.z"}, {"J.-x.x", "J.-x.y", "J.-x.z"},
                                    {"J.-y.x", "J.-y.y", "J.-y.z"}, {"J.-z.x", "J.-z.y", "J.-z.z"}};
  static constexpr Name kStepN[] = {{"n.+x.x", "n.+x.y", "n.+x.z"}, {"n.+y.x", "n.+y.y", "n.+y.z"},
                                    {"n.+z.x", "n.+z.y", "n.+z.z"}, {"n.-x.x", "n.-x.y", "n.-x.z"},
                                    {"n.-y.x", "n.-y.y", "n.-y.z"}, {"n.-z.x", "n.-z.y", "n.-z.z"}};
  static constexpr std::string_view kStepOff[] = {"off.+x", "off.+y", "off.+z", "off.-x", "off.-y", "off.-z"};
  static constexpr Name u_hat = {"u_hat.x", "u_hat.y", "u_hat.z"}, I = {"I.x", "I.y", "I.z"},
                        N = {"N.x", "N.y", "N.z"};
  static constexpr method::QuestionDecl kQuestions[] = {
      {"faces", method::AnswerType::faces, method::kTickWork, kFaceNames},
      {"inside", method::AnswerType::boolean},
      {"hit", method::AnswerType::boolean},   {"t", method::AnswerType::number},
      {"I.x", method::AnswerType::number, method::kCoordinateWork},
      {"I.y", method::AnswerType::number, method::kCoordinateWork},
      {"I.z", method::AnswerType::number, method::kCoordinateWork},
      {"N.x", method::AnswerType::number, method::kCoordinateWork},
      {"N.y", method::AnswerType::number, method::kCoordinateWork},
      {"N.z", method::AnswerType::number, method::kCoordinateWork}};
  static constexpr FaceTexts kTexts = {"exit_face", "face", "face_away", "face_cross", "face_on", "face_off"};
};

// A face's bit in the contract's face sets (method::FaceMask: +x +y +z −x −y −z are bits 0 … 5).
inline method::FaceMask bit_of(Face f) { return method::FaceMask(1u << (f.axis + (f.sign > 0 ? 0 : 3))); }

// A point's coordinate k, whatever its number type and dimension.
template <class P>
auto coord(const P& p, int axis) {
  if constexpr (requires { p.z; }) return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  else return axis == 0 ? p.x : p.y;
}
// p·n for the face's outward normal n = σ·e_k.
template <class P>
auto along(const P& p, Face f) {
  return f.sign > 0 ? coord(p, f.axis) : -coord(p, f.axis);
}

// A step's group name: a point in the plane is one step; in space, its coordinates' group.
constexpr std::string_view group(std::string_view name) { return name; }
inline std::string_view group(const method::Names3& names) { return names[0].substr(0, names[0].size() - 2); }

// The face's outward normal as data of the method.
template <int Dim, class M>
auto normal_of(M& m, Face f) {
  typename Space<Dim>::Vec n{};
  if constexpr (Dim == 2) (f.axis == 0 ? n.x : n.y) = f.sign;
  else (f.axis == 0 ? n.x : f.axis == 1 ? n.y : n.z) = f.sign;
  return m.in(n);
}

// The course's face-by-face search, from A along w (û, or u_c in the canonical frame): from
// outside the faces of `candidates` (those the ray heads into, |w·n| past kAlongFace·‖w‖, have
// their crossing tried), from inside the faces it heads to. Each face's steps are told with
// `texts`, in `order` (indices into Space<Dim>::kFaces; the contract's order by default). The
// nearest t of a crossing on its face, or none.
template <int Dim, class M, class P>
std::optional<typename M::Number> search_faces(M& m, const P& A, const P& w, bool inside,
                                               method::FaceMask candidates, const FaceTexts& texts,
                                               std::span<const int> order = {}) {
  using S = Space<Dim>;
  using method::less;
  const auto zero = m.in(0.0), one = m.in(1.0);
  double length2 = 0;
  for (int k = 0; k < Dim; ++k) length2 += method::value(coord(w, k)) * method::value(coord(w, k));
  const double tiny = kAlongFace * std::sqrt(length2);
  constexpr int kCount = int(std::size(S::kFaces));
  std::array<int, kCount> contract_order{};
  for (int i = 0; i < kCount; ++i) contract_order[i] = i;
  if (order.empty()) order = contract_order;

  std::optional<typename M::Number> best;
  for (int i : order) {
    const Face f = S::kFaces[i];
    const auto u_n = along(w, f);
    const bool in_play = inside ? method::value(u_n) > tiny : (candidates & bit_of(f)) != 0;
    if (!in_play) continue;
    m.note(S::kStepUn[i], u_n);
    m.note(S::kStepN[i], normal_of<Dim>(m, f));
    const method::Shows face{"face", S::kFaceNames[i], Shown::face}, n{"n", group(S::kStepN[i]), Shown::data},
        un{"un", S::kStepUn[i], texts.number};
    if (!inside && !(method::value(u_n) < -tiny)) {
      if (!texts.face.empty()) m.tell(texts.face, {face, n, un});
      m.tell(texts.away, {face, un});
      continue;
    }
    // (A + t·w)·n = 1
    const auto t = m.note(S::kStepT[i], (one - along(A, f)) / u_n);
    const auto J = m.note(S::kStepJ[i], A + t * w);
    bool on_face = !less(t, zero).v;
    for (int k = 0; k < Dim; ++k)
      if (k != f.axis) on_face = on_face && !less(one, method::magnitude(coord(J, k))).v;
    const int a = (f.axis + 1) % Dim, b = (f.axis + 2) % Dim;
    if constexpr (Dim == 2) m.note(S::kStepOff[i], method::magnitude(coord(J, a)));
    const std::initializer_list<method::Shows> shows = {
        face,
        n,
        un,
        {"t", S::kStepT[i], texts.number},
        {"J", group(S::kStepJ[i]), texts.point},
        {"c", S::kAxes[a], Shown::text},
        {"v", S::kStepOff[i], Dim == 2 ? texts.number : Shown::text},
        {"a", S::kAxes[std::min(a, b)], Shown::text},
        {"b", S::kAxes[std::max(a, b)], Shown::text}};
    if (inside) {
      m.tell(texts.exit, shows);
    } else {
      if (!texts.face.empty()) m.tell(texts.face, shows);
      if (!texts.cross.empty()) m.tell(texts.cross, shows);
      m.tell(on_face ? texts.on : texts.off, shows);
    }
    if (on_face && (!best || less(t, *best))) best = t;
  }
  return best;
}

// The normal of the face I lies on (its largest coordinate in absolute value; x, then y, first
// at a tie), read from I: it depends on I's answers though no number of I enters it.
template <int Dim, class M, class P>
P face_normal(M& m, const P& I) {
  using method::less;
  const auto zero = m.in(0.0), one = m.in(1.0);
  int k = 0;
  for (int j = 1; j < Dim; ++j)
    if (less(method::magnitude(coord(I, k)), method::magnitude(coord(I, j)))) k = j;
  const auto sign = less(coord(I, k), zero) ? -one : one;
  auto component = [&](int j) {
    auto c = j == k ? sign : zero;
    for (int l = 0; l < Dim; ++l) c = method::depends_on(coord(I, l), c);
    return c;
  };
  if constexpr (Dim == 2) return P{component(0), component(1)};
  else return P{component(0), component(1), component(2)};
}

// The face the normal names ("+x"), static storage.
template <int Dim, class P>
std::string_view face_of_normal(const P& n) {
  using S = Space<Dim>;
  for (int i = 0; i < int(std::size(S::kFaces)); ++i)
    if (method::value(along(n, S::kFaces[i])) > 0.5) return S::kFaceNames[i];
  return S::kFaceNames[0];
}

template <int Dim>
struct Data {
  typename Space<Dim>::Point A;
  typename Space<Dim>::Vec u;
};

// The core's solution of the figure, on the unit ray (t a length).
template <int Dim>
typename Space<Dim>::Result solve_core(const Data<Dim>& d) {
  if constexpr (Dim == 2) return geo::intersect_canonical_square(geo::Ray2::unit(d.A, d.u));
  else return geo::intersect_canonical_cube(geo::Ray3::unit(d.A, d.u));
}

// The branch the core's solution shows: inside, hit or miss.
template <class Result>
RayBranch branch_of(const Result& r) {
  if (r.inside) return RayBranch::inside;
  return r.hit ? RayBranch::hit : RayBranch::miss;
}

// The family, for MethodKind (kind_method.h): a kind adds its kName and kPoints.
template <int Dim>
struct Family {
  using Data = box::Data<Dim>;
  using S = Space<Dim>;

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u, role::from("A"));
  }

  // The square's and the cube's half side, a size of the figure that is no datum: A's numbers
  // are as small beside it as beside a datum (solve/number_span.h).
  static constexpr double kCanonicalSize = 1;

  static constexpr auto& kQuestions = S::kQuestions;
  static constexpr std::string_view kMistakes[] = {"faces_wrong_half_planes", "faces_inner_half_planes",
                                                   "faces_from_direction", "direction_not_unit", "normal_inward"};

  // The candidate faces are those whose closed outer half-space holds A (A·n ≥ 1), A is inside
  // when there is none; then û, the face-by-face search, I = A + t·û and the normal of the face
  // I lies on. Mistakes: the candidates from the wrong half-spaces (A·n ≤ −1), from the inner
  // ones (A·n ≤ 1: the faces whose line A lies within), from the direction (the faces u heads
  // to); u not normalised; the normal inward.
  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    const auto A = m.in(d.A), u = m.in(d.u);
    const auto zero = m.in(0.0), one = m.in(1.0);
    method::FaceMask candidates = 0, opposite = 0, inner = 0, towards = 0;
    method::Cond inside{true};
    for (int k = 0; k < Dim; ++k) m.note(S::kStepA[k], coord(A, k));
    for (Face f : S::kFaces) {
      // the closed outer half-space A·n ≥ 1, exactly where the data are exact
      const auto a_n = along(A, f);
      const method::Cond within = method::exactly_less(a_n, one);
      if (!within) candidates |= bit_of(f), opposite |= bit_of({f.axis, -f.sign});
      if (!method::exactly_less(one, a_n)) inner |= bit_of(f);
      inside = inside && within;
      if (less(along(u, f), zero)) towards |= bit_of(f);
    }
    // each axis: which face, if any, is a candidate
    for (int k = 0; k < Dim; ++k) {
      const Face plus{k, +1}, minus{k, -1};
      const int side = method::value(coord(A, k)) > 0 ? 0 : int(std::size(S::kFaces)) / 2;
      const std::string_view where = (candidates & bit_of(plus)) ? "axis.plus"
                                     : (candidates & bit_of(minus)) ? "axis.minus"
                                                                    : "axis.none";
      m.tell(where, {{"c", S::kAxes[k], Shown::text},
                     {"v", S::kStepA[k], Shown::datum},
                     {"face", S::kFaceNames[k + side], Shown::face}});
    }
    const method::Faces right{candidates};
    const auto faces = m.faces(
        "faces", m.mistake("faces_from_direction",
                           m.mistake("faces_inner_half_planes",
                                     m.mistake("faces_wrong_half_planes", right, method::Faces{opposite}),
                                     inside ? right : method::Faces{inner}),
                           method::Faces{towards}));
    const auto in = m.boolean("inside", inside);
    if (inside) m.tell("no_candidate");
    else m.tell("candidates", {{"faces", "faces", Shown::faces}});
    const auto length = m.note("norm_u", sqrt(dot(u, u)));
    const auto uh = m.round(S::u_hat, m.mistake("direction_not_unit", u / length, u));
    m.tell("unit", {{"norm_u", "norm_u"}, {"u_hat", group(S::u_hat), Shown::point}});

    const auto best = search_faces<Dim>(m, A, uh, static_cast<bool>(in), faces.bits, S::kTexts);
    const auto hit = m.boolean("hit", method::Cond{best.has_value(), faces.deps | in.deps});
    if (!hit) {
      m.tell("miss");
      return;
    }
    const auto t = m.number("t", m.round("t", best ? *best : zero));
    const auto I = m.point(S::I, m.round(S::I, A + t * uh));
    const auto n = face_normal<Dim>(m, I);
    const auto N = m.point(S::N, m.mistake("normal_inward", n, -n));
    m.tell(inside ? "exit" : "hit", {{"face", face_of_normal<Dim>(n), Shown::face},
                                     {"t", "t"},
                                     {"I", "I", Shown::point},
                                     {"N", "N", Shown::data}});
    (void)N;
  }

  static CoreAnswers core(const Data& d) {
    const auto rs = solve_core(d);
    method::FaceMask bits = 0;
    rs.faces.for_each([&](Face f) { bits |= bit_of(f); });
    CoreAnswers a;
    a.faces("faces", bits).boolean("inside", rs.inside).boolean("hit", rs.hit.has_value());
    if (rs.hit) a.number("t", rs.hit->t).point(S::I, rs.hit->I).vec(S::N, rs.hit->N);
    return a;
  }

  // The solve contract: faces, inside, hit; then t, I, N.
  static void contract(const Data&, const solve::Fields& f, solve::Result& r) {
    const auto A = f.decimals<Dim>("A");
    const auto [u, length] = solve::raw_direction(f.decimals<Dim>("u"));
    if constexpr (Dim == 2) {
      auto s = geo::intersect_canonical_square_exact(A, u);
      r.faces(s.faces).boolean("inside", s.inside).hit(s.hit, length);
    } else {
      auto c = geo::intersect_canonical_cube_exact(A, u);
      r.faces(c.faces).boolean("inside", c.inside).hit(c.hit, length);
    }
  }
};

// ---- what the key's figure reads from the run, and the draw's clearances ----------------------

// A face the method looked at: a candidate from outside, a face the ray heads to from inside,
// with its crossing when the method tried it (the run's own values: nothing is computed again).
template <int Dim>
struct FaceInPlay {
  Face face;
  double u_n;
  std::optional<double> t;
  std::optional<typename Space<Dim>::Point> J;
};

template <int Dim, class Run>
std::vector<FaceInPlay<Dim>> faces_in_play(const Run& run) {
  using S = Space<Dim>;
  std::vector<FaceInPlay<Dim>> out;
  for (int i = 0; i < int(std::size(S::kFaces)); ++i) {
    const auto* u_n = run.step(S::kStepUn[i]);
    if (!u_n) continue;
    FaceInPlay<Dim> f{S::kFaces[i], method::value(u_n->x), std::nullopt, std::nullopt};
    if (const auto* t = run.step(S::kStepT[i])) {
      f.t = method::value(t->x);
      if constexpr (Dim == 2) {
        const auto* J = run.step(S::kStepJ[i]);
        f.J = geo::Point2{method::value(J->x), method::value(J->y)};
      } else {
        const auto& names = S::kStepJ[i];
        f.J = geo::Point3{method::value(run.step(names[0])->x), method::value(run.step(names[1])->x),
                          method::value(run.step(names[2])->x)};
      }
    }
    out.push_back(f);
  }
  return out;
}

// The draw's margins (the kind's constraints as the spec sets them).
struct Margins {
  double edge;   // a crossing at least this far from a face's edges (on or off it)
  double face;   // each coordinate of A at least this far from ±1
  double t_min;  // the hit at least this far along the ray
  double min_cos;  // |û·n| of a face in play at least this, unless exactly 0
};

// Whether the core's solution is the branch asked, clear of its boundaries: A clearly off every
// face's plane, each face in play crossed clearly on or clearly off (the hit's face on, the
// others off), no face in play nearly parallel to the ray. `closest` is how near a decisive
// crossing comes to a face's edge (none without a crossing), for the hard level's choice.
template <int Dim>
bool clear(const Data<Dim>& x, const typename Space<Dim>::Result& rs, std::optional<RayBranch> branch,
           const Margins& mg, double edge_clear, double face_clear, std::optional<double>& closest) {
  using S = Space<Dim>;
  if (!branch || branch_of(rs) != *branch) return false;
  for (int k = 0; k < Dim; ++k)
    if (std::abs(std::abs(coord(x.A, k)) - 1) < face_clear) return false;
  if (rs.hit && rs.hit->t < mg.t_min) return false;
  // the faces in play on the core's unit ray, for the draw only (the key reads the run's)
  const auto uh = x.u / geo::norm(x.u);
  std::optional<double> nearest;
  for (Face f : S::kFaces) {
    const double u_n = along(uh, f);
    if (rs.inside ? !(u_n > 0) : !rs.faces.contains(f)) continue;
    if (std::abs(u_n) < mg.min_cos && u_n != 0) return false;  // nearly parallel to the face
    if (!(rs.inside || u_n < 0)) continue;
    const double t = (1 - along(x.A, f)) / u_n;
    const auto J = x.A + t * uh;
    double out = 0;  // how far the crossing's other coordinates reach
    for (int k = 0; k < Dim; ++k)
      if (k != f.axis) out = std::max(out, std::abs(coord(J, k)));
    const bool decisive = rs.face && *rs.face == f;
    if (decisive) {
      if (out > 1 - edge_clear) return false;
      nearest = std::min(nearest.value_or(1 - out), 1 - out);
    } else if (!rs.inside) {
      if (out < 1 + edge_clear) return false;
      nearest = std::min(nearest.value_or(out - 1), out - 1);
    }
  }
  closest = nearest;
  return true;
}

// One attempt at the data, the same way in the plane and in space: A strictly inside on a grid of
// 1/(2w + 2) (easy and standard: unwidened, half a grid step, the only integer point strictly
// inside being the centre), or on the difficulty's grid within ±0.9 (hard), or outside within
// ±(4 + 2w); u one of the kind's easy directions, or on the grid within ±(3 or 4 + 2w) and at
// least 1 long. w: the widening (a large set has used up the usual ranges).
template <int Dim, class EasyDirection>
std::optional<Data<Dim>> draw_data(Rng& rng, const ExerciseContext& ctx, EasyDirection&& easy_direction) {
  const Difficulty level = ctx.spec.difficulty;
  const bool hard = level == Difficulty::hard, inside = ray_branch(ctx.branch) == RayBranch::inside;
  const int w = ctx.widening;
  std::array<double, Dim> a{};
  if (inside && !hard) {
    const std::int64_t k = 2 * w + 1;
    for (double& c : a) c = double(rng.integer(-k, k)) / double(k + 1);
  } else if (inside) {
    for (double& c : a) c = grid_value(rng, -0.9, 0.9, level);
  } else {
    const double reach = 4 + 2 * w;
    for (double& c : a) c = grid_value(rng, -reach, reach, level);
  }
  Data<Dim> x;
  if constexpr (Dim == 2) x.A = {a[0], a[1]};
  else x.A = {a[0], a[1], a[2]};
  if (level == Difficulty::easy) {
    x.u = easy_direction(rng);
  } else {
    const double m = (hard ? 3 : 4) + 2 * w;
    std::array<double, Dim> u{};
    for (double& c : u) c = grid_value(rng, -m, m, level);
    if constexpr (Dim == 2) x.u = {u[0], u[1]};
    else x.u = {u[0], u[1], u[2]};
    if (geo::norm(x.u) < 1) return std::nullopt;
  }
  return x;
}

// A kind of the family: MethodKind with the family's branches and draw loop. The kind (a
// Family<Dim> with kName, kPoints) adds, as static members:
//   kWhat                                   what its constraints hold ("branch, corner and side margins, t range")
//   constraints(), margins(ctx, kind)       its constraints' names and defaults, read as Margins
//   easy_direction(Rng&)                    an easy level's u
//   hard_enough(x, result, closest, mg, face_clear)   the hard level's choice of a near miss
//   sheet_figure(d, result, ctx), key_figure(d, result, key, ctx)
//   kDrawn()                                what a feedback sheet draws (optional)
template <class Kind>
class BoxKind final : public MethodKind<Kind> {
 public:
  using Data = typename Kind::Data;
  static constexpr int kDim = int(std::size(Kind::S::kFaces)) / 2;

  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override { return Kind::constraints(); }
  std::vector<DrawnField> drawn() const override {
    if constexpr (requires { Kind::kDrawn(); }) return Kind::kDrawn();
    else return {};
  }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const bool hard = ctx.spec.difficulty == Difficulty::hard;
    const std::optional<RayBranch> branch = ray_branch(ctx.branch);
    const Margins mg = Kind::margins(ctx, *this);
    // hard: near an edge or grazing a face's end, yet on the clear side of these margins
    const double edge_clear = hard ? mg.edge / 3 : mg.edge, face_clear = hard ? mg.face / 5 : mg.face;
    auto accept = [&](const Data& x) {
      const auto rs = solve_core(x);
      std::optional<double> closest;  // how near a decisive crossing comes to a face's edge
      if (!clear(x, rs, branch, mg, edge_clear, face_clear, closest)) return false;
      return !hard || Kind::hard_enough(x, rs, closest, mg, face_clear);
    };
    const Data d = draw_until(200000, fmt::format("{} ({})", Kind::kName, Kind::kWhat), [&]() -> std::optional<Data> {
      auto x = draw_data<kDim>(rng, ctx, [](Rng& r) { return Kind::easy_direction(r); });
      if (!x || !accept(*x)) return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, this->write(d))) return *std::move(taken);
    return this->made(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto rs = solve_core(d);
    return this->assemble(
        d, ctx, [&](const KeySolution&) { return Kind::sheet_figure(d, rs, ctx); },
        [&](const KeySolution& key) { return Kind::key_figure(d, rs, key, ctx); });
  }
};

}  // namespace epure::kinds::box
