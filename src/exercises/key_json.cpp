#include "exercises/key_json.h"

#include "solve/json_out.h"

namespace epure {

namespace {

void write_expected(JsonWriter& w, const Expected& e) {
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) w.number(v);
        else if constexpr (std::is_same_v<T, bool>) w.boolean(v);
        else if constexpr (std::is_same_v<T, std::string>) w.string(v);
        else {
          w.begin_array();
          for (const auto& s : v) w.string(s);
          w.end_array();
        }
      },
      e);
}

std::string_view rule_name(ToleranceRule::Kind k) {
  switch (k) {
    case ToleranceRule::Kind::exact: return "exact";
    case ToleranceRule::Kind::isclose: return "isclose";
    case ToleranceRule::Kind::distance: return "distance";
  }
  return "?";
}

}  // namespace

void KeyJson::begin(fmt::memory_buffer& out, const WorksheetSet& set, std::string_view epure_version) {
  const auto& spec = set.spec();
  JsonWriter w(out);
  w.begin_object();
  w.key("spec").begin_object();
  w.field("source", std::string_view(spec.source));
  w.field("title", std::string_view(spec.title));
  w.field("course", std::string_view(spec.course));
  w.field("language", std::string_view(set.language()));
  w.key("decimals").integer(spec.decimals);
  w.field("follow_through", spec.follow_through);
  if (spec.scale) w.field("scale", *spec.scale);  // only when set: keys without one are unchanged
  w.field("text", std::string_view(spec.text));
  w.end_object();
  w.key("seed").integer(static_cast<long long>(set.seed()));
  w.key("version").begin_object();
  w.field("epure", epure_version);
  w.key("draw").integer(kDrawVersion);
  w.end_object();
  w.key("sheets");
  out.push_back('[');
}

void KeyJson::sheet(fmt::memory_buffer& out, const Sheet& sheet, bool first, const SheetStudent* student) {
  if (!first) out.push_back(',');
  out.push_back('\n');
  JsonWriter w(out);
  w.begin_object();
  w.field("id", std::string_view(sheet.id.str()));
  w.key("index").integer(sheet.id.index);
  if (student) {
    w.key("student").begin_object();
    w.field("number", std::string_view(student->number));
    w.field("name", std::string_view(student->name));
    if (!student->email.empty()) w.field("email", std::string_view(student->email));
    w.end_object();
  }
  w.key("exercises").begin_array();
  for (const auto& e : sheet.exercises) {
    w.begin_object();
    w.key("n").integer(e.n);
    // the number its ids start with ("3.3"), when it is not n (key.json before it: always n)
    const std::string number = e.number.empty() ? std::to_string(e.n) : e.number;
    if (number != std::to_string(e.n)) w.field("number", std::string_view(number));
    w.field("kind", std::string_view(e.kind));
    w.field("branch", std::string_view(e.branch));
    w.key("instance").raw(e.instance);
    w.key("solution").raw(e.solution);
    w.key("questions").begin_array();
    for (const auto& q : e.questions) {
      w.begin_object();
      w.field("id", std::string_view(fmt::format("{}.{}", number, q.field)));
      w.key("expected");
      write_expected(w, q.expected);
      if (q.exact) w.field("exact", std::string_view(*q.exact));
      w.key("tolerance").begin_object();
      w.field("rule", rule_name(q.tolerance.kind));
      if (q.tolerance.kind != ToleranceRule::Kind::exact) {
        if (q.tolerance.kind == ToleranceRule::Kind::isclose) w.field("rel", q.tolerance.rel);
        w.field("abs", q.tolerance.abs);
        if (q.tolerance.follow_abs > 0) w.field("follow_abs", q.tolerance.follow_abs);
      }
      w.field("why", std::string_view(q.tolerance.why));
      w.end_object();
      w.field("points", q.points);
      if (!q.point_group.empty()) w.field("point", std::string_view(fmt::format("{}.{}", number, q.point_group)));
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

void KeyJson::end(fmt::memory_buffer& out) {
  out.push_back('\n');
  out.push_back(']');
  out.push_back('}');
  out.push_back('\n');
}

}  // namespace epure
