#include "explore/explorer.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <variant>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/kinds/space_common.h"
#include "exercises/numbers.h"
#include "exercises/rng.h"
#include "exercises/texts.h"
#include "render/camera.h"
#include "render/scene_painter.h"
#include "render/svg_scene.h"
#include "render/text.h"
#include "solve/solve.h"

namespace epure::explore {

namespace {

using nlohmann::json;
using render::Box;
using render::P2;

// The figure's width in the page, points (the SVG scales to the page's column).
constexpr double kFigureWidth = 520;
// Grid steps of a keyboard nudge, and the rounding of dragged data: integers with snap (the
// exact forms of an easy sheet), hundredths without (data as a worksheet prints it).
constexpr double kSnapStep = 1, kFreeStep = 0.1, kFreeScale = 100;
constexpr double kSnapAngle = 15;  // degrees

// The kind whose data the instance holds: the one of its contract kind that reads it (the
// contract's `vectors` is one kind in the plane, another in space: the one that reads it).
const ExerciseKind& kind_of(const json& instance) {
  if (!instance.is_object() || !instance.contains("kind") || !instance["kind"].is_string())
    throw std::runtime_error("field 'kind': missing");
  const auto& name = instance["kind"].get_ref<const std::string&>();
  std::vector<const ExerciseKind*> candidates;
  for (const ExerciseKind* k : all_kinds())
    if (k->contract_kind() == name) candidates.push_back(k);
  if (candidates.empty()) throw std::runtime_error(fmt::format("field 'kind': no view for '{}'", name));
  // The kinds of one contract kind read disjoint instances (the contract's vectors: pairs for
  // one, triples for the other), so whichever order they are tried in, the one that reads it
  // is the same: the one that read the last instance goes first, and a kind alone is the answer
  // whether it reads the instance or not. (A read that fails throws: not on every move.)
  const ExerciseKind* first = candidates.front();
  if (candidates.size() == 1) return *first;
  thread_local const ExerciseKind* last = nullptr;
  if (const auto it = std::find(candidates.begin(), candidates.end(), last); it != candidates.end())
    std::rotate(candidates.begin(), it, it + 1);
  for (const ExerciseKind* k : candidates) {
    try {
      k->read_instance(instance);
      return *(last = k);
    } catch (const std::exception&) {
      // another kind of that contract kind may read it
    }
  }
  return *first;  // its key_of names the field at fault
}

json parse(std::string_view text) {
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error("not a JSON object");
  return j;
}

// The instance drag returned, as it was before its dump: the view of that instance comes next
// and need not parse it again.
struct LastDragged {
  std::string text;
  json instance;
};
LastDragged& last_dragged() {
  thread_local LastDragged last;
  return last;
}
const json* as_dragged(std::string_view text) {
  const LastDragged& last = last_dragged();
  return !last.text.empty() && text == last.text ? &last.instance : nullptr;
}

// ---- handles: one per datum, from the solve fields -----------------------------------------
// A point field (A, B, C, D) is its own handle; a direction (u) is held by its tip, drawn from A
// (from the origin when the figure has no A: the vectors kind); a radius r by the point C + (r, 0);
// a pair of sizes with an angle (radii, half) by the ends of the two axes, the first also turning
// the figure.
//
// Data in space (three components) are held where the key's 3D view (its first panel, drawn by
// kinds::space::camera()) projects them: A, C, the tip of u (from A, or of u and v from the
// origin), and r at C's projection + (r, 0), on the sphere's outline (orthographic: the outline is
// a circle of radius r). A projected point has a line of points in space behind it, so a drag
// moves it in a plane: by default the horizontal plane through it (z kept, x and y under the
// pointer), the plane of the floor grid the view draws, so that the point's dashed drop line
// slides on the grid with its foot under the pointer; in `height` mode (Shift, or the page's
// toggle) along its vertical (x and y kept, z under the pointer), along that drop line. Either
// way a move changes the coordinates one reads on the view's grid, never all three at once, as a
// drag in the plane parallel to the screen would (that plane is tilted in x, y and z).

bool is_pair(const json& j) { return j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number(); }
P2 pair_of(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }
bool is_triple(const json& j) {
  return j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
}
render::P3 triple_of(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

struct Handle {
  std::string id;
  P2 at;  // math coordinates (of the 3D view: the camera's projection)
};

// Whether the instance's data are in space (the view's first panel is the camera's).
bool in_space(const json& instance) {
  for (const char* f : {"A", "C", "u", "v"})
    if (instance.contains(f) && is_triple(instance[f])) return true;
  return false;
}

const render::Camera& camera() {
  static const render::Camera cam = kinds::space::camera();
  return cam;
}

double degrees_of(const json& instance) {
  return instance.contains("angle") && instance["angle"].is_number() ? instance["angle"].get<double>() : 0.0;
}

P2 axis(double degrees, int index) {
  const double a = degrees * std::numbers::pi / 180;
  return index == 0 ? P2{std::cos(a), std::sin(a)} : P2{-std::sin(a), std::cos(a)};
}

P2 anchor_of(const json& instance, std::string_view field) {
  if (field == "u" && instance.contains("A") && is_pair(instance["A"])) return pair_of(instance["A"]);
  return {0, 0};
}

render::P3 anchor3_of(const json& instance, std::string_view field) {
  if (field == "u" && instance.contains("A") && is_triple(instance["A"])) return triple_of(instance["A"]);
  return {0, 0, 0};
}

std::vector<Handle> handles3_of(const json& instance) {
  const render::Camera& cam = camera();
  std::vector<Handle> out;
  for (const char* f : {"A", "B", "C", "D"})
    if (instance.contains(f) && is_triple(instance[f])) out.push_back({f, cam.project(triple_of(instance[f]))});
  for (const char* f : {"u", "v"})
    if (instance.contains(f) && is_triple(instance[f]))
      out.push_back({f, cam.project(anchor3_of(instance, f) + triple_of(instance[f]))});
  if (instance.contains("C") && is_triple(instance["C"]) && instance.contains("r") && instance["r"].is_number()) {
    const P2 c = cam.project(triple_of(instance["C"]));
    out.push_back({"r", {c.x + instance["r"].get<double>(), c.y}});
  }
  return out;
}

std::vector<Handle> handles_of(const json& instance) {
  if (in_space(instance)) return handles3_of(instance);
  std::vector<Handle> out;
  for (const char* f : {"A", "B", "C", "D"})
    if (instance.contains(f) && is_pair(instance[f])) out.push_back({f, pair_of(instance[f])});
  for (const char* f : {"u", "v"})
    if (instance.contains(f) && is_pair(instance[f])) {
      const P2 o = anchor_of(instance, f), u = pair_of(instance[f]);
      out.push_back({f, {o.x + u.x, o.y + u.y}});
    }
  const bool centred = instance.contains("C") && is_pair(instance["C"]);
  const P2 c = centred ? pair_of(instance["C"]) : P2{0, 0};
  if (centred && instance.contains("r") && instance["r"].is_number())
    out.push_back({"r", {c.x + instance["r"].get<double>(), c.y}});
  for (const char* f : {"radii", "half"})
    if (centred && instance.contains(f) && is_pair(instance[f])) {
      const P2 s = pair_of(instance[f]);
      const double deg = degrees_of(instance);
      for (int i = 0; i < 2; ++i) {
        const P2 e = axis(deg, i);
        const double len = i == 0 ? s.x : s.y;
        out.push_back({fmt::format("{}.{}", f, i), {c.x + len * e.x, c.y + len * e.y}});
      }
    }
  return out;
}

double quantise(double x, bool snap) {
  // k / 100 as the nearest double, the one a worksheet's "3.51" denotes
  return snap ? std::round(x) : std::round(x * kFreeScale) / kFreeScale;
}

double rounded_size(double x, bool snap) { return quantise(x, snap); }

// The point of space that projects to m: in the horizontal plane through p, or (height) on the
// vertical through p. The projection is linear: m = x·X + y·Y + z·Z with X, Y, Z the axes' images.
render::P3 unprojected(render::P3 p, P2 m, bool height) {
  const render::Camera& cam = camera();
  const P2 X = cam.project({1, 0, 0}), Y = cam.project({0, 1, 0}), Z = cam.project({0, 0, 1});
  if (height) {
    // the vertical's image is a vertical line (Z.x = 0: the camera keeps z upright)
    const P2 foot = cam.project({p.x, p.y, 0});
    return {p.x, p.y, (m.y - foot.y) / Z.y};
  }
  // x·X + y·Y = m − z·Z, by Cramer's rule (X ∧ Y = sin(elevation) ≠ 0)
  const P2 r{m.x - p.z * Z.x, m.y - p.z * Z.y};
  const double det = X.x * Y.y - Y.x * X.y;
  return {(r.x * Y.y - Y.x * r.y) / det, (X.x * r.y - r.x * X.y) / det, p.z};
}

json triple_json(render::P3 p) { return json::array({p.x, p.y, p.z}); }

// The 3D instance with handle `id` moved to figure point m (math coordinates of the 3D view).
json moved3(json instance, std::string_view id, P2 m, bool snap, bool height) {
  const auto placed = [&](render::P3 p) {
    const render::P3 q = unprojected(p, m, height);
    // only the coordinates the move changes are rounded; the others stay as they were
    return height ? render::P3{p.x, p.y, quantise(q.z, snap)} : render::P3{quantise(q.x, snap), quantise(q.y, snap), p.z};
  };
  const std::string f(id);
  if (id == "A" || id == "B" || id == "C" || id == "D") {
    if (!instance.contains(f) || !is_triple(instance[f])) return instance;
    instance[f] = triple_json(placed(triple_of(instance[f])));
    return instance;
  }
  if (id == "u" || id == "v") {
    if (!instance.contains(f) || !is_triple(instance[f])) return instance;
    const render::P3 o = anchor3_of(instance, f), u = triple_of(instance[f]);
    const render::P3 tip = placed(o + u);
    const render::P3 w = height ? render::P3{u.x, u.y, quantise(tip.z - o.z, snap)}
                                : render::P3{quantise(tip.x - o.x, snap), quantise(tip.y - o.y, snap), u.z};
    if (w.x == 0 && w.y == 0 && w.z == 0) return instance;  // a direction is never zero
    instance[f] = triple_json(w);
    return instance;
  }
  if (id == "r" && instance.contains("C") && is_triple(instance["C"])) {
    // the outline is a circle of radius r around C's image
    const P2 c = camera().project(triple_of(instance["C"]));
    const double r = rounded_size(std::hypot(m.x - c.x, m.y - c.y), snap);
    if (r > 0) instance["r"] = r;
  }
  return instance;
}

// The instance with handle `id` at math point m; unchanged when that would zero a datum.
json moved(json instance, std::string_view id, P2 m, bool snap, bool height = false) {
  if (in_space(instance)) return moved3(std::move(instance), id, m, snap, height);
  const P2 q{quantise(m.x, snap), quantise(m.y, snap)};
  const auto set_pair = [&](const char* f, double a, double b) { instance[f] = json::array({a, b}); };
  if (id == "A" || id == "B" || id == "C" || id == "D") {
    const std::string f(id);
    if (!instance.contains(f)) return instance;
    set_pair(f.c_str(), q.x, q.y);
    return instance;
  }
  if (id == "u" || id == "v") {
    const std::string f(id);
    const P2 o = anchor_of(instance, f);
    const double x = quantise(m.x - o.x, snap), y = quantise(m.y - o.y, snap);
    if (x == 0 && y == 0) return instance;  // a direction is never zero
    set_pair(f.c_str(), x, y);
    return instance;
  }
  if (!instance.contains("C") || !is_pair(instance["C"])) return instance;
  const P2 c = pair_of(instance["C"]);
  const P2 d{m.x - c.x, m.y - c.y};
  if (id == "r") {
    const double r = rounded_size(std::hypot(d.x, d.y), snap);
    if (r > 0) instance["r"] = r;
    return instance;
  }
  for (const char* f : {"radii", "half"}) {
    for (int i = 0; i < 2; ++i) {
      if (id != fmt::format("{}.{}", f, i) || !instance.contains(f) || !is_pair(instance[f])) continue;
      P2 s = pair_of(instance[f]);
      if (i == 0) {
        // the first axis's end: its length, and the figure's angle
        const double len = rounded_size(std::hypot(d.x, d.y), snap);
        double deg = std::atan2(d.y, d.x) * 180 / std::numbers::pi;
        deg = snap ? std::round(deg / kSnapAngle) * kSnapAngle : std::round(deg);
        if (deg <= -180) deg += 360;
        if (len <= 0) return instance;
        s.x = len;
        instance["angle"] = deg;
      } else {
        const P2 e = axis(degrees_of(instance), 1);
        const double len = rounded_size(std::abs(d.x * e.x + d.y * e.y), snap);
        if (len <= 0) return instance;
        s.y = len;
      }
      set_pair(f, s.x, s.y);
      return instance;
    }
  }
  return instance;
}

// A keyboard step in space: (dx, dy), an arrow's direction on the screen, moves along the floor
// axis (±x or ±y) whose image points most nearly that way (with the view's camera: → +y, ↑ −x);
// dz moves along z. A step of `step` on that coordinate, rounded as a drag rounds.
json nudged3(json instance, std::string_view id, int dx, int dy, int dz, double step, bool snap) {
  const std::string f(id);
  if (id == "r") {
    if (!instance.contains("r") || !instance["r"].is_number()) return instance;
    const double r = rounded_size(instance["r"].get<double>() + (dx != 0 ? dx : dy != 0 ? dy : dz) * step, snap);
    if (r > 0) instance["r"] = r;
    return instance;
  }
  if (!instance.contains(f) || !is_triple(instance[f])) return instance;
  render::P3 p = triple_of(instance[f]);
  if (dz != 0) {
    p.z = quantise(p.z + dz * step, snap);
  } else if (dx != 0 || dy != 0) {
    const P2 X = camera().project({1, 0, 0}), Y = camera().project({0, 1, 0});
    const double along_x = (dx * X.x + dy * X.y) / std::hypot(X.x, X.y);
    const double along_y = (dx * Y.x + dy * Y.y) / std::hypot(Y.x, Y.y);
    if (std::abs(along_x) >= std::abs(along_y)) p.x = quantise(p.x + (along_x > 0 ? step : -step), snap);
    else p.y = quantise(p.y + (along_y > 0 ? step : -step), snap);
  }
  if ((id == "u" || id == "v") && p.x == 0 && p.y == 0 && p.z == 0) return instance;
  instance[f] = triple_json(p);
  return instance;
}

// ---- the first panel's frame: math <-> figure (SVG user units) -------------------------------

struct FrameData {
  Box view, rect;
};

// As JSON text; the frame of a drag stays what it was (the view is held still): written once.
const std::string& frame_text(const FrameData& f) {
  thread_local FrameData last{};
  thread_local std::string text;
  if (text.empty() || std::memcmp(&last, &f, sizeof f) != 0) {  // bits: −0 is not 0 in JSON
    last = f;
    text = json{{"view", {f.view.x_min, f.view.y_min, f.view.x_max, f.view.y_max}},
                {"rect", {f.rect.x_min, f.rect.y_min, f.rect.x_max, f.rect.y_max}}}
               .dump();
  }
  return text;
}

std::optional<FrameData> read_frame(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const json j = json::parse(text, nullptr, false);
  const auto box = [&](const char* key, Box& b) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_array() || j[key].size() != 4) return false;
    for (const auto& x : j[key])
      if (!x.is_number()) return false;
    b = {j[key][0].get<double>(), j[key][1].get<double>(), j[key][2].get<double>(), j[key][3].get<double>()};
    return b.width() > 0 && b.height() > 0;
  };
  FrameData f;
  if (!box("view", f.view) || !box("rect", f.rect)) return std::nullopt;
  return f;
}

// The page hands the same frame back on every move of a drag (to drag and to view_parts): it
// is read once.
std::optional<FrameData> frame_from(std::string_view text) {
  thread_local std::string last_text;
  thread_local std::optional<FrameData> last;
  if (text != last_text) {
    last = read_frame(text);
    last_text = text;
  }
  return last;
}

// The figure point's math coordinates: render::Frame's map, inverted (one scale, y flipped).
P2 to_math(const FrameData& f, P2 page) {
  const render::Frame frame(f.view, f.rect);
  const P2 corner = frame.to_page({f.view.x_min, f.view.y_max});
  return {f.view.x_min + (page.x - corner.x) / frame.scale(), f.view.y_max - (page.y - corner.y) / frame.scale()};
}

// ---- the key as HTML ------------------------------------------------------------------------

// HTML's four special characters escaped, the runs between them appended whole.
constexpr std::array<bool, 256> kHtmlSpecial = [] {
  std::array<bool, 256> special{};
  for (char c : {'&', '<', '>', '"'}) special[static_cast<unsigned char>(c)] = true;
  return special;
}();
void escape_into(std::string& out, std::string_view s) {
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (!kHtmlSpecial[static_cast<unsigned char>(c)]) continue;
    out.append(s, run, i - run);
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : "&quot;";
    run = i + 1;
  }
  out.append(s, run, std::string_view::npos);
}

// `s` as a JSON string (UTF-8 kept as it is: the texts and figures are valid UTF-8).
void append_json_string(std::string& out, std::string_view s) {
  out += '"';
  std::size_t run = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c != '"' && c != '\\' && c >= 0x20) continue;
    out.append(s, run, i - run);
    run = i + 1;
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default: out += fmt::format("\\u{:04x}", c);
    }
  }
  out.append(s, run, std::string_view::npos);
  out += '"';
}

// The label markup (t_{ab}, r^{2}, \vec{AB}) as HTML, through the parser every backend uses,
// appended to `out`: each of parse_rich_text's runs (pieces of one shift and arrow) in its tags.
class HtmlRuns final : public render::RichSink {
 public:
  explicit HtmlRuns(std::string& out) : out_(out) {}
  ~HtmlRuns() { close(); }
  void piece(std::string_view text, render::Shift shift, bool arrow) override {
    if (!open_ || shift != shift_ || arrow != arrow_) {
      close();
      open_ = true, shift_ = shift, arrow_ = arrow;
      if (const char* tag = script()) out_ += '<', out_ += tag, out_ += '>';
      if (arrow_) out_ += "<span class=\"vec\">";
    }
    escape_into(out_, text);
  }

 private:
  const char* script() const {
    return shift_ == render::Shift::sub ? "sub" : shift_ == render::Shift::super ? "sup" : nullptr;
  }
  void close() {
    if (!open_) return;
    if (arrow_) out_ += "</span>";
    if (const char* tag = script()) out_ += "</", out_ += tag, out_ += '>';
  }
  std::string& out_;
  bool open_ = false, arrow_ = false;
  render::Shift shift_ = render::Shift::none;
};

void append_rich_html(std::string& out, std::string_view rich) {
  HtmlRuns runs(out);
  render::parse_rich_pieces(rich, runs);
}

struct KeyView {
  std::string steps;
  render::Scene* figure = nullptr;  // in the section
};

KeyView key_view(render::Section& key) {
  KeyView v;
  std::string& out = v.steps;
  for (auto& block : key.blocks) {
    if (const auto* h = std::get_if<render::Heading>(&block)) {
      const std::string level = std::to_string(h->level + 1);
      out += "<h" + level + '>';
      append_rich_html(out, h->text);
      out += "</h" + level + ">\n";
    } else if (const auto* p = std::get_if<render::Paragraph>(&block)) {
      out += p->emphasis ? "<p class=\"emphasis\">" : "<p>";
      append_rich_html(out, p->text);
      out += "</p>\n";
    } else if (const auto* a = std::get_if<render::AnswerLine>(&block)) {
      out += "<p class=\"answer\" data-question=\"";
      out += a->question_id;
      out += "\"><span class=\"prompt\">";
      append_rich_html(out, a->prompt);
      out += "</span> ";
      append_rich_html(out, a->answer);
      out += "</p>\n";
    } else if (auto* f = std::get_if<render::Figure>(&block)) {
      if (v.figure == nullptr) v.figure = &f->scene;
      out += "<div class=\"figure-here\"></div>\n";
    }
  }
  return v;
}

ExerciseSpec exercise_spec(std::string_view kind) {
  ExerciseSpec s;
  s.kind = std::string(kind);
  s.difficulty = Difficulty::standard;
  return s;
}

// The figure's SVG with the handles drawn over it, as circles the page's script can grab.
std::string with_handles(std::string svg, const std::vector<Handle>& handles, const FrameData& f) {
  const render::Frame frame(f.view, f.rect);
  std::string g = "<g class=\"handles\">";
  for (const auto& h : handles) {
    const P2 p = frame.to_page(h.at);
    g += fmt::format(
        "<circle class=\"handle\" data-handle=\"{0}\" cx=\"{1:.3f}\" cy=\"{2:.3f}\" r=\"7\" tabindex=\"-1\" "
        "role=\"slider\" aria-label=\"{0}\"/>",
        h.id, p.x, p.y);
  }
  g += "</g>\n";  // one element per line, as the SVG writer writes them (the page patches by line)
  const auto end = svg.rfind("</svg>");
  if (end == std::string::npos) throw std::logic_error("explore: the figure is not an SVG document");
  svg.insert(end, g);
  // the XML declaration has no place inside HTML
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  return svg;
}

}  // namespace

std::string solve(std::string_view line) {
  fmt::memory_buffer out;
  solve::solve_line(line, out, solve::Semantics::exact);
  return std::string(out.data(), out.size());
}

std::string kinds() {
  json names = json::array();
  for (const ExerciseKind* k : all_kinds()) names.push_back(k->name());
  return names.dump();
}

std::string words(std::string_view language) {
  constexpr std::string_view prefix = "explore.";
  json out = json::object();
  for (const auto& [key, text] : Texts::builtin(language).all())
    if (key.starts_with(prefix)) out[key.substr(prefix.size())] = text;
  return out.dump();
}

std::string starting_instance(std::string_view kind_name) {
  const ExerciseKind* kind = find_kind(kind_name);
  if (kind == nullptr) throw std::runtime_error(fmt::format("no view for '{}'", kind_name));
  const auto branches = kind->default_branches();
  std::string branch = branches.front().first;
  double weight = branches.front().second;
  for (const auto& [b, w] : branches)
    if (w > weight) branch = b, weight = w;
  const ExerciseSpec spec = exercise_spec(kind_name);
  const Texts& texts = Texts::builtin("en");
  const ExerciseContext ctx{1, spec, texts, NumberStyle::for_language("en"), 2, branch};
  Rng rng(1);
  return kind->make(rng, ctx).instance;
}

ViewParts view_parts(std::string_view instance_text, std::string_view language, int n, std::string_view frozen) {
  try {
    json fresh;
    const json* dragged = as_dragged(instance_text);
    const json& instance = dragged ? *dragged : (fresh = parse(instance_text));
    const ExerciseKind& kind = kind_of(instance);
    const ExerciseSpec spec = exercise_spec(kind.name());
    const Texts& texts = Texts::builtin(language);
    ExerciseContext ctx{n, spec, texts, NumberStyle::for_language(language), 2, ""};
    ctx.sheet = false;        // the view shows the key only,
    ctx.tolerances = false;   // and marks nothing
    ExerciseInstance key = kind.key_of(instance, ctx);
    KeyView kv = key_view(key.key);
    if (kv.figure == nullptr || kv.figure->panels.empty()) throw std::logic_error("explore: the key has no figure");
    render::Scene& scene = *kv.figure;
    if (auto f = frame_from(frozen)) scene.panels[0].view = f->view;
    const auto layout = render::layout_scene(scene, 0, 0, kFigureWidth);
    const FrameData frame{scene.panels[0].view, layout.panels[0]};
    const auto handles = handles_of(instance);
    json hs = json::array();
    const render::Frame map(frame.view, frame.rect);
    for (const auto& h : handles) {
      const P2 p = map.to_page(h.at);
      hs.push_back({{"id", h.id}, {"x", p.x}, {"y", p.y}});
    }
    ViewParts out;
    out.head = "{\"kind\":";
    append_json_string(out.head, kind.name());
    out.head += ",\"instance\":";
    append_json_string(out.head, key.instance);
    out.head += ",\"solution\":";
    out.head += key.solution;  // JSON already: the solve output
    out.head += ",\"frame\":";
    out.head += frame_text(frame);
    out.head += ",\"handles\":";
    out.head += hs.dump();
    out.head += in_space(instance) ? ",\"space\":true}" : ",\"space\":false}";
    out.svg = with_handles(render::scene_to_svg(scene, kFigureWidth, layout), handles, frame);
    out.steps = std::move(kv.steps);
    return out;
  } catch (const std::exception& e) {
    return {json{{"error", e.what()}}.dump(), {}, {}};
  }
}

std::string view(std::string_view instance, std::string_view language, int n, std::string_view frozen) {
  ViewParts parts = view_parts(instance, language, n, frozen);
  if (parts.svg.empty()) return std::move(parts.head);
  // the two long texts go through a plain escaper (nlohmann's validating one was a quarter of
  // the view's time)
  std::string out = std::move(parts.head);
  out.pop_back();  // the closing brace
  out += ",\"svg\":";
  append_json_string(out, parts.svg);
  out += ",\"steps\":";
  append_json_string(out, parts.steps);
  out += '}';
  return out;
}

std::string drag(std::string_view instance_text, std::string_view handle, double x, double y,
                 std::string_view frame_text, bool snap, bool height) {
  const json instance = parse(instance_text);
  const auto frame = frame_from(frame_text);
  if (!frame || !std::isfinite(x) || !std::isfinite(y)) return std::string(instance_text);
  LastDragged& last = last_dragged();
  last.instance = moved(instance, handle, to_math(*frame, {x, y}), snap, height);
  last.text = last.instance.dump();
  return last.text;
}

std::string nudge(std::string_view instance_text, std::string_view handle, int dx, int dy, int dz, bool snap) {
  const json instance = parse(instance_text);
  const double step = snap ? kSnapStep : kFreeStep;
  if (in_space(instance)) return nudged3(instance, handle, dx, dy, dz, step, snap).dump();
  for (const auto& h : handles_of(instance))
    if (h.id == handle) return moved(instance, handle, {h.at.x + dx * step, h.at.y + dy * step}, snap).dump();
  return std::string(instance_text);
}

}  // namespace epure::explore
