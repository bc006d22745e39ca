#include "render/scene_painter.h"

#include <algorithm>
#include <map>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "render/font_metrics.h"
#include "render/text.h"
#include "support/portable.h"

namespace epure::render {
namespace {

// Layout of a scene, points.
constexpr double kPanelGap = 14;  // between two panels with no link
constexpr double kLinkPad = 6;    // around a link's text and arrow
constexpr double kMinLinkGap = 40;
constexpr double kMaxLinkShare = 0.3;  // of the scene's width, for one link
constexpr double kCaptionGap = 4;      // between a panel and its caption
constexpr double kLineSpacing = 1.25;  // × font size, captions and links

// Circles and ellipses become polylines of this many sides as label obstacles: at the radii of
// a worksheet (< 200 pt) the chord strays less than 0.25 pt from the curve, inside the
// clearance a label keeps anyway.
constexpr int kCurveSides = 64;
// A quarter circle as one cubic Bézier: control points at 4/3 (√2 − 1) of the radius.
constexpr double kKappa = 0.5522847498307936;

// A ray's arrowhead stays this far inside the panel, so the clip never cuts its tip.
constexpr double kRayInset = 3;
// Below this length (points) an arrow is drawn without a head: it would be all head.
constexpr double kMinArrow = 1.5;
// An extension line of a dimension leaves this gap at the measured point and runs this far past
// the dimension line.
constexpr double kExtensionGap = 2;
constexpr double kExtensionOver = 2.5;
constexpr double kExtensionWidth = 0.5;
// Marks (right angle, tick) are drawn solid and at most this thick, whatever their role's dash:
// a dashed 7 pt square reads as noise.
constexpr double kMarkWidth = 0.9;
// A point's disc has a white rim so that lines passing under it stay apart from it.
constexpr double kPointRim = 0.8;
// Behind a label: the grid hidden, a faint fill still showing through.
constexpr double kLabelBackgroundOpacity = 0.85;
constexpr double kLabelBackgroundPad = 0.6;
// Between two labels side by side, at least this × their size (each keeps half): more than
// the gap at which a PDF's text extraction joins letters into one word (a tenth of an em).
constexpr double kWordSpace = 0.3;
// A leader from a label set far from its point: thin, so that it reads as a pointer, not a line
// of the figure.
constexpr double kLeaderWidth = 0.4;
// Axis numbers: their distance from the axis, and the least room between two of them.
constexpr double kNumberGap = 2.5;
constexpr double kNumberSpacing = 4;
// The axes' own arrowheads, smaller than a vector's.
constexpr double kAxisArrow = 5;

constexpr double kInf = std::numeric_limits<double>::infinity();

P2 add(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 sub(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 mul(double k, P2 a) { return {k * a.x, k * a.y}; }
double norm(P2 v) { return portable::hypot(v.x, v.y); }
P2 perp(P2 v) { return {-v.y, v.x}; }  // a quarter turn (counter-clockwise in math space)
std::optional<P2> unit(P2 v) {
  const double n = norm(v);
  if (n == 0 || !std::isfinite(n)) return std::nullopt;  // zero direction: nothing to draw
  return P2{v.x / n, v.y / n};
}

// Parameter range [t0, t1] ⊂ [t_lo, t_hi] of p + t d inside `box` (Liang–Barsky), or nothing.
std::optional<std::pair<double, double>> clip(P2 p, P2 d, double t_lo, double t_hi,
                                              const Box& box) {
  const double pd[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {p.x - box.x_min, box.x_max - p.x, p.y - box.y_min, box.y_max - p.y};
  for (int i = 0; i < 4; ++i) {
    if (pd[i] == 0) {  // parallel to this edge
      if (q[i] < 0) return std::nullopt;
      continue;
    }
    const double t = q[i] / pd[i];
    if (pd[i] < 0) {
      t_lo = std::max(t_lo, t);
    } else {
      t_hi = std::min(t_hi, t);
    }
  }
  if (!(t_lo < t_hi)) return std::nullopt;
  return std::pair{t_lo, t_hi};
}

std::string_view role_name(Role r) {
  switch (r) {
    case Role::data: return "data";
    case Role::construction: return "construction";
    case Role::result: return "result";
    case Role::normal: return "normal";
    case Role::muted: return "muted";
    case Role::highlight: return "highlight";
    case Role::given: return "given";
  }
  return "data";
}

// Drawing order: context under the figure, the answer on top.
constexpr std::array<Role, 7> kLayerOrder = {Role::muted, Role::construction, Role::highlight, Role::data,
                                             Role::normal, Role::result,      Role::given};

P2 side_direction(Side s) {
  switch (s) {
    case Side::auto_: return {0, 0};
    case Side::above: return {0, -1};
    case Side::below: return {0, 1};
    case Side::left: return {-1, 0};
    case Side::right: return {1, 0};
    case Side::above_left: return {-1, -1};
    case Side::above_right: return {1, -1};
    case Side::below_left: return {-1, 1};
    case Side::below_right: return {1, 1};
  }
  return {0, 0};
}

// A grid number as printed: at most two decimals, no trailing zeros, a true minus sign.
std::string axis_number(double v) {
  char buf[32];
  std::string_view s;
  if (const double a = std::abs(v); a == std::trunc(a) && a < 1e15) {
    // most grid numbers are whole: their digits, as fmt's would be once trimmed, without it
    char* p = std::end(buf);
    for (auto n = static_cast<long long>(a); p == std::end(buf) || n != 0; n /= 10) *--p = static_cast<char>('0' + n % 10);
    s = std::string_view(p, static_cast<std::size_t>(std::end(buf) - p));
  } else {
    // fmt's fixed format is exact, as std::to_chars's is (portable.h: not every libc++ has it)
    const auto r = fmt::format_to_n(buf, sizeof buf, "{:.2f}", a);
    s = std::string_view(buf, static_cast<std::size_t>(r.out - buf));
    while (s.back() == '0') s.remove_suffix(1);
    if (s.back() == '.') s.remove_suffix(1);
  }
  if (s == "0" || v > 0) return std::string(s);
  return "\u2212" + std::string(s);
}

std::vector<TextRun> plain_runs(std::string text) {
  std::vector<TextRun> runs;
  runs.push_back(TextRun{std::move(text), Shift::none, false, false});
  return runs;
}

struct Op {
  Path path;
  Paint paint;
  std::optional<std::pair<P2, double>> disc;  // drawn as a disc instead of the path
};

struct PendingLabel {
  int priority;      // ticks first (they line up along their stroke), then names, then dimensions
  std::string text;  // the rich text, for the report
  std::vector<TextRun> runs;
  TextExtent extent;
  double size;
  Colour colour;
  LabelRequest request;
};

struct Number {
  std::vector<TextRun> runs;
  P2 at;
  Anchor anchor;
  double size;
  Box box;
  int axis;    // 0: x, 1: y, 2: the origin's 0
  long index;  // of its grid line
};

class PanelPainter {
 public:
  PanelPainter(Canvas& canvas, const Panel& panel, const Box& rect, const Style& style)
      : canvas_(canvas), panel_(panel), frame_(panel.view, rect), style_(style) {}

  PanelReport paint() {
    for (const Item& it : panel_.items) std::visit([&](const auto& i) { this->item(i); }, it);
    for (const Item& item : panel_.items) {
      if (const auto* g = std::get_if<Grid>(&item)) add_grid(*g);
    }

    std::stable_sort(
        labels_.begin(), labels_.end(),
        [](const PendingLabel& a, const PendingLabel& b) { return a.priority < b.priority; });
    PanelReport report;
    report.area = frame_.rect();
    std::vector<LabelRequest> requests;
    for (const PendingLabel& l : labels_) requests.push_back(l.request);
    report.labels = place_labels(requests, obstacles_, frame_.rect());
    for (const PendingLabel& l : labels_) report.texts.push_back(l.text);
    drop_crowded_numbers(report.labels);
    emit(report.labels);
    report.obstacles = std::move(obstacles_);
    return report;
  }

 private:
  // ---- items ----

  void item(const Grid&) {}  // after the other items: its numbers make way for their strokes

  void item(const Label& l) { request_label(l, l.anchor, style_.label_gap, style_.label_size); }

  void item(const PointMark& m) {
    const RoleStyle& rs = style_.of(m.role);
    const P2 c = frame_.to_page(m.at);
    Op op;
    op.paint.fill = rs.colour;
    op.paint.stroke = StrokeStyle{style_.background, kPointRim, {}};
    op.disc = std::pair{c, rs.point_radius};
    points_[index(m.role)].push_back(std::move(op));
    obstacles_.discs.push_back({c, rs.point_radius + kPointRim / 2});
    if (m.label)
      request_label(*m.label, m.at, rs.point_radius + style_.label_gap, style_.label_size);
  }

  void item(const Segment& s) {
    const RoleStyle& rs = style_.of(s.role);
    stroke_segment(frame_.to_page(s.a), frame_.to_page(s.b), s.role,
                   s.dashed ? kForcedDash : rs.dash);
  }

  void item(const Line& l) {
    const P2 d = sub(l.b, l.a);
    if (!unit(d)) return;  // a and b coincide: no line
    const auto range = clip(l.a, d, -kInf, kInf, frame_.view());
    if (!range) return;
    stroke_segment(frame_.to_page(add_p(l.a, range->first, d)),
                   frame_.to_page(add_p(l.a, range->second, d)), l.role, style_.of(l.role).dash);
  }

  void item(const Ray& r) {
    if (!unit(r.dir)) return;  // zero direction: no ray
    const double inset = kRayInset / frame_.scale();
    const Box& v = frame_.view();
    const Box inner{v.x_min + inset, v.y_min + inset, v.x_max - inset, v.y_max - inset};
    const auto range = clip(r.origin, r.dir, 0, kInf, inner);
    if (!range) return;
    const P2 start = add_p(r.origin, range->first, r.dir), end = add_p(r.origin, range->second, r.dir);
    // the hit's parameter along the ray, in steps of dir as the clip's
    double t_hit = kInf;
    if (r.followed_to) {
      const P2 to_hit = sub(*r.followed_to, r.origin);
      t_hit = (to_hit.x * r.dir.x + to_hit.y * r.dir.y) / (r.dir.x * r.dir.x + r.dir.y * r.dir.y);
    }
    if (!(t_hit < range->second)) {  // no hit, or past the view: the ray as far as it is seen
      arrow(frame_.to_page(start), frame_.to_page(end), r.role);
      return;
    }
    // solid up to the hit, muted past it
    const P2 hit = add_p(r.origin, std::max(t_hit, range->first), r.dir);
    stroke_segment(frame_.to_page(start), frame_.to_page(hit), r.role, style_.of(r.role).dash);
    arrow(frame_.to_page(hit), frame_.to_page(end), Role::muted);
  }

  void item(const Arrow& a) { arrow(frame_.to_page(a.from), frame_.to_page(a.to), a.role); }

  void item(const Circle& c) {
    if (!(c.r > 0)) return;
    add_conic(c.c, {c.r, 0}, {0, c.r}, c.role);
  }

  void item(const Ellipse& e) {
    if (!(e.rx > 0) || !(e.ry > 0)) return;
    const double a = e.angle_deg * std::numbers::pi / 180;
    const P2 e1{std::cos(a), std::sin(a)};
    add_conic(e.c, mul(e.rx, e1), mul(e.ry, perp(e1)), e.role);
  }

  void item(const Polygon& p) {
    if (p.points.size() < 2) return;
    std::vector<P2> pts;
    for (P2 m : p.points) pts.push_back(frame_.to_page(m));
    Path path;
    path.move_to(pts[0]);
    for (std::size_t i = 1; i < pts.size(); ++i) path.line_to(pts[i]);
    if (p.closed) path.close();
    const RoleStyle& rs = style_.of(p.role);
    Op op{std::move(path), stroke_paint(p.role, rs.dash), std::nullopt};
    if (p.filled && p.closed) {
      op.paint.fill = rs.colour;
      op.paint.fill_opacity = style_.fill_opacity;
    }
    strokes_[index(p.role)].push_back(std::move(op));
    obstacles_.add_polyline(pts, p.closed, rs.width / 2);
  }

  void item(const RightAngle& r) {
    const auto u1 = unit(frame_.dir_to_page(r.d1));
    const auto u2 = unit(frame_.dir_to_page(r.d2));
    if (!u1 || !u2) return;
    const double a = style_.right_angle_size;
    const P2 v = frame_.to_page(r.vertex);
    const P2 p1 = add(v, mul(a, *u1)), p2 = add(v, mul(a, *u2));
    const P2 corner = add(p1, mul(a, *u2));
    Path path;
    path.move_to(p1).line_to(corner).line_to(p2);
    strokes_[index(r.role)].push_back({std::move(path), mark_paint(r.role), std::nullopt});
    obstacles_.add_polyline({p1, corner, p2}, false, mark_paint(r.role).stroke->width / 2);
  }

  void item(const Tick& t) {
    const auto u = unit(frame_.dir_to_page(t.along));
    if (!u) return;
    const P2 at = frame_.to_page(t.at);
    P2 n = perp(*u);
    // Its text goes below the line (or to its right when the line is vertical).
    if (n.y < 0 || (std::abs(n.y) < 1e-9 && n.x < 0)) n = mul(-1, n);
    const double h = style_.tick_half_length;
    const P2 a = add(at, mul(-h, n)), b = add(at, mul(h, n));
    Path path;
    path.move_to(a).line_to(b);
    strokes_[index(t.role)].push_back({std::move(path), mark_paint(t.role), std::nullopt});
    obstacles_.segments.push_back({a, b, mark_paint(t.role).stroke->width / 2});
    if (t.text) {
      pending(0, *t.text, style_.small_size, style_.of(t.role).text, at, n, h + style_.label_gap,
              *u);
    }
  }

  void item(const Dimension& d) {
    const auto n_math = unit(perp(sub(d.b, d.a)));
    if (!n_math) return;
    const RoleStyle& rs = style_.of(d.role);
    const P2 a = frame_.to_page(d.a), b = frame_.to_page(d.b);
    const P2 a2 = frame_.to_page(add(d.a, mul(d.offset, *n_math)));
    const P2 b2 = frame_.to_page(add(d.b, mul(d.offset, *n_math)));
    const P2 n_page = *unit(frame_.dir_to_page(*n_math));
    const P2 out = d.offset < 0 ? mul(-1, n_page) : n_page;  // from the measured side outwards
    if (norm(sub(a2, a)) > kExtensionGap + 1) {
      for (auto [p, q] : {std::pair{a, a2}, std::pair{b, b2}}) {
        const P2 from = add(p, mul(kExtensionGap, out)), to = add(q, mul(kExtensionOver, out));
        Path path;
        path.move_to(from).line_to(to);
        strokes_[index(d.role)].push_back(
            {std::move(path), Paint{StrokeStyle{rs.colour, kExtensionWidth, {}}, std::nullopt, 1},
             std::nullopt});
        obstacles_.segments.push_back({from, to, kExtensionWidth / 2});
      }
    }
    // Solid, with a head at each end pointing outwards.
    const double head = style_.dimension_arrow;
    const P2 dir = sub(b2, a2);
    const double len = norm(dir);
    const Paint paint{StrokeStyle{rs.colour, std::min(rs.width, kMarkWidth), {}}, std::nullopt, 1};
    if (len > 2.5 * head) {
      const P2 u = mul(1 / len, dir);
      Path shaft;
      shaft.move_to(add(a2, mul(head * 0.7, u))).line_to(add(b2, mul(-head * 0.7, u)));
      strokes_[index(d.role)].push_back({std::move(shaft), paint, std::nullopt});
      head_at(b2, u, head, head * 0.36, d.role);
      head_at(a2, mul(-1, u), head, head * 0.36, d.role);
    } else {
      Path shaft;
      shaft.move_to(a2).line_to(b2);
      strokes_[index(d.role)].push_back({std::move(shaft), paint, std::nullopt});
    }
    obstacles_.segments.push_back({a2, b2, paint.stroke->width / 2});
    pending(2, d.text, style_.small_size, rs.text, mul(0.5, add(a2, b2)), out, style_.label_gap,
            dir);
  }

  void add_grid(const Grid& g) {
    if (!(g.step > 0)) return;
    const Box& v = frame_.view();
    const double step = g.step;
    // Index range of the grid lines inside the view, a hair of tolerance at the edges.
    const auto range = [&](double lo, double hi) {
      constexpr double kEdge = 1e-9;
      return std::pair{static_cast<long>(std::ceil(lo / step - kEdge)),
                       static_cast<long>(std::floor(hi / step + kEdge))};
    };
    const auto [i0, i1] = range(v.x_min, v.x_max);
    const auto [j0, j1] = range(v.y_min, v.y_max);
    const Paint grid{StrokeStyle{style_.grid, style_.grid_width, {}}, std::nullopt, 1};
    Path lines;
    for (long i = i0; i <= i1; ++i) {
      lines.move_to(frame_.to_page({i * step, v.y_min}))
          .line_to(frame_.to_page({i * step, v.y_max}));
    }
    for (long j = j0; j <= j1; ++j) {
      lines.move_to(frame_.to_page({v.x_min, j * step}))
          .line_to(frame_.to_page({v.x_max, j * step}));
    }
    grid_.push_back({std::move(lines), grid, std::nullopt});
    if (!g.numbered_axes) return;

    // The axes through the origin when it is inside the view (an axis on the frame would hide
    // under it); otherwise numbers along the panel's bottom and left edges.
    const Box& r = frame_.rect();
    const P2 o = frame_.to_page({0, 0});
    const bool x_axis = o.y > r.y_min + kAxisArrow && o.y < r.y_max - kAxisArrow;
    const bool y_axis = o.x > r.x_min + kAxisArrow && o.x < r.x_max - kAxisArrow;
    const Paint axis{StrokeStyle{style_.axis, style_.axis_width, {}}, std::nullopt, 1};
    const double axis_y = x_axis ? o.y : r.y_max;
    const double axis_x = y_axis ? o.x : r.x_min;
    if (x_axis) axis_line({r.x_min, axis_y}, {r.x_max - 1, axis_y}, axis);
    if (y_axis) axis_line({axis_x, r.y_max}, {axis_x, r.y_min + 1}, axis);

    const double size = style_.number_size;
    const VerticalMetrics vm = vertical_metrics();
    const double cap = vm.cap_height * size;
    // Every k-th line is numbered, k as small as keeps the numbers apart.
    double widest = 0;
    for (long i = std::min(i0, j0); i <= std::max(i1, j1); ++i) {
      widest = std::max(widest, text_width(axis_number(i * step), size));
    }
    const double pitch = step * frame_.scale();
    const long kx = std::max(1L, static_cast<long>(std::ceil((widest + kNumberSpacing) / pitch)));
    const long ky = std::max(1L, static_cast<long>(std::ceil((cap + kNumberSpacing) / pitch)));
    // Numbers below the x-axis and left of the y-axis, unless the panel ends there.
    const bool below = axis_y + kNumberGap + cap + vm.descent * size < r.y_max;
    const bool left = axis_x - kNumberGap - widest > r.x_min;
    const double x_baseline = below ? axis_y + kNumberGap + cap : axis_y - kNumberGap;
    const double y_edge = left ? axis_x - kNumberGap : axis_x + kNumberGap;
    every_[0] = kx;
    every_[1] = ky;
    for (long i = i0; i <= i1; ++i) {
      if (i == 0 && y_axis) continue;
      number(axis_number(i * step), {frame_.to_page({i * step, 0}).x, x_baseline}, Anchor::middle,
             size, 0, i);
    }
    for (long j = j0; j <= j1; ++j) {
      if (j == 0 && x_axis) continue;
      const double py = frame_.to_page({0, j * step}).y;
      number(axis_number(j * step), {y_edge, py + cap / 2}, left ? Anchor::end : Anchor::start,
             size, 1, j);
    }
    if (x_axis && y_axis) {  // one 0 for both axes, in the corner the numbers are on
      number("0", {y_edge, x_baseline}, left ? Anchor::end : Anchor::start, size, 2, 0);
    }
  }

  // ---- helpers ----

  static std::size_t index(Role r) { return static_cast<std::size_t>(r); }
  static P2 add_p(P2 p, double t, P2 d) { return {p.x + t * d.x, p.y + t * d.y}; }

  Paint stroke_paint(Role role, const std::vector<double>& dash) const {
    const RoleStyle& rs = style_.of(role);
    return Paint{StrokeStyle{rs.colour, rs.width, dash}, std::nullopt, 1};
  }
  Paint mark_paint(Role role) const {
    const RoleStyle& rs = style_.of(role);
    return Paint{StrokeStyle{rs.colour, std::min(rs.width, kMarkWidth), {}}, std::nullopt, 1};
  }

  void stroke_segment(P2 a, P2 b, Role role, const std::vector<double>& dash) {
    Path path;
    path.move_to(a).line_to(b);
    strokes_[index(role)].push_back({std::move(path), stroke_paint(role, dash), std::nullopt});
    obstacles_.segments.push_back({a, b, style_.of(role).width / 2});
  }

  // A filled arrowhead with its tip at `tip`, pointing along unit `u`.
  void head_at(P2 tip, P2 u, double length, double half_width, Role role) {
    const P2 base = add(tip, mul(-length, u));
    const P2 n = perp(u);
    const P2 l = add(base, mul(half_width, n)), r = add(base, mul(-half_width, n));
    Path path;
    path.move_to(tip).line_to(l).line_to(r).close();
    strokes_[index(role)].push_back(
        {std::move(path), Paint{std::nullopt, style_.of(role).colour, 1}, std::nullopt});
    obstacles_.add_polyline({tip, l, r}, true);
  }

  // A shaft from `from` to `to` with a head at `to`; the shaft stops inside the head so that its
  // end never shows past the tip.
  void arrow(P2 from, P2 to, Role role) {
    const P2 d = sub(to, from);
    const double len = norm(d);
    if (len < kMinArrow) return;
    const P2 u = mul(1 / len, d);
    const double head = std::min(style_.arrow_length, len * 0.6);
    const RoleStyle& rs = style_.of(role);
    stroke_segment(from, add(to, mul(-head * 0.7, u)), role, rs.dash);
    obstacles_.segments.back().b = to;
    head_at(to, u, head, style_.arrow_half_width * head / style_.arrow_length, role);
  }

  // The conic c + cos θ·e1 + sin θ·e2 (a circle or an ellipse): four cubic arcs, mapped to the
  // page point by point (the map is affine, so the arcs stay exact).
  void add_conic(P2 c, P2 e1, P2 e2, Role role) {
    const auto at = [&](double cs, double sn) {
      return frame_.to_page(add(c, add(mul(cs, e1), mul(sn, e2))));
    };
    Path path;
    path.move_to(at(1, 0));
    const double q[5][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 0}};
    for (int k = 0; k < 4; ++k) {
      const double c0 = q[k][0], s0 = q[k][1], c1 = q[k + 1][0], s1 = q[k + 1][1];
      // Tangent at angle θ is (−sin θ, cos θ) in the (e1, e2) frame.
      path.cubic_to(at(c0 - kKappa * s0, s0 + kKappa * c0), at(c1 + kKappa * s1, s1 - kKappa * c1),
                    at(c1, s1));
    }
    path.close();
    strokes_[index(role)].push_back(
        {std::move(path), stroke_paint(role, style_.of(role).dash), std::nullopt});
    std::vector<P2> pts;
    for (int k = 0; k < kCurveSides; ++k) {
      const double t = 2 * std::numbers::pi * k / kCurveSides;
      pts.push_back(at(std::cos(t), std::sin(t)));
    }
    obstacles_.add_polyline(pts, true, style_.of(role).width / 2);
  }

  void axis_line(P2 from, P2 to, const Paint& paint) {
    const auto u = unit(sub(to, from));
    if (!u) return;
    Path path;
    path.move_to(from).line_to(add(to, mul(-kAxisArrow * 0.7, *u)));
    grid_.push_back({std::move(path), paint, std::nullopt});
    const P2 base = add(to, mul(-kAxisArrow, *u));
    const P2 n = perp(*u);
    Path head;
    head.move_to(to)
        .line_to(add(base, mul(kAxisArrow * 0.36, n)))
        .line_to(add(base, mul(-kAxisArrow * 0.36, n)))
        .close();
    grid_.push_back({std::move(head), Paint{std::nullopt, style_.axis, 1}, std::nullopt});
    obstacles_.segments.push_back({from, to, paint.stroke ? paint.stroke->width / 2 : 0});
  }

  void number(std::string text, P2 at, Anchor anchor, double size, int axis, long index) {
    std::vector<TextRun> runs = plain_runs(std::move(text));
    const TextExtent e = text_extent(runs, size);
    const double x0 = anchor == Anchor::start    ? at.x
                      : anchor == Anchor::middle ? at.x - e.width / 2
                                                 : at.x - e.width;
    const Box box{x0, at.y - e.ascent, x0 + e.width, at.y + e.descent};
    numbers_.push_back({std::move(runs), at, anchor, size, box, axis, index});
  }

  void request_label(const Label& l, P2 anchor_math, double gap, double size) {
    pending(1, l.text, size, style_.of(l.role).text, frame_.to_page(anchor_math),
            side_direction(l.side), gap);
  }

  void pending(int priority, const RichText& text, double size, Colour colour, P2 anchor, P2 prefer,
               double gap, P2 along = {0, 0}) {
    PendingLabel l;
    l.priority = priority;
    l.text = text;
    l.runs = parse_rich_text(text);
    if (l.runs.empty()) return;
    l.extent = text_extent(l.runs, size);
    l.size = size;
    l.colour = colour;
    // The type box: each run's font ascent and descent at its own size and shift (a subscript's
    // reaches below the line's).
    const VerticalMetrics vm = vertical_metrics();
    double type_top = 0, type_bottom = 0;
    for (const RunPlacement& p : place_runs(l.runs, size)) {
      type_top = std::max(type_top, p.rise + vm.ascent * p.size);
      type_bottom = std::max(type_bottom, vm.descent * p.size - p.rise);
    }
    l.request = LabelRequest{anchor, l.extent.width, l.extent.ascent + l.extent.descent, prefer,
                             gap,    along,
                             std::max(0.0, type_top - l.extent.ascent),
                             std::max(0.0, type_bottom - l.extent.descent),
                             kWordSpace * size / 2};
    labels_.push_back(std::move(l));
  }

  // Axis numbers give way: one on a label, a point or a stroke of the figure is left out.
  // Axis numbers give way: one on a label, a point or a stroke of the figure is left out. Of
  // every k-th line's number, the phase that keeps the most is taken (0, k, 2k… on a tie), so
  // that a unit circle does not hide the only numbers of a crowded axis.
  void drop_crowded_numbers(const std::vector<Placement>& placed) {
    const Box& r = frame_.rect();
    const auto free = [&](const Number& n) {
      if (n.box.x_min < r.x_min || n.box.x_max > r.x_max || n.box.y_min < r.y_min ||
          n.box.y_max > r.y_max) {
        return false;
      }
      // As far from a label as a label keeps from anything; from a stroke's ink, half that (a
      // number is small and grey, and a grid's numbers are many: most stay).
      const Box b = inflate(n.box, kLabelClearance / 2);
      const Box from_labels = inflate(n.box, kLabelClearance);
      // Its type box (the font's ascent to descent) clear of the labels' type boxes too.
      const VerticalMetrics vm = vertical_metrics();
      const Box type{n.box.x_min, n.at.y - vm.ascent * n.size, n.box.x_max, n.at.y + vm.descent * n.size};
      for (const Placement& p : placed) {
        if (boxes_overlap(from_labels, p.box) || boxes_overlap(type, p.type)) return false;
      }
      for (const auto& d : obstacles_.discs) {
        if (disc_hits_box(d.c, d.r, b)) return false;
      }
      for (const auto& s : obstacles_.segments) {
        if (segment_hits_box(s.a, s.b, inflate(b, s.half_width))) return false;
      }
      return true;
    };
    std::erase_if(numbers_, [&](const Number& n) { return !free(n); });
    const auto phase = [](long i, long k) { return ((i % k) + k) % k; };
    for (int axis = 0; axis < 2; ++axis) {
      // The phase that keeps the most numbers (the smallest of equals, 0 when none is left),
      // counted over the numbers, not over the k phases: on a figure of tiny scale k is huge
      // (the numbers' width over a grid pitch of a hair) and a loop over the phases never ended.
      const long k = every_[axis];
      std::map<long, long> count;
      for (const Number& n : numbers_)
        if (n.axis == axis) ++count[phase(n.index, k)];
      long best = 0, best_count = -1;
      for (const auto& [p, c] : count)
        if (c > best_count) best = p, best_count = c;
      std::erase_if(numbers_,
                    [&](const Number& n) { return n.axis == axis && phase(n.index, k) != best; });
    }
    // Where the x numbers run along the panel's bottom edge and the y numbers up its left one,
    // the first of each meet in the corner: the y number gives way.
    const VerticalMetrics vm = vertical_metrics();
    const auto type_box = [&](const Number& n) {
      return Box{n.box.x_min, n.at.y - vm.ascent * n.size, n.box.x_max, n.at.y + vm.descent * n.size};
    };
    // So does the origin's 0 to an x or y number beside it. (The x numbers are spaced apart.)
    std::vector<Box> kept;
    for (const Number& n : numbers_)
      if (n.axis == 0) kept.push_back(type_box(n));
    for (int axis : {1, 2}) {
      std::erase_if(numbers_, [&](const Number& n) {
        return n.axis == axis && std::any_of(kept.begin(), kept.end(), [&](const Box& k) {
                 return boxes_overlap(type_box(n), k);
               });
      });
      for (const Number& n : numbers_)
        if (n.axis == axis) kept.push_back(type_box(n));
    }
    // Nothing is placed after the numbers; the report lists them with what was drawn.
    for (const Number& n : numbers_) obstacles_.boxes.push_back(n.box);
  }

  void emit(const std::vector<Placement>& placed) {
    canvas_.begin_group("panel", "panel");
    const Box& r = frame_.rect();
    Path frame_path;
    frame_path.move_to({r.x_min, r.y_min})
        .line_to({r.x_max, r.y_min})
        .line_to({r.x_max, r.y_max})
        .line_to({r.x_min, r.y_max})
        .close();

    canvas_.push_clip(r);
    if (!grid_.empty() || !numbers_.empty()) {
      canvas_.begin_group("grid");
      for (const Op& op : grid_) draw(op);
      for (const Number& n : numbers_) canvas_.text(TextLine{n.at, n.anchor, n.size, n.runs, style_.numbers});
      canvas_.end_group();
    }
    for (Role role : kLayerOrder) {
      if (strokes_[index(role)].empty()) continue;
      canvas_.begin_group(role_name(role));
      for (const Op& op : strokes_[index(role)]) draw(op);
      canvas_.end_group();
    }
    for (Role role : kLayerOrder) {
      if (points_[index(role)].empty()) continue;
      canvas_.begin_group(fmt::format("points {}", role_name(role)));
      for (const Op& op : points_[index(role)]) draw(op);
      canvas_.end_group();
    }
    canvas_.pop_clip();
    canvas_.path(frame_path,
                 Paint{StrokeStyle{style_.frame, style_.frame_width, {}}, std::nullopt, 1});

    if (!labels_.empty()) {
      canvas_.begin_group("labels");
      for (std::size_t i = 0; i < labels_.size(); ++i) {
        if (placed[i].leader) draw_leader(labels_[i], placed[i].box);
        draw_label(labels_[i], placed[i].box);
      }
      canvas_.end_group();
    }
    canvas_.end_group();
  }

  void draw(const Op& op) {
    if (op.disc) {
      canvas_.disc(op.disc->first, op.disc->second, op.paint);
    } else {
      canvas_.path(op.path, op.paint);
    }
  }

  // A thin line from a far label's anchor to its box, stopping short of both.
  void draw_leader(const PendingLabel& l, const Box& box) {
    const P2 a = l.request.anchor;
    const Box bg = inflate(box, kLabelBackgroundPad);
    const P2 end{std::clamp(a.x, bg.x_min, bg.x_max), std::clamp(a.y, bg.y_min, bg.y_max)};
    const auto u = unit(sub(end, a));
    if (!u || norm(sub(end, a)) <= l.request.gap) return;
    Path path;
    path.move_to(add(a, mul(l.request.gap, *u))).line_to(end);
    canvas_.path(path, Paint{StrokeStyle{l.colour, kLeaderWidth, {}}, std::nullopt, 1});
  }

  void draw_label(const PendingLabel& l, const Box& box) {
    const Box bg = inflate(box, kLabelBackgroundPad);
    Path back;
    back.move_to({bg.x_min, bg.y_min})
        .line_to({bg.x_max, bg.y_min})
        .line_to({bg.x_max, bg.y_max})
        .line_to({bg.x_min, bg.y_max})
        .close();
    canvas_.path(back, Paint{std::nullopt, style_.background, kLabelBackgroundOpacity});
    const double baseline = box.y_min + l.extent.ascent;
    const double x0 = box.x_min;
    canvas_.text(TextLine{
        {(box.x_min + box.x_max) / 2, baseline}, Anchor::middle, l.size, l.runs, l.colour});
    draw_vec_arrows(canvas_, l.runs, x0, baseline, l.size, l.colour);
  }

 public:
  // The arrows of the \vec runs of a line set from (x0, baseline).
  static void draw_vec_arrows(Canvas& canvas, std::span<const TextRun> runs, double x0,
                              double baseline, double size, Colour colour) {
    const std::vector<RunPlacement> placed = place_runs(runs, size);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (!runs[i].arrow) continue;
      const RunPlacement& p = placed[i];
      const double y = baseline - (p.rise + p.top + kArrowGap * p.size);
      const double left = x0 + p.x + 0.06 * p.size, right = x0 + p.x + p.width - 0.02 * p.size;
      const double head = kArrowHead * p.size, half = kArrowHeadHalf * p.size;
      Path shaft;
      shaft.move_to({left, y}).line_to({right - head * 0.6, y});
      canvas.path(shaft, Paint{StrokeStyle{colour, kArrowStroke * p.size, {}}, std::nullopt, 1});
      Path tip;
      tip.move_to({right, y})
          .line_to({right - head, y - half})
          .line_to({right - head, y + half})
          .close();
      canvas.path(tip, Paint{std::nullopt, colour, 1});
    }
  }

 private:
  Canvas& canvas_;
  const Panel& panel_;
  Frame frame_;
  const Style& style_;
  Obstacles obstacles_;
  std::vector<Op> grid_;
  std::array<std::vector<Op>, kLayerOrder.size()> strokes_;
  std::array<std::vector<Op>, kLayerOrder.size()> points_;
  std::vector<PendingLabel> labels_;
  std::vector<Number> numbers_;
  std::array<long, 2> every_{1, 1};  // number every k-th grid line, on x and y
};

// Lines of a caption or link text, centred on `centre_x`, the first baseline at `baseline`.
void centred_lines(Canvas& canvas, const std::vector<std::vector<TextRun>>& lines, double centre_x,
                   double baseline, double size, Colour colour) {
  for (const auto& runs : lines) {
    canvas.text(TextLine{{centre_x, baseline}, Anchor::middle, size, runs, colour});
    PanelPainter::draw_vec_arrows(canvas, runs, centre_x - text_width(runs, size) / 2, baseline,
                                  size, colour);
    baseline += size * kLineSpacing;
  }
}

double caption_height(const std::string& caption, double width, const Style& style) {
  if (caption.empty()) return 0;
  const auto lines = wrap_rich_text(caption, style.small_size, width);
  return kCaptionGap + static_cast<double>(lines.size()) * style.small_size * kLineSpacing;
}

}  // namespace

Frame::Frame(const Box& view, const Box& rect) : view_(view), rect_(rect) {
  const double sx = view.width() > 0 ? rect.width() / view.width() : 1;
  const double sy = view.height() > 0 ? rect.height() / view.height() : 1;
  scale_ = std::min(sx, sy);
  origin_ = {rect.x_min + (rect.width() - view.width() * scale_) / 2,
             rect.y_min + (rect.height() - view.height() * scale_) / 2};
}

P2 Frame::to_page(P2 m) const {
  return {origin_.x + (m.x - view_.x_min) * scale_, origin_.y + (view_.y_max - m.y) * scale_};
}

P2 Frame::dir_to_page(P2 v) const {
  const P2 o = to_page({view_.x_min, view_.y_max});
  const P2 p = to_page({view_.x_min + v.x, view_.y_max + v.y});
  return {p.x - o.x, p.y - o.y};
}

SceneLayout layout_scene(const Scene& scene, double x, double y, double width, const Style& style) {
  SceneLayout out;
  const std::size_t n = scene.panels.size();
  if (n == 0) return out;
  std::vector<double> gaps;
  double gap_sum = 0;
  std::vector<std::string_view> notes;  // the links set under the captions
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const std::string_view link =
        i < scene.links.size() ? std::string_view(scene.links[i]) : std::string_view();
    double g = kPanelGap;
    bool on_arrow = true;
    if (!link.empty()) {
      const double one_line = text_width(link, style.small_size) + 2 * kLinkPad;
      on_arrow = one_line <= kMaxLinkShare * width;
      g = on_arrow ? std::max(one_line, kMinLinkGap) : kMinLinkGap;
      if (!on_arrow) notes.push_back(link);
    }
    gaps.push_back(g);
    gap_sum += g;
    out.link_on_arrow.push_back(on_arrow);
  }
  double aspects = 0;
  for (const Panel& p : scene.panels) {
    aspects += p.view.width() > 0 && p.view.height() > 0 ? p.view.width() / p.view.height() : 1;
  }
  // Panels never shrink below a fifth of the width, however wide the links.
  const double h = std::max(width - gap_sum, 0.2 * width) / aspects;
  double cx = x;
  double captions = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Panel& p = scene.panels[i];
    const double aspect =
        p.view.width() > 0 && p.view.height() > 0 ? p.view.width() / p.view.height() : 1;
    const Box rect{cx, y, cx + h * aspect, y + h};
    out.panels.push_back(rect);
    const double ch = caption_height(p.caption, rect.width(), style);
    out.captions.push_back(ch > 0 ? Box{rect.x_min, y + h + kCaptionGap, rect.x_max, y + h + ch}
                                  : Box{rect.x_min, y + h, rect.x_min, y + h});
    captions = std::max(captions, ch);
    cx = rect.x_max;
    if (i + 1 < n) {
      out.links.push_back({cx, y, cx + gaps[i], y + h});
      cx += gaps[i];
    }
  }
  out.height = h + captions;
  if (!notes.empty()) {
    double lines = 0;
    for (std::string_view note : notes)
      lines += static_cast<double>(wrap_rich_text(note, style.small_size, width).size());
    const double top = out.height + kCaptionGap;
    out.notes = {x, y + top, x + width, y + top + lines * style.small_size * kLineSpacing};
    out.height = out.notes.y_max - y;
  }
  if (!scene.legend.empty()) {
    const double top = out.height + kCaptionGap;
    out.legend = {x, y + top, x + width, y + top + style.small_size * kLineSpacing};
    out.height = out.legend.y_max - y;
  }
  return out;
}

namespace {

// The legend: its entries on one line, centred under the figure, each a swatch drawn as its
// role draws (a stroke, or a shaded square) and its words.
constexpr double kSwatch = 14;       // a swatch's width
constexpr double kSwatchGap = 3;     // between a swatch and its words
constexpr double kEntryGap = 12;     // between two entries

void paint_legend(Canvas& canvas, const Scene& scene, const Box& at, const Style& style) {
  const double size = style.small_size;
  std::vector<std::vector<TextRun>> texts;
  double total = 0;
  for (const LegendEntry& e : scene.legend) {
    texts.push_back(parse_rich_text(e.text));
    total += kSwatch + kSwatchGap + text_extent(texts.back(), size).width;
  }
  total += kEntryGap * static_cast<double>(scene.legend.size() - 1);
  const double cap = vertical_metrics().cap_height * size;
  const double baseline = at.y_min + cap + (at.height() - cap) / 2 - 1;
  const double mid = baseline - cap / 2;
  double x = (at.x_min + at.x_max - total) / 2;
  canvas.begin_group("legend");
  for (std::size_t i = 0; i < scene.legend.size(); ++i) {
    const LegendEntry& e = scene.legend[i];
    const RoleStyle& rs = style.of(e.role);
    Path swatch;
    if (e.swatch == LegendEntry::Swatch::line) {
      swatch.move_to({x, mid}).line_to({x + kSwatch, mid});
      canvas.path(swatch, Paint{StrokeStyle{rs.colour, rs.width, rs.dash}, std::nullopt, 1});
    } else {
      const double h = cap * 1.2;
      swatch.move_to({x, mid - h / 2}).line_to({x + kSwatch, mid - h / 2}).line_to({x + kSwatch, mid + h / 2})
          .line_to({x, mid + h / 2}).close();
      canvas.path(swatch, Paint{StrokeStyle{rs.colour, std::min(rs.width, 0.9), {}}, rs.colour, style.fill_opacity});
    }
    x += kSwatch + kSwatchGap;
    canvas.text(TextLine{{x, baseline}, Anchor::start, size, texts[i], style.caption});
    x += text_extent(texts[i], size).width + kEntryGap;
  }
  canvas.end_group();
}

}  // namespace

double scene_height(const Scene& scene, double width, const Style& style) {
  return layout_scene(scene, 0, 0, width, style).height;
}

int SceneReport::unclean() const {
  int n = 0;
  for (const PanelReport& p : panels) {
    for (const Placement& l : p.labels) n += l.clean ? 0 : 1;
  }
  return n;
}

SceneReport paint_scene(Canvas& canvas, const Scene& scene, double x, double y, double width,
                        const Style& style) {
  return paint_scene(canvas, scene, layout_scene(scene, x, y, width, style), style);
}

SceneReport paint_scene(Canvas& canvas, const Scene& scene, const SceneLayout& layout, const Style& style) {
  SceneReport report;
  for (std::size_t i = 0; i < scene.panels.size(); ++i) {
    report.panels.push_back(PanelPainter(canvas, scene.panels[i], layout.panels[i], style).paint());
  }
  const double size = style.small_size;
  const double first_baseline = vertical_metrics().cap_height * size;
  bool any_text = false;
  for (const Panel& p : scene.panels) any_text = any_text || !p.caption.empty();
  for (const std::string& l : scene.links) any_text = any_text || !l.empty();
  if (!scene.legend.empty()) paint_legend(canvas, scene, layout.legend, style);
  if (!any_text) return report;

  canvas.begin_group("captions");
  for (std::size_t i = 0; i < scene.panels.size(); ++i) {
    const std::string& caption = scene.panels[i].caption;
    if (caption.empty()) continue;
    const Box& c = layout.captions[i];
    centred_lines(canvas, wrap_rich_text(caption, size, c.width()), (c.x_min + c.x_max) / 2,
                  c.y_min + first_baseline, size, style.caption);
  }
  double note_baseline = layout.notes.y_min + first_baseline;
  bool first_note = true;
  for (std::size_t i = 0; i < layout.links.size() && i < scene.links.size(); ++i) {
    if (scene.links[i].empty()) continue;
    const Box& g = layout.links[i];
    const double mid_y = (g.y_min + g.y_max) / 2;
    if (layout.link_on_arrow[i]) {
      // The text stands on the arrow, centred across the gap, on the one line layout measured.
      const auto lines = wrap_rich_text(scene.links[i], size, g.width() - 2 * kLinkPad);
      const double block = static_cast<double>(lines.size()) * size * kLineSpacing;
      centred_lines(canvas, lines, (g.x_min + g.x_max) / 2, mid_y - block - 2 + first_baseline, size,
                    style.caption);
    } else {
      const auto lines = wrap_rich_text(scene.links[i], size, layout.notes.width());
      // A superscript (T^{−1}) reaches above the capitals: the first line drops to keep it in.
      if (first_note && !lines.empty())
        note_baseline += std::max(0.0, text_extent(lines[0], size).ascent - first_baseline);
      first_note = false;
      centred_lines(canvas, lines, (layout.notes.x_min + layout.notes.x_max) / 2, note_baseline, size,
                    style.caption);
      note_baseline += static_cast<double>(lines.size()) * size * kLineSpacing;
    }
    const double x0 = g.x_min + kLinkPad, x1 = g.x_max - kLinkPad;
    Path shaft;
    shaft.move_to({x0, mid_y}).line_to({x1 - kAxisArrow * 0.7, mid_y});
    canvas.path(shaft, Paint{StrokeStyle{style.caption, 0.8, {}}, std::nullopt, 1});
    Path head;
    head.move_to({x1, mid_y})
        .line_to({x1 - kAxisArrow, mid_y - kAxisArrow * 0.4})
        .line_to({x1 - kAxisArrow, mid_y + kAxisArrow * 0.4})
        .close();
    canvas.path(head, Paint{std::nullopt, style.caption, 1});
  }
  canvas.end_group();
  return report;
}

}  // namespace epure::render
