// The teacher's corrections file: exactly the shared shape {"format": "epure-corrections",
// "version": 1, "corrections": [{sheet, question, value, note?}]}, unknown keys ignored, each
// bad entry said with its number and the rest applied; applied by a grading run before marking.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "grading/answer_source.h"
#include "grading/corrections.h"
#include "grading/session.h"

using namespace epure::grading;

namespace {
bool has(const Corrections& c, int entry, const std::string& code) {
  for (const auto& p : c.problems)
    if (p.entry == entry && p.code == code) return true;
  return false;
}
}  // namespace

TEST_CASE("the shape of a corrections file") {
  SUBCASE("1. every field, unknown keys ignored, a BOM") {
    const auto c = read_corrections("\xef\xbb\xbf{\"format\": \"epure-corrections\", \"version\": 1, \"written_by\": \"review.html\","
                                    "\"corrections\": [{\"sheet\": \"1000-0005-002N\", \"question\": \"2.t\", \"value\": \"−0,48\","
                                    " \"note\": \"read on paper\", \"crop\": \"p1.png\"},"
                                    "{\"sheet\": \"1000-0005-002N\", \"question\": \"student_number\", \"value\": \"21804512\"}]}",
                                    "c.json");
    CHECK(c.readable);
    CHECK(c.problems.empty());
    REQUIRE(c.entries.size() == 2);
    CHECK(c.entries[0].entry == 1);
    CHECK(c.entries[0].sheet == "1000-0005-002N");
    CHECK(c.entries[0].question == "2.t");
    CHECK(c.entries[0].value == "−0,48");
    CHECK(c.entries[0].note == "read on paper");
    CHECK(c.entries[1].question == "student_number");
  }
  SUBCASE("2. a bad entry is said with its number; the others are kept") {
    const auto c = read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [
      {"sheet": "A", "question": "2.t", "value": 3},
      {"sheet": "A", "value": "3"},
      "2.t = 3",
      {"sheet": "", "question": "2.t", "value": "3"},
      {"sheet": "A", "question": "2.t", "value": "3", "note": 5},
      {"sheet": "A", "question": "2.t", "value": ""}]})",
                                    "c.json");
    CHECK(c.readable);
    CHECK(has(c, 1, "value_not_string"));
    CHECK(has(c, 2, "missing"));
    CHECK(has(c, 3, "entry_not_object"));
    CHECK(has(c, 4, "empty"));
    CHECK(has(c, 5, "not_string"));
    REQUIRE(c.entries.size() == 1);  // an empty value: the answer left empty
    CHECK(c.entries[0].entry == 6);
  }
  SUBCASE("3. a file that is not one stops, with why") {
    for (const auto& [text, code] : std::vector<std::pair<std::string, std::string>>{
             {"", "not_json"},
             {"[1, 2]", "not_object"},
             {R"({"format": "epure-answers", "version": 1, "corrections": []})", "bad_format"},
             {R"({"version": 1, "corrections": []})", "bad_format"},
             {R"({"format": "epure-corrections", "version": 2, "corrections": []})", "bad_version"},
             {R"({"format": "epure-corrections", "version": "1", "corrections": []})", "bad_version"},
             {R"({"format": "epure-corrections", "version": 1, "corrections": {}})", "no_list"},
             {std::string(100, '[') + std::string(100, ']'), "too_deep"},
             {R"({"format": "epure-corrections", "version": 1, "corrections": [1e400]})", "not_json"}}) {
      CAPTURE(text);
      const auto c = read_corrections(text, "c.json");
      CHECK_FALSE(c.readable);
      CHECK(c.entries.empty());
      REQUIRE(c.problems.size() == 1);
      CHECK(c.problems[0].code == code);
      CHECK(c.problems[0].entry == 0);
    }
  }
  SUBCASE("4. every problem reads in both languages") {
    const auto c = read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [{"sheet": "A", "value": 3}]})", "c.json");
    for (const char* language : {"en", "fr"})
      for (const auto& p : c.problems) {
        const std::string text = describe(p, epure::Texts::builtin(language));
        CHECK(text.find("${") == std::string::npos);
        CHECK(text.find("1") != std::string::npos);  // the entry's number
      }
  }
}

namespace {
const AnswerKey& key() {
  static const AnswerKey k = [] {
    std::ifstream in(EPURE_SOURCE_DIR "/tests/grading/data/key_small.json");
    std::stringstream s;
    s << in.rdbuf();
    return read_key_json(s.str(), "key_small.json");
  }();
  return k;
}

struct Rows final : SubmissionSink {
  std::vector<Submission> all;
  std::vector<std::vector<ExerciseMarks>> marks;
  void submission(const Submission& s) override {
    all.push_back(s);
    marks.emplace_back(s.marks.begin(), s.marks.end());
  }
  void finish(const ClassStatistics&, const Outcome&) override {}
};

struct Graded {
  Rows rows;
  Outcome outcome;
};

Graded grade(const std::string& csv, const Corrections* corrections) {
  SessionOptions o;
  o.answers_name = "a.csv";
  o.log = nullptr;
  o.corrections = corrections;
  GradingSession session(key(), std::move(o));
  Graded g;
  session.add_sink(g.rows);
  const SourceInfo info = read_answers_text(csv, "a.csv", session);
  g.outcome = session.finish(info);
  return g;
}

const QuestionMark* find(const Graded& g, std::size_t row, const std::string& id) {
  const Submission& s = g.rows.all[row];
  for (std::size_t e = 0; e < s.sheet->exercises.size(); ++e)
    for (std::size_t q = 0; q < s.sheet->exercises[e].questions.size(); ++q)
      if (s.sheet->exercises[e].questions[q].id == id) return &g.rows.marks[row][e][q];
  return nullptr;
}
}  // namespace

TEST_CASE("to check, then settled by a corrections file and grade run again") {
  const std::string csv = "sheet,student,2.t,2.P.x,2.P.y,2.position\n1000-0005-002N,A,-0.4?,9.41,3.97,before\n";
  SUBCASE("1. without corrections: to check, its 2 points held, the row flagged, exit status 1") {
    const auto g = grade(csv, nullptr);
    const Submission& s = g.rows.all[0];
    CHECK(find(g, 0, "2.t")->verdict == Verdict::to_check);
    CHECK(s.held == doctest::Approx(2).epsilon(1e-12));
    CHECK(s.to_check == 1);
    CHECK(s.score == doctest::Approx(3).epsilon(1e-12));
    CHECK(s.flagged("to_check"));
    CHECK(g.outcome.to_check == 1);
    CHECK(g.outcome.exit_status() == 1);
  }
  SUBCASE("2. with the teacher's reading: marked, nothing held, exit status 0") {
    const auto c = read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [
      {"sheet": "10000005002n", "question": "2.T", "value": "-0,48", "note": "a 8 under the blot"}]})",
                                    "c.json");
    const auto g = grade(csv, &c);
    const Submission& s = g.rows.all[0];
    CHECK(find(g, 0, "2.t")->verdict == Verdict::right);
    CHECK(find(g, 0, "2.t")->corrected);
    CHECK(s.held == 0);
    CHECK(s.score == doctest::Approx(5).epsilon(1e-12));
    CHECK_FALSE(s.flagged("to_check"));
    CHECK(g.outcome.corrections_applied == 1);
    CHECK(g.outcome.exit_status() == 0);
  }
  SUBCASE("3. a correction replaces any cell, even one the file has no column for") {
    const auto c = read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [
      {"sheet": "1000-0005-002N", "question": "3.t_ab", "value": "0,5"},
      {"sheet": "1000-0005-002N", "question": "student_number", "value": "21804512"}]})",
                                    "c.json");
    const auto g = grade(csv, &c);
    CHECK(find(g, 0, "3.t_ab")->given.raw == "0,5");
    CHECK(g.rows.all[0].student_number == "21804512");
  }
  SUBCASE("4. entries that cannot be placed are said with the file and entry; the rest applies") {
    const auto c = read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [
      {"sheet": "1000-0005-002M", "question": "2.t", "value": "1"},
      {"sheet": "1000-0005-002N", "question": "9.z", "value": "1"},
      {"sheet": "1000-0005-0089", "question": "2.t", "value": "1"},
      {"sheet": "1000-0005-002N", "question": "2.t", "value": "1"},
      {"sheet": "1000-0005-002N", "question": "2.t", "value": "-0,48"},
      {"sheet": "1000-0005-002N", "question": 2}]})",
                                    "c.json");
    const auto g = grade(csv, &c);
    CHECK(find(g, 0, "2.t")->verdict == Verdict::right);  // entry 5, the later one
    int said = 0;
    for (const auto& p : g.outcome.problems) {
      if (p.file != "c.json") continue;
      ++said;
      CAPTURE(p.message);
      const bool names_entry = p.message.find("entry ") != std::string::npos;
      CHECK(names_entry);
    }
    // 1 unknown sheet, 2 not asked, 3 no row (a warning), 4 repeated, 6 twice: no value, a question that is no string
    CHECK(said == 6);
  }
}

TEST_CASE("corrections written in the canonical shape read back the same") {
  std::vector<Correction> entries(2);
  entries[0].sheet = "1000-0005-002N";
  entries[0].question = "2.t";
  entries[0].value = "−0,48";
  entries[0].note = "une tache sur le 8, \"lue\"";
  entries[1].sheet = "1000-0005-0089";
  entries[1].question = "student_number";
  const std::string text = corrections_json(entries);
  CHECK(text.find("\"format\": \"epure-corrections\"") != std::string::npos);
  CHECK(text.find("−0,48") != std::string::npos);  // UTF-8 as is
  const auto back = read_corrections(text, "c.json");
  REQUIRE(back.readable);
  CHECK(back.problems.empty());
  REQUIRE(back.entries.size() == 2);
  CHECK(back.entries[0].value == "−0,48");
  CHECK(back.entries[0].note == entries[0].note);
  CHECK(back.entries[1].value.empty());
}
