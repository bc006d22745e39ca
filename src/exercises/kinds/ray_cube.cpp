// The course's remark on the square, "cet algo se généralise très simplement en 3D avec le cube
// canonique (6 faces)": the first point where a ray meets [-1,1]³. The faces whose closed outer
// half-space holds A are the candidates (at most three); each is met where (A + t·û)·n = 1,
// t = (1 − A·n)/(û·n), when the ray heads into it (û·n < 0), and the crossing is the hit when its
// two other coordinates lie in [-1, 1]. From inside, the ray leaves through the face it reaches
// first among those it heads to (û·n > 0).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercises/kind_method.h"
#include "exercises/kinds/space_common.h"
#include "geometry/ray_3d.h"

namespace epure::kinds {

namespace {

using geo::Face;
using geo::Point3;
using geo::Vec3;
using method::AnswerType;
using method::Names3;

struct Data {
  Point3 A;
  Vec3 u;
};

constexpr Vec3 kEasyDirections[] = {{1, 0, 0}, {2, 0, 0}, {3, 4, 0}, {1, 2, 2}, {2, 3, 6}, {2, 1, 2}, {4, 4, 2}};

// The six faces in the contract's order, and the names of the method's steps on each.
constexpr Face kFaces[] = {{0, +1}, {1, +1}, {2, +1}, {0, -1}, {1, -1}, {2, -1}};
constexpr std::string_view kFaceNames[] = {"+x", "+y", "+z", "-x", "-y", "-z"};
constexpr std::string_view kStepUn[] = {"u_n.+x", "u_n.+y", "u_n.+z", "u_n.-x", "u_n.-y", "u_n.-z"};
constexpr std::string_view kStepT[] = {"t.+x", "t.+y", "t.+z", "t.-x", "t.-y", "t.-z"};
constexpr Names3 kStepJ[] = {{"J.+x.x", "J.+x.y", "J.+x.z"}, {"J.+y.x", "J.+y.y", "J.+y.z"},
                             {"J.+z.x", "J.+z.y", "J.+z.z"}, {"J.-x.x", "J.-x.y", "J.-x.z"},
                             {"J.-y.x", "J.-y.y", "J.-y.z"}, {"J.-z.x", "J.-z.y", "J.-z.z"}};
constexpr Names3 kUh = {"u_hat.x", "u_hat.y", "u_hat.z"}, kI = {"I.x", "I.y", "I.z"}, kN = {"N.x", "N.y", "N.z"};
const char* const kAxis[] = {"x", "y", "z"};

method::FaceMask bit_of(Face f) { return method::FaceMask(1u << (f.axis + (f.sign > 0 ? 0 : 3))); }
double coord(Point3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
Vec3 normal_of(Face f) {
  Vec3 n{};
  (f.axis == 0 ? n.x : f.axis == 1 ? n.y : n.z) = f.sign;
  return n;
}
int index_of(Face f) {
  for (int i = 0; i < 6; ++i)
    if (kFaces[i] == f) return i;
  return 0;
}

geo::RayCube solve_core(const Data& d) { return geo::intersect_canonical_cube(geo::Ray3::unit(d.A, d.u)); }

std::string branch_of(const geo::RayCube& rc) {
  if (rc.inside) return "inside";
  return rc.hit ? "hit" : "miss";
}

// A face the method looks at: a candidate from outside, a face the ray heads to from inside.
struct FaceInPlay {
  Face face;
  double u_n;
  std::optional<double> t;
  std::optional<Point3> J;
};

std::vector<FaceInPlay> faces_in_play(const Data& d, const geo::RayCube& rc) {
  const Vec3 uh = d.u / geo::norm(d.u);
  std::vector<FaceInPlay> out;
  for (Face f : kFaces) {
    const Vec3 n = normal_of(f);
    const double u_n = geo::dot(uh, n);
    FaceInPlay s{f, u_n, std::nullopt, std::nullopt};
    if (rc.inside ? !(u_n > 0) : !rc.faces.contains(f)) continue;
    if (rc.inside || u_n < 0) {
      s.t = (1 - geo::dot(geo::to_vec(d.A), n)) / u_n;
      s.J = d.A + *s.t * uh;
    }
    out.push_back(s);
  }
  return out;
}

struct RayCubeMethod {
  using Data = kinds::Data;
  static constexpr std::string_view kName = "ray_cube";

  template <class V, class D>
  static void schema(V& v, D& d) {
    v("A", d.A);
    v("u", d.u);
  }

  static constexpr method::QuestionDecl kQuestions[] = {
      {"faces", AnswerType::faces, 1, kFaceNames}, {"inside", AnswerType::boolean}, {"hit", AnswerType::boolean},
      {"t", AnswerType::number},        {"I.x", AnswerType::number, 0.5}, {"I.y", AnswerType::number, 0.5},
      {"I.z", AnswerType::number, 0.5}, {"N.x", AnswerType::number, 0.5}, {"N.y", AnswerType::number, 0.5},
      {"N.z", AnswerType::number, 0.5}};
  static constexpr double kPoints = 7;
  static constexpr std::string_view kMistakes[] = {"faces_wrong_half_planes", "faces_from_direction",
                                                   "direction_not_unit", "normal_inward"};

  template <class M>
  static void method(M& m, const Data& d) {
    using method::less;
    using Num = typename M::Number;
    const auto A = m.in(d.A), u = m.in(d.u);
    const auto zero = m.in(0.0), one = m.in(1.0);
    auto at = [](const auto& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; };
    auto along = [&](const auto& p, Face f) { return f.sign > 0 ? at(p, f.axis) : -at(p, f.axis); };

    method::FaceMask candidates = 0, opposite = 0, towards = 0;
    method::Cond inside{true};
    for (Face f : kFaces) {
      const auto a_n = along(A, f);
      if (!less(a_n, one)) candidates |= bit_of(f), opposite |= bit_of({f.axis, -f.sign});
      inside = inside && less(a_n, one);
      if (less(along(u, f), zero)) towards |= bit_of(f);
    }
    const method::Faces right{candidates};
    const auto faces = m.faces("faces", m.mistake("faces_from_direction",
                                                  m.mistake("faces_wrong_half_planes", right, method::Faces{opposite}),
                                                  method::Faces{towards}));
    const auto in = m.boolean("inside", inside);
    const auto length = m.note("norm_u", sqrt(dot(u, u)));
    const auto uh = m.round(kUh, m.mistake("direction_not_unit", u / length, u));

    std::optional<Num> best;
    const method::Deps deps = faces.deps | in.deps;
    for (int i = 0; i < 6; ++i) {
      const Face f = kFaces[i];
      const auto u_n = m.note(kStepUn[i], along(uh, f));
      const bool in_play = in ? method::value(u_n) > 0 : (faces.bits & bit_of(f)) != 0;
      if (!in_play || (!in && !less(u_n, zero))) continue;
      const auto t = m.note(kStepT[i], (one - along(A, f)) / u_n);
      const auto J = m.note(kStepJ[i], A + t * uh);
      const int a = (f.axis + 1) % 3, b = (f.axis + 2) % 3;
      const bool on_face = static_cast<bool>(!less(t, zero) && !less(one, method::magnitude(at(J, a))) &&
                                             !less(one, method::magnitude(at(J, b))));
      if (on_face && (!best || less(t, *best))) best = t;
    }
    const auto hit = m.boolean("hit", method::Cond{best.has_value(), deps});
    if (!hit) return;
    const auto t = m.number("t", m.round("t", best ? *best : zero));
    const auto I = m.point(kI, m.round(kI, A + t * uh));
    // the face I lies on: its largest coordinate in absolute value (x, then y, first at a tie)
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (less(method::magnitude(at(I, k)), method::magnitude(at(I, j)))) k = j;
    const auto sign = [&](const auto& c) { return less(c, zero) ? -one : one; };
    const auto no = I.x - I.x + (I.y - I.y) + (I.z - I.z);  // carries I's dependencies into N
    auto component = [&](int j) {
      const Num c = j == k ? sign(at(I, k)) : zero;
      return m.either(no + c, c);
    };
    const method::V3<Num> n{component(0), component(1), component(2)};
    m.point(kN, m.mistake("normal_inward", n, -n));
  }

  static CoreAnswers core(const Data& d) {
    const auto rc = solve_core(d);
    method::FaceMask bits = 0;
    rc.faces.for_each([&](Face f) { bits |= bit_of(f); });
    CoreAnswers a;
    a.faces("faces", bits).boolean("inside", rc.inside).boolean("hit", rc.hit.has_value());
    if (rc.hit) a.number("t", rc.hit->t).point(kI, rc.hit->I).vec(kN, rc.hit->N);
    return a;
  }
};

class RayCubeKind final : public MethodKind<RayCubeMethod> {
 public:
  std::vector<std::pair<std::string, double>> default_branches() const override {
    return {{"hit", 3}, {"miss", 1}, {"inside", 1}};
  }
  std::map<std::string, double> default_constraints() const override {
    return {{"edge_margin", 0.15}, {"face_margin", 0.5}, {"t_min", 0.5}, {"min_cos", 0.2}};
  }

  ExerciseInstance make(Rng& rng, const ExerciseContext& ctx) const override {
    const Difficulty level = ctx.spec.difficulty;
    const bool hard = level == Difficulty::hard;
    const bool inside = ctx.branch == "inside";
    const double em = constraint(ctx, *this, "edge_margin");
    const double fm = constraint(ctx, *this, "face_margin");
    const double t_min = constraint(ctx, *this, "t_min") / (hard ? 2 : 1);
    const double min_cos = constraint(ctx, *this, "min_cos");
    const double em_clear = hard ? em / 3 : em, fm_clear = hard ? fm / 5 : fm;

    auto accept = [&](const Data& x) {
      const auto rc = solve_core(x);
      if (branch_of(rc) != ctx.branch) return false;
      for (int k = 0; k < 3; ++k)
        if (std::abs(std::abs(coord(x.A, k)) - 1) < fm_clear) return false;
      if (rc.hit && rc.hit->t < t_min) return false;
      double closest = 1e9;
      for (const FaceInPlay& s : faces_in_play(x, rc)) {
        if (std::abs(s.u_n) < min_cos && s.u_n != 0) return false;
        if (!s.J) continue;
        const int a = (s.face.axis + 1) % 3, b = (s.face.axis + 2) % 3;
        const double out = std::max(std::abs(coord(*s.J, a)), std::abs(coord(*s.J, b)));
        const bool decisive = rc.face && *rc.face == s.face;
        if (decisive) {
          if (out > 1 - em_clear) return false;
          closest = std::min(closest, 1 - out);
        } else if (!rc.inside) {
          if (out < 1 + em_clear) return false;
          closest = std::min(closest, out - 1);
        }
      }
      return !hard || closest <= em + 0.1 || rc.inside;
    };

    const Data d = draw_until(200000, "ray_cube (branch, edge and face margins, t range)", [&]() -> std::optional<Data> {
      Data x;
      // widened (a large set has used up the usual ranges): A further out, finer steps inside,
      // longer directions
      const int w = ctx.widening;
      if (inside && !hard) {
        // a grid of 1/(2w + 2) strictly inside
        const std::int64_t k = 2 * w + 1;
        auto c = [&] { return double(rng.integer(-k, k)) / double(k + 1); };
        x.A = {c(), c(), c()};
      } else if (inside) {
        x.A = {grid_value(rng, -0.9, 0.9, level), grid_value(rng, -0.9, 0.9, level), grid_value(rng, -0.9, 0.9, level)};
      } else {
        const double reach = 4 + 2 * w;
        x.A = {grid_value(rng, -reach, reach, level), grid_value(rng, -reach, reach, level),
               grid_value(rng, -reach, reach, level)};
      }
      if (level == Difficulty::easy) {
        Vec3 e = kEasyDirections[rng.integer(0, std::size(kEasyDirections) - 1)];
        double c[3] = {e.x, e.y, e.z};
        for (int i = 2; i > 0; --i) std::swap(c[i], c[rng.integer(0, i)]);
        for (double& k : c)
          if (rng.chance(0.5)) k = -k;
        x.u = {c[0], c[1], c[2]};
      } else {
        const double m = (hard ? 3 : 4) + 2 * w;
        x.u = {grid_value(rng, -m, m, level), grid_value(rng, -m, m, level), grid_value(rng, -m, m, level)};
        if (geo::norm(x.u) < 1) return std::nullopt;
      }
      if (!accept(x)) return std::nullopt;
      return x;
    });
    if (auto taken = already_taken(ctx, write(d))) return *std::move(taken);
    return build(d, ctx);
  }

 private:
  ExerciseInstance build(const Data& d, const ExerciseContext& ctx) const override {
    const auto& T = ctx.texts;
    const auto& N = ctx.numbers;
    const auto rc = solve_core(d);
    const auto faces = faces_in_play(d, rc);

    ExerciseInstance inst = begin_instance(d, ctx);
    KeySolution key = solve(d, ctx);
    const Questions& q = key.questions;
    inst.questions = key.questions.take_questions();
    auto value = [&](std::string_view id) { return step_value(ctx, key.value(id), key.exact(id)); };
    auto point = [&](const Names3& ids) { return space::step_point3(ctx, key, ids); };

    const TextVars data_vars = {{"A", N.point(d.A.x, d.A.y, d.A.z)}, {"u", N.point(d.u.x, d.u.y, d.u.z)}};
    if (ctx.sheet) {  // not for the explorer's views, which show the key only
      inst.sheet = begin_sheet_section(ctx, "ray_cube.title");
      inst.sheet.add(render::Paragraph{T.format("ray_cube.statement", data_vars)});
      inst.sheet.add(render::Figure{question_scene(d, ctx), 0.5});
      add_fields(inst.sheet, q);
    }

    inst.key = begin_key_section(ctx, "ray_cube.title");
    inst.key.add(render::Paragraph{T.format("ray_cube.data", data_vars)});
    auto step = [&](std::string_view id, const TextVars& vars = {}) {
      inst.key.add(render::Paragraph{T.format(fmt::format("ray_cube.step.{}", id), vars)});
    };
    for (int k = 0; k < 3; ++k) {
      const double a = coord(d.A, k);
      const char* where = rc.faces.contains({k, +1}) ? "plus" : rc.faces.contains({k, -1}) ? "minus" : "none";
      step(fmt::format("axis.{}", where),
           {{"c", kAxis[k]}, {"v", N.datum(a)}, {"face", std::string(geo::face_name({k, a > 0 ? +1 : -1}))}});
    }
    if (rc.inside) {
      step("no_candidate");
    } else {
      std::string list;
      rc.faces.for_each([&](Face f) { list += fmt::format("{}{}", list.empty() ? "" : ", ", geo::face_name(f)); });
      step("candidates", {{"faces", list}});
    }
    step("unit", {{"norm_u", value("norm_u")}, {"u_hat", point(kUh)}});
    for (const FaceInPlay& s : faces) {
      const int i = index_of(s.face);
      const bool hit_here = rc.face && *rc.face == s.face;
      const Vec3 n = normal_of(s.face);
      TextVars vars = {{"face", std::string(geo::face_name(s.face))},
                       {"n", N.point(n.x, n.y, n.z)},
                       {"un", value(kStepUn[i])}};
      if (s.J) {
        vars.emplace_back("t", value(kStepT[i]));
        vars.emplace_back("J", point(kStepJ[i]));
      }
      if (rc.inside) {
        step("exit_face", vars);
        continue;
      }
      step("face", vars);
      if (!s.J) {
        step("face_away");
        continue;
      }
      step("face_cross", vars);
      const int a = (s.face.axis + 1) % 3, b = (s.face.axis + 2) % 3;
      step(hit_here ? "face_on" : "face_off", {{"a", kAxis[std::min(a, b)]}, {"b", kAxis[std::max(a, b)]}});
    }
    if (rc.hit) {
      step(rc.inside ? "exit" : "hit", {{"face", std::string(geo::face_name(*rc.face))},
                                         {"t", value("t")},
                                         {"I", point(kI)},
                                         {"N", N.point(rc.hit->N.x, rc.hit->N.y, rc.hit->N.z)}});
    } else {
      step("miss");
    }
    inst.key.add(render::Figure{key_scene(d, rc, faces, ctx), 0.95});
    add_lines(inst.key, q);
    return inst;
  }

  // The cube's 12 edges, the back ones dashed.
  static void add_cube(render::Panel& panel, const render::Camera& cam, const render::AlignedBox& box) {
    for (int axis = 0; axis < 3; ++axis)
      for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
          double a[3], b[3];
          a[axis] = -1, b[axis] = 1;
          a[(axis + 1) % 3] = b[(axis + 1) % 3] = s1;
          a[(axis + 2) % 3] = b[(axis + 2) % 3] = s2;
          render::add_segment(panel, cam, {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, render::Role::data, box);
        }
  }

  static std::vector<render::P3> face_corners(Face f) {
    std::vector<render::P3> out;
    const int a = (f.axis + 1) % 3, b = (f.axis + 2) % 3;
    const double sa[] = {-1, 1, 1, -1}, sb[] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
      double c[3];
      c[f.axis] = f.sign, c[a] = sa[k], c[b] = sb[k];
      out.push_back({c[0], c[1], c[2]});
    }
    return out;
  }

  static render::Panel view(const Data& d, const render::Camera& cam, double reach,
                            const std::vector<FaceInPlay>* shaded) {
    using render::Role;
    using space::p3;
    const Vec3 uh = d.u / geo::norm(d.u);
    const Point3 end = d.A + reach * uh;
    const render::AlignedBox box{{-1, -1, -1}, {1, 1, 1}};
    render::Panel panel = space::view_panel(cam, {p3(d.A), p3(end), {1, 1, 1}, {-1, -1, -1}}, 3, 2, box);
    space::add_drop(panel, cam, p3(d.A));
    if (shaded)
      for (const FaceInPlay& s : *shaded) {
        std::vector<render::P2> pts;
        for (const auto& c : face_corners(s.face)) pts.push_back(cam.project(c));
        panel.add(render::Polygon{pts, true, Role::highlight, true});
      }
    add_cube(panel, cam, box);
    render::add_segment(panel, cam, p3(d.A), p3(end), Role::data, box);
    panel.add(render::Arrow{cam.project(p3(d.A)), cam.project(p3(d.A + uh)), Role::construction});
    panel.add(render::Label{"û", cam.project(p3(d.A + uh)), render::Side::auto_, Role::construction});
    panel.add(render::PointMark{cam.project(p3(d.A)), Role::data, render::Label{"A", cam.project(p3(d.A))}});
    return panel;
  }

  static double reach_of(const Data& d) { return geo::norm(geo::to_vec(d.A)) + 2.5; }

  render::Scene question_scene(const Data& d, const ExerciseContext& ctx) const {
    render::Scene s;
    s.title = ctx.texts.get("ray_cube.title");
    s.description = ctx.texts.get("ray_cube.figure.question");
    render::Panel panel = view(d, space::camera(), reach_of(d), nullptr);
    panel.caption = ctx.texts.get("ray_cube.figure.view");
    s.panels.push_back(std::move(panel));
    return s;
  }

  // A face drawn flat in its own plane, axes (a, b) the two other coordinates in order: with I
  // and N (perpendicular to the plane, towards the reader) when it is the face hit, else where
  // the ray meets the plane off the face.
  static render::Panel flat_face(Face f, std::optional<Point3> point, bool hit, const ExerciseContext& ctx) {
    using render::P2;
    using render::Role;
    const auto& T = ctx.texts;
    const int a = std::min((f.axis + 1) % 3, (f.axis + 2) % 3), b = std::max((f.axis + 1) % 3, (f.axis + 2) % 3);
    render::Panel panel;
    std::vector<P2> pts = {{-1, -1}, {1, 1}};
    std::optional<P2> J;
    if (point) J = P2{coord(*point, a), coord(*point, b)};
    if (J) pts.push_back(*J);
    panel.view = view_around(pts, 0.8, 3.0);
    panel.add(render::Grid{1, false});
    panel.add(render::Polygon{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, true, Role::highlight, true});
    panel.add(render::Label{kAxis[a], {panel.view.x_max - 0.2, 0}, render::Side::above, Role::construction});
    panel.add(render::Label{kAxis[b], {0, panel.view.y_max - 0.2}, render::Side::right, Role::construction});
    if (J) {
      if (hit) {
        panel.add(render::PointMark{*J, Role::result, render::Label{"I", *J, render::Side::auto_, Role::result}});
        panel.add(render::Circle{*J, 0.18, Role::normal});
        panel.add(render::Label{T.get("ray_cube.figure.N_out"), {J->x + 0.18, J->y - 0.18}, render::Side::below_right,
                                Role::normal});
      } else {
        panel.add(render::PointMark{*J, Role::construction,
                                    render::Label{"J", *J, render::Side::auto_, Role::construction}});
      }
    }
    panel.caption = T.format("ray_cube.figure.face", {{"face", std::string(geo::face_name(f))},
                                                      {"c", kAxis[f.axis]},
                                                      {"v", f.sign > 0 ? "1" : "−1"}});
    return panel;
  }

  render::Scene key_scene(const Data& d, const geo::RayCube& rc, const std::vector<FaceInPlay>& faces,
                          const ExerciseContext& ctx) const {
    using render::P2;
    using render::Role;
    using space::p3;
    const auto& T = ctx.texts;
    const render::Camera cam = space::camera();
    render::Scene s;
    s.title = T.get("ray_cube.title");
    s.description = T.get(fmt::format("ray_cube.figure.key.{}", branch_of(rc)));
    render::Panel v3 = view(d, cam, reach_of(d), &faces);
    for (const FaceInPlay& f : faces)
      if (f.J && !(rc.face && *rc.face == f.face))
        v3.add(render::PointMark{cam.project(p3(*f.J)), Role::construction,
                                 render::Label{"J", cam.project(p3(*f.J)), render::Side::auto_, Role::construction}});
    if (rc.hit) {
      const P2 I = cam.project(p3(rc.hit->I)), tip = cam.project(p3(rc.hit->I + rc.hit->N));
      v3.add(render::PointMark{I, Role::result, render::Label{"I", I, render::Side::auto_, Role::result}});
      v3.add(render::Arrow{I, tip, Role::normal});
      v3.add(render::Label{T.get("ray_cube.figure.N"), tip, render::Side::auto_, Role::normal});
    }
    v3.caption = T.get("ray_cube.figure.view");
    s.panels.push_back(std::move(v3));
    if (rc.hit) {
      s.panels.push_back(flat_face(*rc.face, rc.hit->I, true, ctx));
      s.links = {T.get("ray_cube.figure.link")};
    } else {
      // a miss: the first face tried that the ray's line crosses, off the face
      for (const FaceInPlay& f : faces)
        if (f.J) {
          s.panels.push_back(flat_face(f.face, f.J, false, ctx));
          s.links = {T.get("ray_cube.figure.link")};
          break;
        }
    }
    return s;
  }
};

}  // namespace

const ExerciseKind& ray_cube_kind() {
  static const RayCubeKind kind;
  return kind;
}

}  // namespace epure::kinds
