#include "scan/scan_outputs.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <set>
#include <stdexcept>

#include "embed/embedded.h"
#include "exercises/texts.h"
#include "output/atomic_file.h"
#include "render/markup_escape.h"
#include "support/base64.h"
#include "support/safe_file_name.h"

namespace epure::scan {

namespace {

using nlohmann::json;

std::string csv_cell(std::string_view s, char delimiter) {
  if (s.find_first_of(std::string{delimiter, '"', '\n', '\r'}) == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// A value `epure grade` marks: read for sure, or settled by a correction.
bool usable(const FieldResult& f) { return !f.reading.uncertain && !f.reading.blank; }

void replace_all(std::string& s, std::string_view what, std::string_view with) {
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size())) s.replace(at, what.size(), with);
}

}  // namespace

std::size_t fields_to_review(const ScanResult& result) {
  std::size_t n = 0;
  for (const auto& [id, s] : result.sheets)
    for (const auto& [q, f] : s.fields) n += f.reading.uncertain;
  return n;
}

std::string answers_json(const ScanResult& result) {
  json rows = json::array();
  for (const auto& [id, s] : result.sheets) {
    json answers = json::object();
    for (const auto& [q, f] : s.fields)
      if (q != "student_number" && usable(f)) answers[q] = f.reading.value;
    json row = {{"sheet", id}};
    if (!s.student_name.empty()) row["student"] = s.student_name;
    row["answers"] = std::move(answers);
    rows.push_back(std::move(row));
  }
  return rows.dump(1) + "\n";
}

std::string answers_csv(const ScanResult& result, const SetLayout& layout) {
  const char d = layout.decimal_separator == "," ? ';' : ',';
  std::set<std::string> questions;
  for (const auto& [id, s] : result.sheets)
    for (const auto& [q, f] : s.fields)
      if (q != "student_number") questions.insert(q);
  std::string out = fmt::format("sheet{}student", d);
  for (const auto& q : questions) out += d + csv_cell(q, d);
  out += "\n";
  for (const auto& [id, s] : result.sheets) {
    out += csv_cell(id, d) + d + csv_cell(s.student_name, d);
    for (const auto& q : questions) {
      out += d;
      auto it = s.fields.find(q);
      if (it != s.fields.end() && usable(it->second)) out += csv_cell(it->second.reading.value, d);
    }
    out += "\n";
  }
  return out;
}

std::string pages_csv(const ScanResult& result) {
  std::string out = "file,page,sheet,sheet_page,status,marks,residual_pt,detail\n";
  for (const auto& p : result.pages)
    out += fmt::format("{},{},{},{},{},{},{:.2f},{}\n", csv_cell(p.file, ','), p.page, p.sheet,
                       p.sheet_page > 0 ? std::to_string(p.sheet_page) : "", page_status_name(p.status), p.marks, p.residual,
                       csv_cell(p.detail, ','));
  return out;
}

std::string sheets_csv(const ScanResult& result) {
  std::string out = "sheet,pages,pages_read,pages_missing,student_number_read,student_number_roster,roster_match,fields_read,fields_blank,fields_to_review,fields_corrected\n";
  for (const auto& [id, s] : result.sheets) {
    std::string missing;
    int read = 0;
    for (std::size_t i = 0; i < s.seen.size(); ++i) {
      if (s.seen[i]) ++read;
      else missing += (missing.empty() ? "" : " ") + std::to_string(i + 1);
    }
    int values = 0, blank = 0, review = 0, corrected = 0;
    for (const auto& [q, f] : s.fields) {
      review += f.reading.uncertain;
      blank += !f.reading.uncertain && f.reading.blank;
      values += usable(f);
      corrected += f.corrected;
    }
    const char* match = s.roster_number.empty()    ? ""
                        : s.number_printed         ? "printed"
                        : s.student_number.empty() ? "not read"
                        : s.student_number == s.roster_number ? "yes"
                                                              : "no";
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", id, s.pages, read, missing, s.student_number, s.roster_number, match,
                       values, blank, review, corrected);
  }
  return out;
}

std::string fields_csv(const ScanResult& result) {
  std::string out = "sheet,page,question,status,value,confidence,cells,cell_confidence,why\n";
  for (const auto& [id, s] : result.sheets)
    for (const auto& [q, f] : s.fields) {
      const char* status = f.corrected ? "corrected" : f.reading.uncertain ? "review" : f.reading.blank ? "blank" : "read";
      std::string cells = f.reading.chars;
      for (const auto& t : f.reading.ticks) cells += (cells.empty() ? "" : " ") + std::string(tick_state_name(t.state)) + fmt::format("({:.2f})", t.filled);
      std::string conf;
      for (const auto& c : f.reading.cells) conf += fmt::format("{}{}:{:.3f}", conf.empty() ? "" : " ", class_char(c.best) == ' ' ? '_' : class_char(c.best), c.confidence);
      out += fmt::format("{},{},{},{},{},{:.4f},{},{},{}\n", id, f.page, csv_cell(q, ','), status, csv_cell(f.reading.value, ','),
                         f.reading.confidence, csv_cell(cells, ','), conf, csv_cell(f.reading.why, ','));
    }
  return out;
}

void write_review_html(const ScanResult& result, const SetLayout& layout, const std::function<void(std::string_view)>& out) {
  const Texts& t = Texts::builtin(layout.language == "fr" ? "fr" : "en");
  json words = {{"sheet", t.get("scan.sheet")},       {"page", t.get("scan.page")},     {"question", t.get("scan.question")},
                {"proposed", t.get("scan.proposed")}, {"why", t.get("scan.why")},       {"saved", t.get("scan.saved")},
                {"reviewed", t.get("scan.reviewed")}, {"none", t.get("scan.review_none")}};
  std::string page(*embedded_data("review.html"));
  replace_all(page, "{{LANG}}", layout.language == "fr" ? "fr" : "en");
  replace_all(page, "{{TITLE}}", render::markup_escaped(t.get("scan.review_title")));
  replace_all(page, "{{INTRO}}", render::markup_escaped(t.get("scan.review_intro")));
  replace_all(page, "{{SAVE}}", render::markup_escaped(t.get("scan.save")));
  // The data, {"fields":[...],"words":{...}} as one compact JSON dump writes it (keys in order),
  // written a field at a time: each field's crop is read back from the spool only to be written.
  // Inside a <script> element no "</" may close it early and no "<!--" may open the script's
  // escaped state (a question id comes from layout.json): every '<' is written as \u003c, which
  // JSON reads back as the same character (as explore.html's configuration is written).
  constexpr std::string_view kData = "{{DATA}}";
  const std::size_t at = page.find(kData);
  if (at == std::string::npos) throw std::logic_error("review.html has no {{DATA}}");
  out(std::string_view(page).substr(0, at));
  out("{\"fields\":[");
  bool first = true;
  for (const auto& [id, s] : result.sheets)
    for (const auto& [q, f] : s.fields)
      if (f.reading.uncertain) {
        const json field = {{"sheet", id}, {"page", f.page}, {"question", q}, {"proposed", f.reading.value},
                            {"why", f.reading.why}, {"crop", base64(result.crop(f))}};
        std::string data = field.dump();
        replace_all(data, "<", "\\u003c");
        if (!first) out(",");
        first = false;
        out(data);
      }
  std::string data = words.dump();
  replace_all(data, "<", "\\u003c");
  out("],\"words\":");
  out(data);
  out("}");
  out(std::string_view(page).substr(at + kData.size()));
}

std::string review_html(const ScanResult& result, const SetLayout& layout) {
  std::string page;
  write_review_html(result, layout, [&](std::string_view bytes) { page += bytes; });
  return page;
}

void say_crops_not_written(ScanResult& result) {
  for (const auto& [id, s] : result.sheets)
    for (const auto& [q, f] : s.fields)
      if (q != "student_number" && (!safe_file_name(id) || !safe_file_name(q)))
        result.problems.push_back(fmt::format("sheet {}: field {}: its id cannot be a file name: no crop written", id, q));
}

void write_scan_outputs(const std::filesystem::path& dir, const ScanResult& result, const SetLayout& layout) {
  std::filesystem::create_directories(dir);
  output::write_file_atomically(dir / "answers.json", answers_json(result));
  output::write_file_atomically(dir / "answers.csv", answers_csv(result, layout));
  output::write_file_atomically(dir / "pages.csv", pages_csv(result));
  output::write_file_atomically(dir / "sheets.csv", sheets_csv(result));
  output::write_file_atomically(dir / "fields.csv", fields_csv(result));
  output::AtomicFile review(dir / "review.html");
  write_review_html(result, layout, [&](std::string_view bytes) { review.write(bytes); });
  review.commit();
}

}  // namespace epure::scan
