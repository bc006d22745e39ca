#include "render/label_placer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "support/portable.h"

namespace epure::render {
namespace {

// Distances from the anchor to the label's box tried in turn, beyond the request's gap: close
// first, farther only when everything near is taken.
constexpr double kRings[] = {0, 3, 7, 12, 18, 26};
// When nothing near is clear (a crowded corner: a point, its vector and the centre beside it),
// these farther rings are tried before a label is set over something; a label placed there gets
// a leader line to its anchor, so that it still names its point.
constexpr double kFarRings[] = {36, 48, 62};
// A label whose box is farther than this from its anchor (beyond the request's gap), and nearer
// to another point, gets a leader: a reader takes a label to name the point nearest to it.
constexpr double kLeaderFrom = 8;
// Rings from this index on try 16 directions instead of 8.
constexpr std::size_t kFineRing = 2;
// A box must stay this far inside its panel.
constexpr double kAreaMargin = 1.0;

// Weights of the fallback's penalty: two labels on top of each other are worse than a label on
// a line, which is worse than a label sticking out of the panel a little.
constexpr double kOverlapWeight = 10;  // per square point of label-on-label
constexpr double kCrossWeight = 4;     // per point of stroke inside the box
constexpr double kOutsideWeight = 2;   // per point outside the panel

// Parameters [t0, t1] of segment a→b inside `box` (Liang–Barsky); false when it misses.
bool clip_segment(P2 a, P2 b, const Box& box, double& t0, double& t1) {
  t0 = 0;
  t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - box.x_min, box.x_max - a.x, a.y - box.y_min, box.y_max - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {  // parallel to this edge: in or out for the whole segment
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) return false;
  }
  return true;
}

double overlap_area(const Box& a, const Box& b) {
  const double w = std::min(a.x_max, b.x_max) - std::max(a.x_min, b.x_min);
  const double h = std::min(a.y_max, b.y_max) - std::max(a.y_min, b.y_min);
  return w > 0 && h > 0 ? w * h : 0;
}

double outside_amount(const Box& b, const Box& area) {
  return std::max(0.0, area.x_min - b.x_min) + std::max(0.0, b.x_max - area.x_max) +
         std::max(0.0, area.y_min - b.y_min) + std::max(0.0, b.y_max - area.y_max);
}

double box_distance(P2 p, const Box& b) {
  const double dx = std::max({b.x_min - p.x, 0.0, p.x - b.x_max});
  const double dy = std::max({b.y_min - p.y, 0.0, p.y - b.y_max});
  return portable::hypot(dx, dy);
}

P2 unit(P2 v) {
  const double n = portable::hypot(v.x, v.y);
  return n > 0 ? P2{v.x / n, v.y / n} : P2{0, 0};
}

// The box of a w×h label whose side or corner faces the anchor from direction u at distance d.
Box candidate(P2 anchor, P2 u, double d, double w, double h) {
  const double m = std::max(std::abs(u.x), std::abs(u.y));
  const double cx = anchor.x + d * u.x + w / 2 * u.x / m;
  const double cy = anchor.y + d * u.y + h / 2 * u.y / m;
  return {cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2};
}

// The turns that give the directions tried on one ring from the preferred one: k·360°/count
// for k = 0, 1, −1, 2, −2, … (the counter-clockwise one first on a tie).
template <std::size_t count>
std::array<P2, count> turns() {
  std::array<P2, count> t{};
  for (std::size_t i = 0; i < count; ++i) {
    const int k = static_cast<int>((i + 1) / 2) * (i % 2 == 1 ? 1 : -1);
    const double a = 2 * std::numbers::pi * k / static_cast<double>(count);
    t[i] = {std::cos(a), std::sin(a)};
  }
  return t;
}
const std::array<P2, 8> kCoarse = turns<8>();
const std::array<P2, 16> kFine = turns<16>();

class Placer {
 public:
  Placer(const Obstacles& obstacles, const Box& area)
      : obstacles_(obstacles),
        area_{area.x_min + kAreaMargin, area.y_min + kAreaMargin, area.x_max - kAreaMargin,
              area.y_max - kAreaMargin} {
    // The strokes' bounding boxes once: every candidate of every label is tested against all of
    // them (hundreds in a sphere's figure), and most are rejected on these alone.
    stroke_bounds_.reserve(obstacles.segments.size());
    // (grown by the pen's half width, as the box is for each segment when it is tested)
    for (const auto& s : obstacles.segments)
      stroke_bounds_.push_back(inflate({std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), std::max(s.a.x, s.b.x),
                                        std::max(s.a.y, s.b.y)},
                                       s.half_width));
  }

  Placement place(const LabelRequest& r) {
    above_ = r.type_above;
    below_ = r.type_below;
    side_ = r.type_side;
    // Most labels take their first or second candidate: test each as it is made.
    Box found{};
    if (for_each_candidate(r, [&](const Box& b) {
          if (!clean(b)) return false;
          found = b;
          return true;
        })) {
      // Set away from its point (an outer ring, past the other labels near it) and nearer to
      // another point than to its own: a leader says which point it names, where one can be
      // drawn clear of the other labels. (A tick's or a dimension's text slides along its
      // stroke, which says what it names.)
      const bool along = portable::hypot(r.along.x, r.along.y) > 0;
      const double own = box_distance(r.anchor, found);
      bool nearer_other = false;
      for (const auto& d : obstacles_.discs)
        nearer_other = nearer_other || (box_distance(d.c, found) < own - 1 && portable::hypot(d.c.x - r.anchor.x, d.c.y - r.anchor.y) > 1);
      const bool far = !along && own > r.gap + kLeaderFrom && nearer_other && leader_clear(r.anchor, found);
      Placement p = accept(found, true);
      p.leader = far;
      return p;
    }
    for (double ring : kFarRings) {
      for (const P2& t : kFine) {
        const P2 prefer = unit(portable::hypot(r.prefer.x, r.prefer.y) > 0 ? r.prefer : P2{1, -1});
        const P2 u{prefer.x * t.x - prefer.y * t.y, prefer.x * t.y + prefer.y * t.x};
        const Box b = candidate(r.anchor, u, r.gap + ring, r.width, r.height);
        if (clean(b) && leader_clear(r.anchor, b)) {
          Placement p = accept(b, true);
          p.leader = true;
          return p;
        }
      }
    }
    // No clean spot: the least bad one (the first of equals).
    double best_penalty = std::numeric_limits<double>::infinity();
    for_each_candidate(r, [&](const Box& b) {
      const double p = penalty(b);
      if (p < best_penalty) {
        best_penalty = p;
        found = b;
      }
      return false;
    });
    return accept(found, false);
  }

 private:
  // Calls `f` on every candidate box for `r`, best first, until it returns true; says whether
  // it did.
  template <class F>
  static bool for_each_candidate(const LabelRequest& r, F&& f) {
    const bool any = portable::hypot(r.prefer.x, r.prefer.y) > 0;
    const P2 prefer = unit(any ? r.prefer : P2{1, -1});  // above right by default
    const P2 along = unit(r.along);
    if (portable::hypot(along.x, along.y) > 0) {
      // Beside the stroke: the box's centre on the normal, as far as its half-extent in that
      // direction, so that the stroke's line clears the box; then slid along the stroke.
      P2 n{-along.y, along.x};
      if (n.x * prefer.x + n.y * prefer.y < 0) n = {-n.x, -n.y};
      const double slide = r.width / 2 + 2;
      for (double ring : {0.0, 3.0, 7.0}) {
        for (double side : {1.0, -1.0}) {
          const P2 m{side * n.x, side * n.y};
          const double reach =
              r.gap + ring + std::abs(m.x) * r.width / 2 + std::abs(m.y) * r.height / 2;
          for (double k : {0.0, 0.5, -0.5, 1.0, -1.0}) {
            const double cx = r.anchor.x + reach * m.x + k * slide * along.x;
            const double cy = r.anchor.y + reach * m.y + k * slide * along.y;
            if (f(Box{cx - r.width / 2, cy - r.height / 2, cx + r.width / 2, cy + r.height / 2}))
              return true;
          }
        }
      }
    }
    for (std::size_t ring = 0; ring < std::size(kRings); ++ring) {
      const bool fine = ring >= kFineRing;
      const std::size_t count = fine ? kFine.size() : kCoarse.size();
      for (std::size_t i = 0; i < count; ++i) {
        const P2 t = fine ? kFine[i] : kCoarse[i];
        const P2 u{prefer.x * t.x - prefer.y * t.y, prefer.x * t.y + prefer.y * t.x};
        if (f(candidate(r.anchor, u, r.gap + kRings[ring], r.width, r.height))) return true;
      }
    }
    return false;
  }

  Box type_of(const Box& b) const {
    return {b.x_min - side_, b.y_min - above_, b.x_max + side_, b.y_max + below_};
  }

  Placement accept(const Box& b, bool is_clean) {
    placed_.push_back(b);
    placed_types_.push_back(type_of(b));
    return {b, placed_types_.back(), is_clean};
  }

  // The leader from the anchor to the box's nearest point crosses no other label.
  bool leader_clear(P2 anchor, const Box& b) const {
    const P2 end{std::clamp(anchor.x, b.x_min, b.x_max), std::clamp(anchor.y, b.y_min, b.y_max)};
    for (const Box& p : placed_types_)
      if (segment_hits_box(anchor, end, p)) return false;
    for (const Box& p : obstacles_.boxes)
      if (segment_hits_box(anchor, end, p)) return false;
    return true;
  }

  bool clean(const Box& b) const {
    if (outside_amount(b, area_) > 0) return false;
    const Box c = inflate(b, kLabelClearance);
    for (const Box& p : placed_) {
      if (boxes_overlap(c, p)) return false;
    }
    const Box t = type_of(b);
    for (const Box& p : placed_types_) {
      if (boxes_overlap(t, p)) return false;
    }
    for (const Box& p : obstacles_.boxes) {
      if (boxes_overlap(c, p)) return false;
    }
    for (const auto& d : obstacles_.discs) {
      if (disc_hits_box(d.c, d.r, c)) return false;
    }
    for (std::size_t i = 0; i < stroke_bounds_.size(); ++i) {  // segment_hits_box, its bounds made
      const Box& sb = stroke_bounds_[i];
      if (sb.x_max < c.x_min || sb.x_min > c.x_max || sb.y_max < c.y_min || sb.y_min > c.y_max) continue;
      const auto& s = obstacles_.segments[i];
      double t0 = 0, t1 = 0;
      // the box grown by the pen's half width: the segment's centre line then keeps the
      // clearance from the ink's edge (a box's corner is held a little farther than a round
      // pen needs, never nearer)
      if (clip_segment(s.a, s.b, s.half_width > 0 ? inflate(c, s.half_width) : c, t0, t1)) return false;
    }
    return true;
  }

  double penalty(const Box& b) const {
    const Box c = inflate(b, kLabelClearance);
    double p = kOutsideWeight * outside_amount(b, area_);
    for (const Box& o : placed_) p += kOverlapWeight * overlap_area(c, o);
    const Box t = type_of(b);
    for (const Box& o : placed_types_) p += kOverlapWeight * overlap_area(t, o);
    for (const Box& o : obstacles_.boxes) p += kOverlapWeight * overlap_area(c, o);
    for (const auto& d : obstacles_.discs) {
      if (disc_hits_box(d.c, d.r, c)) p += kCrossWeight * 2 * d.r;
    }
    for (const auto& s : obstacles_.segments) {
      double t0 = 0, t1 = 0;
      if (clip_segment(s.a, s.b, inflate(c, s.half_width), t0, t1)) {
        p += kCrossWeight * (t1 - t0) * portable::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
      }
    }
    return p;
  }

  const Obstacles& obstacles_;
  std::vector<Box> stroke_bounds_;  // of obstacles_.segments, in order
  Box area_;
  std::vector<Box> placed_;
  std::vector<Box> placed_types_;  // the same labels' type boxes
  double above_ = 0, below_ = 0, side_ = 0;  // the current request's type_above, _below, _side
};

}  // namespace

void Obstacles::add_polyline(const std::vector<P2>& pts, bool closed, double half_width) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) segments.push_back({pts[i], pts[i + 1], half_width});
  if (closed && pts.size() > 2) segments.push_back({pts.back(), pts.front(), half_width});
}

bool boxes_overlap(const Box& a, const Box& b) {
  return a.x_min < b.x_max && b.x_min < a.x_max && a.y_min < b.y_max && b.y_min < a.y_max;
}

bool segment_hits_box(P2 a, P2 b, const Box& box) {
  // Cheap rejection on the bounding boxes first: most strokes are far from a label.
  if (std::max(a.x, b.x) < box.x_min || std::min(a.x, b.x) > box.x_max ||
      std::max(a.y, b.y) < box.y_min || std::min(a.y, b.y) > box.y_max) {
    return false;
  }
  double t0 = 0, t1 = 0;
  return clip_segment(a, b, box, t0, t1);
}

bool disc_hits_box(P2 c, double r, const Box& box) {
  const double dx = std::max({box.x_min - c.x, 0.0, c.x - box.x_max});
  const double dy = std::max({box.y_min - c.y, 0.0, c.y - box.y_max});
  return dx * dx + dy * dy < r * r;
}

Box inflate(const Box& b, double by) {
  return {b.x_min - by, b.y_min - by, b.x_max + by, b.y_max + by};
}

std::vector<Placement> place_labels(const std::vector<LabelRequest>& requests,
                                    const Obstacles& obstacles, const Box& area) {
  Placer placer(obstacles, area);
  std::vector<Placement> out;
  out.reserve(requests.size());
  for (const LabelRequest& r : requests) out.push_back(placer.place(r));
  return out;
}

}  // namespace epure::render
