#include "explore/explorer.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "exercises/exercise.h"
#include "exercises/numbers.h"
#include "exercises/rng.h"
#include "exercises/texts.h"
#include "explore/drag.h"
#include "explore/frame.h"
#include "explore/handles.h"
#include "explore/key_html.h"
#include "explore/written_numbers.h"
#include "render/scene_painter.h"
#include "render/svg_scene.h"
#include "solve/solve.h"

namespace epure::explore {

namespace {

using nlohmann::json;
using render::P2;

// The figure's width in the page, points (the SVG scales to the page's column).
constexpr double kFigureWidth = 520;

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

// The data fields of the instance's kind (their roles place the handles), none when no kind has
// a view of it (nothing then moves).
std::vector<DataField> fields_of(const json& instance) {
  try {
    return kind_of(instance).data_fields();
  } catch (const std::exception&) {
    return {};
  }
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

// Whether two solve outputs give the same decisions: the same fields, and the same booleans and
// words (the numbers may differ in their last bits: the key's are its doubles').
bool same_decisions(const json& a, const json& b) {
  if (a.size() != b.size()) return false;
  for (auto it = a.begin(); it != a.end(); ++it) {
    const auto other = b.find(it.key());
    if (other == b.end()) return false;
    if ((it->is_boolean() || it->is_string()) && *it != *other) return false;
  }
  return true;
}

// The view of data the key's worked steps cannot follow: an error that says why, with what
// `epure solve` gives for them (also as "solution", for the page's API).
ViewParts not_followed(const std::string& solution) {
  return {json{{"error", fmt::format("the worked steps cannot follow these data: computed in doubles at the course's "
                                     "precision, they do not decide a figure on a boundary as written, or one decided "
                                     "by digits beyond a double's; epure solve gives {}",
                                     solution)},
               {"solution", json::parse(solution)}}
              .dump(),
          {},
          {}};
}

ExerciseSpec exercise_spec(std::string_view kind) {
  ExerciseSpec s;
  s.kind = std::string(kind);
  s.difficulty = Difficulty::standard;
  return s;
}

}  // namespace

std::string solve(std::string_view line) {
  fmt::memory_buffer out;
  solve::solve_line(line, out);
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

ViewParts view_parts(std::string_view instance_text, std::string_view language, int n, std::string_view frozen,
                     std::string_view label) {
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
    ctx.label = std::string(label);
    // The key's worked steps are computed in doubles, with the course's tolerances at 2
    // decimals: on data at a boundary as written (A on the circle, segments parallel as
    // decimals), or decided by digits beyond a double's, its decisions can differ from the exact
    // ones, and it refuses (its method disagrees with the core) or would answer for the doubles.
    // The view then says so and gives `epure solve`'s answer for the data as written, never
    // another figure's.
    ExerciseInstance key;
    try {
      key = kind.key_of(instance, ctx);
    } catch (const std::logic_error&) {
      const std::string solution = solve(instance_text);
      if (json::parse(solution).contains("error")) throw;
      return not_followed(solution);
    }
    // The instance keeps the numbers as written (written_numbers.h), and its solution is
    // `epure solve`'s for them.
    const std::string written = with_written_numbers(key.instance, instance_text);
    if (written != key.instance) {
      std::string solution = solve(written);
      const json by_solve = json::parse(solution), by_key = json::parse(key.solution);
      if (by_solve.contains("error") || !same_decisions(by_solve, by_key)) return not_followed(solution);
      key.instance = written;
      key.solution = std::move(solution);
    }
    KeyView kv = key_view(key.key);
    if (kv.figure == nullptr || kv.figure->panels.empty()) throw std::logic_error("explore: the key has no figure");
    render::Scene& scene = *kv.figure;
    if (auto f = frame_from(frozen)) scene.panels[0].view = f->view;
    const auto layout = render::layout_scene(scene, 0, 0, kFigureWidth);
    const FrameData frame{scene.panels[0].view, layout.panels[0]};
    const std::vector<DataField> fields = kind.data_fields();
    const auto handles = handles_of(fields, instance);
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
    out.head += in_space(fields) ? ",\"space\":true}" : ",\"space\":false}";
    out.svg = with_handles(render::scene_to_svg(scene, kFigureWidth, layout), handles, frame);
    out.steps = std::move(kv.steps);
    return out;
  } catch (const std::exception& e) {
    return {json{{"error", e.what()}}.dump(), {}, {}};
  }
}

std::string view(std::string_view instance, std::string_view language, int n, std::string_view frozen,
                 std::string_view label) {
  ViewParts parts = view_parts(instance, language, n, frozen, label);
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
  last.instance = moved(instance, fields_of(instance), handle, to_math(*frame, {x, y}), snap, height);
  last.text = with_written_numbers(last.instance.dump(), instance_text);
  return last.text;
}

std::string nudge(std::string_view instance_text, std::string_view handle, int dx, int dy, int dz, bool snap) {
  const json instance = parse(instance_text);
  const double step = nudge_step(snap);
  const std::vector<DataField> fields = fields_of(instance);
  // the numbers not moved as they were written (written_numbers.h)
  if (in_space(fields))
    return with_written_numbers(nudged_in_space(instance, fields, handle, dx, dy, dz, snap).dump(), instance_text);
  for (const auto& h : handles_of(fields, instance))
    if (h.id == handle)
      return with_written_numbers(moved(instance, fields, handle, {h.at.x + dx * step, h.at.y + dy * step}, snap).dump(),
                                  instance_text);
  return std::string(instance_text);
}

}  // namespace epure::explore
