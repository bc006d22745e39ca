// The explorer's core (src/explore/explorer.h), natively: what the page shows and how a drag
// moves the data. The page itself is tested in a browser (tests/browser/).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <vector>
#include <string>

#include "explore/explorer.h"
#include "output/explore_page.h"
#include "exercises/exercise.h"
#include "render/svg_page.h"
#include "solve/solve.h"

using nlohmann::json;
namespace ex = epure::explore;

namespace {
json view_of(const std::string& instance, const char* lang = "en", const std::string& frozen = {}) {
  return json::parse(ex::view(instance, lang, 1, frozen));
}
json handle(const json& v, const std::string& id) {
  for (const auto& h : v["handles"])
    if (h["id"] == id) return h;
  FAIL("no handle " << id);
  return {};
}
}  // namespace

TEST_CASE("explore: every kind has a view with its handles, steps and the key's figure") {
  const json kinds = json::parse(ex::kinds());
  CHECK(kinds.size() >= 10);
  for (const auto& k : kinds) {
    const std::string kind = k.get<std::string>();
    CAPTURE(kind);
    const std::string start = ex::starting_instance(kind);
    const json v = view_of(start);
    REQUIRE_FALSE(v.contains("error"));
    CHECK(v["kind"] == kind);
    CHECK(v["handles"].size() >= 2);
    const std::string svg = v["svg"];
    for (const auto& h : v["handles"]) CHECK(svg.find("data-handle=\"" + h["id"].get<std::string>() + "\"") != std::string::npos);
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(std::string(v["steps"]).size() > 100);
    // the key's solution is the one `epure solve` gives the same data (worksheet semantics), of
    // the instance's contract kind (vectors_3d's is the contract's vectors)
    CHECK(v["solution"]["kind"] == json::parse(start)["kind"]);
  }
}

TEST_CASE("explore: the handles are the schema's data by their roles, and each moves its own datum") {
  // every datum with a role of its own has a handle (a sizes pair two: its axes' ends), and
  // nothing else has one; a drag of a handle changes its datum (and, for the first axis, the
  // angle its role names), never another field
  for (const epure::ExerciseKind* kind : epure::all_kinds()) {
    CAPTURE(kind->name());
    std::vector<std::string> expected;
    for (const epure::DataField& f : kind->data_fields()) {
      if (f.role.role == epure::FieldRole::number) continue;
      if (f.role.role == epure::FieldRole::axes) {
        expected.push_back(std::string(f.name) + ".0");
        expected.push_back(std::string(f.name) + ".1");
      } else {
        expected.emplace_back(f.name);
      }
    }
    const std::string start = ex::starting_instance(kind->name());
    const json v = view_of(start);
    std::vector<std::string> ids;
    for (const auto& h : v["handles"]) ids.push_back(h["id"]);
    std::sort(ids.begin(), ids.end());
    std::sort(expected.begin(), expected.end());
    CHECK(ids == expected);
    const json before = json::parse(start);
    for (const auto& h : v["handles"]) {
      const std::string id = h["id"];
      CAPTURE(id);
      const json after = json::parse(ex::drag(start, id, h["x"].get<double>() + 17, h["y"].get<double>() + 9,
                                              v["frame"].dump(), false));
      const std::string field = id.substr(0, id.find('.'));
      std::vector<std::string> changed;
      for (const auto& [key, value] : before.items())
        if (after[key] != value) changed.push_back(key);
      CHECK_FALSE(changed.empty());
      for (const auto& key : changed) CHECK((key == field || (id == field + ".0" && key == "angle")));
    }
  }
}

TEST_CASE("explore: a drag puts the point under the pointer, on hundredths or on the grid") {
  const std::string start = R"({"kind":"projection","A":[1,1],"B":[7,3],"C":[4,6]})";
  const json v = view_of(start);
  const json a = handle(v, "A"), b = handle(v, "B");
  // the page point of B, given back as the drag's target, is B
  const json at_b = json::parse(ex::drag(start, "A", b["x"], b["y"], v["frame"].dump(), false));
  CHECK(at_b["A"][0].get<double>() == doctest::Approx(7).epsilon(1e-12));
  CHECK(at_b["A"][1].get<double>() == doctest::Approx(3).epsilon(1e-12));
  // 55% of the way from A to B: (4.3, 2.1), then rounded to hundredths or to the grid
  const double mx = a["x"].get<double>() + 0.55 * (b["x"].get<double>() - a["x"].get<double>());
  const double my = a["y"].get<double>() + 0.55 * (b["y"].get<double>() - a["y"].get<double>());
  const json free = json::parse(ex::drag(start, "A", mx, my, v["frame"].dump(), false));
  const json snapped = json::parse(ex::drag(start, "A", mx, my, v["frame"].dump(), true));
  const double x = free["A"][0].get<double>();
  CHECK(x > 4);
  CHECK(x < 5);
  CHECK(std::abs(x * 100 - std::round(x * 100)) < 1e-9);
  CHECK(snapped["A"] == json::array({4, 2}));
  // the other data stay
  CHECK(free["B"] == json::array({7, 3}));
  CHECK(free["C"] == json::array({4, 6}));
}

TEST_CASE("explore: a frozen frame keeps the figure still; the branch follows the data") {
  const std::string start = R"({"kind":"projection","A":[0,0],"B":[4,0],"C":[2,3]})";
  const json v = view_of(start);
  const json far = json::parse(ex::nudge(start, "C", 3, 0, 0, true));  // C to (5, 3): P after B
  CHECK(far["C"] == json::array({5, 3}));
  const json w = view_of(far.dump(), "en", v["frame"].dump());
  CHECK(w["frame"] == v["frame"]);
  CHECK(w["solution"]["position"] == "after");
  CHECK(v["solution"]["position"] == "between");
  CHECK(w["steps"] != v["steps"]);
}

TEST_CASE("explore: directions and sizes are never dragged to zero; sizes and angle from the axes") {
  const std::string circle = R"({"kind":"ray_circle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})";
  const json v = view_of(circle);
  const json a = handle(v, "A");
  // the tip of u dragged onto A: refused
  CHECK(json::parse(ex::drag(circle, "u", a["x"], a["y"], v["frame"].dump(), true)) == json::parse(circle));
  // r grows by one grid step
  CHECK(json::parse(ex::nudge(circle, "r", 1, 0, 0, true))["r"] == 4);
  const std::string ellipse = R"({"kind":"ray_ellipse","A":[-6,1],"u":[1,0],"C":[0,0],"radii":[3,2],"angle":0})";
  // the first axis's end moved to (0, 3): a = 3, angle 90
  const json e = json::parse(ex::nudge(ellipse, "radii.0", -3, 3, 0, true));
  CHECK(e["radii"] == json::array({3, 2}));
  CHECK(e["angle"] == 90);
}

TEST_CASE("explore: steps in the chosen language; a degenerate figure is an error") {
  const std::string start = R"({"kind":"projection","A":[0,0],"B":[4,0],"C":[2,3]})";
  CHECK(view_of(start, "fr")["steps"] != view_of(start, "en")["steps"]);
  const json bad = view_of(R"({"kind":"projection","A":[1,1],"B":[1,1],"C":[2,3]})");
  CHECK(bad.contains("error"));
  CHECK_FALSE(bad.contains("svg"));
  CHECK(view_of(R"({"kind":"no_such"})").contains("error"));
}

TEST_CASE("explore: solve is epure solve's line, its one semantics (the decimals written)") {
  const std::string line = R"({"kind":"ray_circle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})";
  fmt::memory_buffer out;
  epure::solve::solve_line(line, out);
  CHECK(ex::solve(line) == std::string(out.data(), out.size()));
  // issue 35's segments, parallel as written (not as their doubles): parallel in the page too
  CHECK(ex::solve(R"({"kind":"segments","A":[9.217,-2.43],"B":[8.593,-1.674],"C":[8.547,-2.17],"D":[7.247,-0.595]})") ==
        R"({"kind":"segments","intersects":false,"reason":"parallel"})");
}

namespace {
// The instance with one field replaced.
json with_field(std::string instance, const char* field, const json& value) {
  json j = json::parse(instance);
  j[field] = value;
  return j;
}
}  // namespace

TEST_CASE("explore: the 3D views have a handle per datum; a drag moves a point in its horizontal plane, or in height") {
  for (const char* kind : {"vectors_3d", "ray_sphere", "ray_cube"}) {
    CAPTURE(kind);
    const json v = view_of(ex::starting_instance(kind));
    REQUIRE_FALSE(v.contains("error"));
    CHECK(v["kind"] == kind);
    CHECK(v["space"] == true);
    CHECK(v["handles"].size() >= 2);
  }
  CHECK(view_of(ex::starting_instance("projection"))["space"] == false);
  // the contract's vectors with three components are vectors_3d's view
  CHECK(view_of(R"({"kind":"vectors","u":[1,2,3],"v":[-2,0,1]})")["kind"] == "vectors_3d");
  CHECK(view_of(R"({"kind":"vectors","u":[1,2],"v":[-2,0]})")["kind"] == "vectors");

  const std::string sphere = R"({"kind":"ray_sphere","A":[-5,1,2],"u":[2,0,0],"C":[0,0,1],"r":3})";
  const json v = view_of(sphere);
  std::vector<std::string> ids;
  for (const auto& h : v["handles"]) ids.push_back(h["id"]);
  CHECK(ids == std::vector<std::string>{"A", "C", "u", "r"});
  const std::string frame = v["frame"].dump();
  // Where would A be at (1, −2, 2)? Its handle there, in the view of that instance (the frame
  // held still; the panel's place on the page follows the other panel, so the drag is given the
  // frame that view returned, as the page does). Dragged there in the horizontal plane (z = 2
  // kept), A lands on it.
  const json target = view_of(with_field(sphere, "A", {1, -2, 2}).dump(), "en", frame);
  const json at = handle(target, "A");
  const std::string frame2 = target["frame"].dump();
  const json floor = json::parse(ex::drag(sphere, "A", at["x"], at["y"], frame2, false));
  CHECK(floor["A"] == json::array({1, -2, 2}));
  CHECK(floor["C"] == json::array({0, 0, 1}));
  // In height mode, to where A would be at (−5, 1, 4): x and y kept, z = 4.
  const json above = view_of(with_field(sphere, "A", {-5, 1, 4}).dump(), "en", frame);
  const json at4 = handle(above, "A");
  const json height = json::parse(ex::drag(sphere, "A", at4["x"], at4["y"], above["frame"].dump(), false, true));
  CHECK(height["A"] == json::array({-5, 1, 4}));
  // the same page point in the horizontal plane keeps z
  CHECK(json::parse(ex::drag(sphere, "A", at4["x"], at4["y"], above["frame"].dump(), false))["A"][2] == 2);
  // straight up on the page: z grows, by the height the pointer moved over cos(elevation)
  const json a = handle(v, "A");
  const json up = json::parse(ex::drag(sphere, "A", a["x"], a["y"].get<double>() - 40, frame, true, true));
  CHECK(up["A"][0] == -5);
  CHECK(up["A"][1] == 1);
  CHECK(up["A"][2].get<double>() > 2);
  // the tip of u: in its horizontal plane, u.z kept; the direction is never dragged to zero
  const json tip = json::parse(ex::drag(sphere, "u", at["x"], at["y"], frame2, false));
  CHECK(tip["u"] == json::array({6, -3, 0}));  // (1, −2, 2) − A, z kept at A's
  const json on_a = json::parse(ex::drag(R"({"kind":"ray_sphere","A":[-5,1,2],"u":[2,0,0],"C":[0,0,1],"r":3})", "u",
                                         a["x"], a["y"], frame, false));
  CHECK(on_a["u"] == json::array({2, 0, 0}));
  // r: the distance from C's image to the pointer (the outline is a circle of radius r)
  const json r = handle(v, "r"), c = handle(v, "C");
  const double scale = (r["x"].get<double>() - c["x"].get<double>()) / 3;
  const json grown = json::parse(ex::drag(sphere, "r", c["x"].get<double>() + 4.5 * scale, c["y"], frame, false));
  CHECK(grown["r"] == 4.5);
}

TEST_CASE("explore: keyboard in space: arrows along the floor axes as the screen shows them, PageUp/PageDown along z") {
  const std::string cube = R"({"kind":"ray_cube","A":[3,-2,1.5],"u":[-1,0.5,0]})";
  // with the views' camera (azimuth 30°): y goes right, x comes down towards the viewer
  CHECK(json::parse(ex::nudge(cube, "A", 1, 0, 0, false))["A"] == json::array({3, -1.9, 1.5}));
  CHECK(json::parse(ex::nudge(cube, "A", -1, 0, 0, false))["A"] == json::array({3, -2.1, 1.5}));
  CHECK(json::parse(ex::nudge(cube, "A", 0, 1, 0, false))["A"] == json::array({2.9, -2, 1.5}));
  CHECK(json::parse(ex::nudge(cube, "A", 0, -1, 0, true))["A"] == json::array({4, -2, 1.5}));
  CHECK(json::parse(ex::nudge(cube, "A", 0, 0, 1, false))["A"] == json::array({3, -2, 1.6}));
  CHECK(json::parse(ex::nudge(cube, "u", 0, 0, -1, true))["u"] == json::array({-1, 0.5, -1}));
  // never a zero direction
  CHECK(json::parse(ex::nudge(R"({"kind":"ray_cube","A":[3,0,0],"u":[0,0,0.1]})", "u", 0, 0, -1, false))["u"] ==
        json::array({0, 0, 0.1}));
  // r grows with → and shrinks with ←, never to zero
  const std::string sphere = R"({"kind":"ray_sphere","A":[-5,1,2],"u":[2,0,0],"C":[0,0,1],"r":0.1})";
  CHECK(json::parse(ex::nudge(sphere, "r", 1, 0, 0, false))["r"] == 0.2);
  CHECK(json::parse(ex::nudge(sphere, "r", -1, 0, 0, false))["r"] == 0.1);
}

TEST_CASE("explore: the page's words come from the templates, in both languages") {
  const json en = json::parse(ex::words("en")), fr = json::parse(ex::words("fr"));
  CHECK(en["snap"] == "snap to grid");
  CHECK(fr["snap"] == "grille magnétique");
  CHECK(en.size() == fr.size());
  for (const auto& item : en.items()) {  // not a structured binding: CHECK's lambda captures it (clang 14)
    const std::string key = item.key();
    CAPTURE(key);
    CHECK(fr.contains(key));
  }
  CHECK(std::string(en["hint_space"]).find("Shift") != std::string::npos);
}

TEST_CASE("explore: tabs named as the course names the exercises; a view outside a sheet is not 'Exercise 1'") {
  const json kinds = json::parse(ex::kinds());
  for (const char* lang : {"en", "fr"}) {
    const json w = json::parse(ex::words(lang));
    CHECK(w["title"] != "");
    for (const auto& k : kinds) {
      const std::string kind = k.get<std::string>();
      CAPTURE(lang);
      CAPTURE(kind);
      REQUIRE(w.contains("tab." + kind));
      const std::string tab = w["tab." + kind];
      CHECK(tab.find('_') == std::string::npos);  // not the internal name
      CHECK(tab != kind);
    }
  }
  CHECK(json::parse(ex::words("fr"))["tab.ray_circle"] == "Rayon / cercle");
  CHECK(json::parse(ex::words("fr"))["title"] != json::parse(ex::words("en"))["title"]);

  // the key's heading: the exercise's name alone outside a sheet, "Exercice 3 — …" as the third
  // exercise of one
  const std::string start = ex::starting_instance("ray_circle");
  const std::string alone = json::parse(ex::view(start, "fr"))["steps"];
  CHECK(alone.rfind("<h2>Intersection d’un rayon et d’un cercle</h2>", 0) == 0);
  const std::string third = json::parse(ex::view(start, "fr", 3))["steps"];
  CHECK(third.rfind("<h2>Exercice 3 — Intersection d’un rayon et d’un cercle</h2>", 0) == 0);
  // the fourth exercise of the course's sheet is its "Exercice 3": the sheet's label wins
  const std::string labelled = json::parse(ex::view(start, "fr", 4, {}, "Exercice 3"))["steps"];
  CHECK(labelled.rfind("<h2>Exercice 3 — Intersection d’un rayon et d’un cercle</h2>", 0) == 0);
}

TEST_CASE("explore: the view in parts is the view; without tolerances the key reads the same") {
  using namespace epure;
  for (const ExerciseKind* kind : all_kinds()) {
    CAPTURE(kind->name());
    const std::string start = ex::starting_instance(kind->name());
    for (const char* lang : {"en", "fr"}) {
      CAPTURE(lang);
      // view_parts: head is view's object without "svg" and "steps", which come as they are
      const ex::ViewParts parts = ex::view_parts(start, lang);
      json whole = json::parse(ex::view(start, lang));
      CHECK(whole.at("svg") == parts.svg);
      CHECK(whole.at("steps") == parts.steps);
      whole.erase("svg");
      whole.erase("steps");
      CHECK(whole == json::parse(parts.head));

      // The page skips the method's dual run (the tolerances, which only marking uses): the
      // solution, the expected answers and the key's text and figure are the same without it.
      ExerciseSpec spec;
      spec.kind = std::string(kind->name());
      const Texts& texts = Texts::builtin(lang);
      ExerciseContext marked{1, spec, texts, NumberStyle::for_language(lang), 2, ""};
      ExerciseContext shown = marked;
      shown.tolerances = false;
      const json instance = json::parse(start);
      const ExerciseInstance a = kind->key_of(instance, marked), b = kind->key_of(instance, shown);
      CHECK(a.solution == b.solution);
      REQUIRE(a.questions.size() == b.questions.size());
      for (std::size_t i = 0; i < a.questions.size(); ++i) {
        CHECK(a.questions[i].field == b.questions[i].field);
        CHECK(a.questions[i].expected == b.questions[i].expected);
        CHECK(a.questions[i].exact == b.questions[i].exact);
      }
      epure::render::Document da, db;
      da.sections.push_back(a.key);
      db.sections.push_back(b.key);
      CHECK(epure::render::document_to_svg(da) == epure::render::document_to_svg(db));
    }
  }
}

TEST_CASE("explore page: a label may hold anything; the configuration still parses and ends where it should") {
  if (!epure::output::explore_available()) return;  // a build without the page (the ASan one)
  const epure::output::ExerciseLabels labels{{"en", {"<!--<script>", "</script><b>"}}};
  const std::string html = epure::output::explore_html("en", {}, labels);
  const std::string open = "<script id=\"epure-config\" type=\"application/json\">";
  const std::size_t at = html.find(open);
  REQUIRE(at != std::string::npos);
  const std::size_t end = html.find("</script>", at);
  REQUIRE(end != std::string::npos);
  const std::string config = html.substr(at + open.size(), end - at - open.size());
  CHECK(config.find('<') == std::string::npos);  // neither "</" nor "<!--" inside the element
  CHECK(json::parse(config)["labels"]["en"] == json({"<!--<script>", "</script><b>"}));
  CHECK(html.find("<!--<script>") == std::string::npos);
}

TEST_CASE("explore: a number keeps every digit written; a verdict that depends on digits beyond a double's is solve's") {
  // 1. Digits beyond the 17th that decide nothing: the view's instance keeps them, its solution
  // is `epure solve`'s for them to the bit, and a drag of another datum keeps them too.
  const std::string long_c = R"({"kind":"projection","A":[0,0],"B":[2,0],"C":[1.00000000000000000001,5]})";
  const json v = view_of(long_c);
  REQUIRE(!v.contains("error"));
  CHECK(v["instance"].get<std::string>().find("1.00000000000000000001") != std::string::npos);
  CHECK(v["solution"] == json::parse(ex::solve(long_c)));
  const json b = handle(v, "B");
  const std::string dragged = ex::drag(long_c, "B", b["x"].get<double>() + 20, b["y"], v["frame"].dump(), false);
  CHECK(dragged.find("1.00000000000000000001") != std::string::npos);
  CHECK(json::parse(dragged)["B"] != json::array({2, 0}));
  const std::string nudged = ex::nudge(long_c, "A", 1, 0, 0, false);
  CHECK(nudged.find("1.00000000000000000001") != std::string::npos);
  CHECK(json::parse(view_of(dragged)["instance"].get<std::string>()) == json::parse(dragged));
  CHECK(view_of(dragged)["solution"] == json::parse(ex::solve(dragged)));
  // vectors in the plane decide nothing: u is one tenth exactly, its cross product with (1, 3)
  // not 0, as solve says; the steps' two decimals show the same
  const std::string tenth = R"({"kind":"vectors","u":[0.1000000000000000055511151231257827,0.3],"v":[1,3]})";
  const json t = view_of(tenth);
  REQUIRE(!t.contains("error"));
  CHECK(t["solution"] == json::parse(ex::solve(tenth)));
  CHECK(t["solution"]["cross"].get<double>() > 0);
  CHECK(json::parse(t["instance"].get<std::string>()) == json::parse(tenth));
  CHECK(t["instance"].get<std::string>().find("0.1000000000000000055511151231257827") != std::string::npos);

  // 2. Digits beyond the 17th that decide: parallel as written, not as the doubles (and the
  // other way round), not collinear as written though the doubles are. The worked steps, in
  // doubles, cannot follow: the view says so with `epure solve`'s answer, never the doubles'.
  struct Case {
    std::string line, verdict;
  };
  const Case cases[] = {
      {R"({"kind":"segments","A":[0,0],"B":[3,1],"C":[0,1],"D":[0.37037036703703703673,1.12345678901234567891]})",
       R"("reason":"parallel")"},
      {R"({"kind":"segments","A":[0,0],"B":[3,3],"C":[1,0],"D":[2,1.0000000000000000000001]})", R"("reason":"outside")"},
      {R"({"kind":"vectors","u":[8.44,3.98,-7.98],"v":[33.76,15.92,-3.19199999999999999996624e1]})",
       R"("collinear":false)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.line);
    const std::string solved = ex::solve(c.line);
    CHECK(solved.find(c.verdict) != std::string::npos);
    const json w = view_of(c.line);
    REQUIRE(w.contains("error"));
    CHECK(w["error"].get<std::string>().find(solved) != std::string::npos);
    CHECK(w["solution"] == json::parse(solved));
  }
}

TEST_CASE("explore: a figure of tiny scale gets its view (its grid numbers' phases are counted, not looped over)") {
  // decimal_cases.py's seed 35: a millionth-scale ellipse; the grid's numbers were thinned by a
  // loop over every k-th phase, k about the numbers' width over a grid pitch of a hair, that
  // never ended (the explorer's page froze)
  const json v = view_of(
      R"({"kind":"ray_ellipse","A":[2.88294999999999e-7,0.00000178082],"u":[-0.000000021403846,-0.000000144415385],)"
      R"("C":[0.00000047257,0.00000083897],"radii":[0.00000053235,0.00000053235],"angle":-275.5})");
  CHECK((v.contains("svg") || v.contains("error")));
}
