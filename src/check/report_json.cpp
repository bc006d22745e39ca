#include "check/report_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "check/judge.h"
#include "output/atomic_file.h"

#ifndef EPURE_VERSION
#define EPURE_VERSION "0.0.0"
#endif

namespace epure::check {

namespace {

using nlohmann::json;

// A number for JSON: NaN and the infinities (an out-parameter left unset) as null.
json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json values_json(const std::vector<NamedValue>& values) {
  json j = json::object();
  for (const auto& v : values) {
    if (v.values.size() == 1) {
      j[v.name] = number(v.values[0]);
    } else {
      json a = json::array();
      for (double x : v.values) a.push_back(number(x));
      j[v.name] = a;
    }
  }
  return j;
}

json outcome_json(Fn fn, const Outcome& o) {
  json j = values_json(named_outputs(fn, o));
  if (info(fn).returns_bool) j["returned"] = o.hit;
  return j;
}

}  // namespace

std::vector<NamedValue> named_inputs(const Case& c) {
  const Inputs& in = c.in;
  auto v2 = [&](const char* n, int i) { return NamedValue{n, {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1]}}; };
  auto v3 = [&](const char* n, int i) {
    return NamedValue{n, {in[static_cast<std::size_t>(i)], in[static_cast<std::size_t>(i) + 1], in[static_cast<std::size_t>(i) + 2]}};
  };
  auto s = [&](const char* n, int i) { return NamedValue{n, {in[static_cast<std::size_t>(i)]}}; };
  switch (c.fn) {
    case Fn::projection: return {v2("A", 0), v2("B", 2), v2("C", 4)};
    case Fn::segments: return {v2("A", 0), v2("B", 2), v2("C", 4), v2("D", 6)};
    case Fn::circle: return {v2("A", 0), v2("u", 2), v2("C", 4), s("r", 6)};
    case Fn::circle_canonical:
    case Fn::square_canonical: return {v2("A", 0), v2("u", 2)};
    case Fn::ellipse: return {v2("A", 0), v2("u", 2), v2("C", 4), s("a", 6), s("b", 7), s("angle_deg", 8)};
    case Fn::rectangle: return {v2("A", 0), v2("u", 2), v2("C", 4), s("w", 6), s("h", 7), s("angle_deg", 8)};
    case Fn::sphere: return {v3("A", 0), v3("u", 3), v3("C", 6), s("r", 9)};
    case Fn::cube_canonical: return {v3("A", 0), v3("u", 3)};
  }
  return {};
}

std::vector<NamedValue> named_outputs(Fn fn, const Outcome& o) {
  const FunctionInfo& f = info(fn);
  if (f.returns_bool && !o.hit) return {};
  const char* point = fn == Fn::projection ? "P" : fn == Fn::segments ? "I" : "J";
  std::vector<NamedValue> out;
  out.push_back({point, {o.out.begin(), o.out.begin() + f.dimension}});
  if (f.has_normal) out.push_back({"N", {o.out.begin() + f.dimension, o.out.begin() + 2 * f.dimension}});
  return out;
}

void write_report_json(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& path) {
  json j;
  j["epure_version"] = EPURE_VERSION;
  j["seed"] = options.seed;
  j["tolerance"] = {
      {"points", "1e-6·L + 64ε·S (L: the figure's size, the largest coordinate of its centre or of its sizes, 1 for a "
                 "canonical figure, the data for a projection or segments; S: the largest coordinate of the data)"},
      {"normals", "the points' tolerance divided by the figure's smallest size (r; min(a,b)²/max(a,b); min(w,h); 1)"},
      {"decisions", "exact, except within the rounding of the data of a boundary (each coordinate moved by 2^-40·S, "
                    "the data read as decimals, segments parallel within rounding): the answer for such nearby data "
                    "is right too; at a corner either side's normal"}};
  json counts = json::object();
  for (const auto& [fn, n] : result.cases_per_function) counts[std::string(info(fn).name)] = n;
  j["standard_cases"] = counts;
  json files = json::array();
  for (const FileReport& f : result.files) {
    json file;
    file["file"] = f.path.string();
    file["student"] = f.student;
    file["sheet"] = f.sheet.empty() ? json(nullptr) : json(f.sheet);
    file["status"] = f.status == Verdict::passed ? "checked" : std::string(verdict_name(f.status));
    if (f.refusal)
      file["refusal"] = {{"line", f.refusal->line}, {"code", f.refusal->code}, {"detail", f.refusal->detail}};
    json compiler = json::array();
    for (const auto& m : f.compiler)
      compiler.push_back({{"severity", m.severity}, {"line", m.line}, {"column", m.column}, {"message", m.text}});
    file["compiler"] = compiler;
    json functions = json::object();
    for (const FunctionReport& r : f.functions) {
      json fr;
      fr["cases"] = r.cases;
      fr["passed"] = r.passed;
      fr["failed"] = r.failed;
      fr["verdict"] = verdict_name(r.verdict);
      fr["bug"] = r.bugs.empty() ? json(nullptr) : json(bug_code(r.bugs.front()));
      json bugs = json::array();
      for (Bug b : r.bugs) bugs.push_back(bug_code(b));
      fr["bugs"] = bugs;
      if (!r.reason.empty()) fr["reason"] = r.reason;
      if (!r.reason_code.empty()) fr["reason_code"] = r.reason_code;
      fr["mark"] = r.mark;
      json by = json::object();
      for (const auto& [c, n] : r.failed_by_category) by[std::string(category_name(c))] = n;
      fr["failed_by_category"] = by;
      json failures = json::array();
      for (const FailedCase& c : r.failures) {
        Case k{r.fn, c.category, c.in};
        json fc;
        fc["case"] = c.index;
        fc["category"] = category_name(c.category);
        fc["input"] = values_json(named_inputs(k));
        fc["expected"] = outcome_json(r.fn, c.expected);
        fc["got"] = c.got ? outcome_json(r.fn, *c.got) : json(nullptr);
        failures.push_back(fc);
      }
      fr["failures"] = failures;
      if (r.output_bytes > 0) {
        fr["output"] = r.output;
        fr["output_bytes"] = r.output_bytes;
      }
      functions[std::string(info(r.fn).name)] = fr;
    }
    file["functions"] = functions;
    json not_written = json::array();
    for (Fn fn : f.not_written) not_written.push_back(info(fn).name);
    file["not_written"] = not_written;
    file["notes"] = f.notes;
    file["total"] = f.total;
    file["feedback"] = options.feedback ? json("feedback/" + f.feedback + ".html") : json(nullptr);
    files.push_back(file);
  }
  j["files"] = files;
  // a student's output may hold any bytes: replaced, not refused
  output::write_file_atomically(path, j.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace epure::check
