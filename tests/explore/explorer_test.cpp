// The explorer's core (src/explore/explorer.h), natively: what the page shows and how a drag
// moves the data. The page itself is tested in a browser (tests/browser/).
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "explore/explorer.h"
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

TEST_CASE("explore: every 2D kind has a view with its handles, steps and the key's figure") {
  const json kinds = json::parse(ex::kinds());
  CHECK(kinds.size() >= 7);
  for (const auto& k : kinds) {
    const std::string kind = k.get<std::string>();
    CAPTURE(kind);
    const json v = view_of(ex::starting_instance(kind));
    REQUIRE_FALSE(v.contains("error"));
    CHECK(v["kind"] == kind);
    // The 3D views have no drag handles yet (a drag on a projected view needs a plane to move in).
    if (kind == "ray_sphere" || kind == "ray_cube") CHECK(v["handles"].empty());
    else CHECK(v["handles"].size() >= 2);
    const std::string svg = v["svg"];
    for (const auto& h : v["handles"]) CHECK(svg.find("data-handle=\"" + h["id"].get<std::string>() + "\"") != std::string::npos);
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(std::string(v["steps"]).size() > 100);
    // the key's solution is the one `epure solve` gives the same data (worksheet semantics)
    CHECK(v["solution"]["kind"] == kind);
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
  const json far = json::parse(ex::nudge(start, "C", 3, 0, true));  // C to (5, 3): P after B
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
  CHECK(json::parse(ex::nudge(circle, "r", 1, 0, true))["r"] == 4);
  const std::string ellipse = R"({"kind":"ray_ellipse","A":[-6,1],"u":[1,0],"C":[0,0],"radii":[3,2],"angle":0})";
  // the first axis's end moved to (0, 3): a = 3, angle 90
  const json e = json::parse(ex::nudge(ellipse, "radii.0", -3, 3, true));
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

TEST_CASE("explore: solve is epure solve's line, exact semantics") {
  const std::string line = R"({"kind":"ray_circle","A":[-5,1],"u":[2,0],"C":[0,0],"r":3})";
  fmt::memory_buffer out;
  epure::solve::solve_line(line, out, epure::solve::Semantics::exact);
  CHECK(ex::solve(line) == std::string(out.data(), out.size()));
}
