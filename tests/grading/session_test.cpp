// A grading run on text: rows in = rows reported, totals, flags and problems with their lines,
// sheet ids with their nearest suggestion, follow-through on and off.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grading/answer_source.h"
#include "grading/session.h"
#include "grading/sheet_lookup.h"

using namespace epure::grading;

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

struct Collect final : SubmissionSink {
  std::vector<std::pair<double, std::vector<std::string>>> rows;  // score, flag codes
  void submission(const Submission& s) override {
    std::vector<std::string> flags;
    for (const auto& f : s.flags) flags.emplace_back(f.code);
    rows.emplace_back(s.marked() ? s.score : -1, flags);
  }
  void finish(const ClassStatistics&, const Outcome&) override {}
};

struct Run {
  Collect rows;
  Outcome outcome;
};

// The small key numbered as sets are since exercises have numbers of their own: the preamble
// "P", then 1 to 4 (ids P.dot, 1.t, …), where key_small.json numbers them by place (1.dot, 2.t).
const AnswerKey& numbered_key() {
  static const AnswerKey k = [] {
    std::ifstream in(EPURE_SOURCE_DIR "/tests/grading/data/key_small.json");
    auto j = nlohmann::json::parse(in);
    for (auto& sheet : j["sheets"])
      for (auto& e : sheet["exercises"]) {
        const int n = e["n"].get<int>();
        const std::string number = n == 1 ? "P" : std::to_string(n - 1);
        e["number"] = number;
        for (auto& q : e["questions"]) {
          const std::string id = q["id"].get<std::string>();
          q["id"] = number + id.substr(id.find('.'));
          if (q.contains("point")) {
            const std::string point = q["point"].get<std::string>();
            q["point"] = number + point.substr(point.find('.'));
          }
        }
      }
    return read_key_json(j.dump(), "numbered.json");
  }();
  return k;
}

Run grade(const std::string& csv, bool follow_through = true, const std::string& language = "",
          const AnswerKey& with = key()) {
  SessionOptions o;
  o.answers_name = "a.csv";
  o.language = language;
  o.log = nullptr;
  o.follow_through = follow_through;
  GradingSession session(with, std::move(o));
  Run run;
  session.add_sink(run.rows);
  const SourceInfo info = read_answers_text(csv, "a.csv", session);
  run.outcome = session.finish(info);
  return run;
}

bool has_problem(const Outcome& o, int line, const std::string& part) {
  for (const auto& p : o.problems)
    if (p.line == line && p.message.find(part) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("totals: right answers earn the sheet's points, blanks nothing") {
  const auto run = grade("sheet,student,2.t,2.P.x,2.P.y,2.position\n"
                         "1000-0005-002N,A,-0.48,9.41,3.97,before\n"
                         "1000-0005-002N,B,,,,\n");
  REQUIRE(run.rows.rows.size() == 2);
  CHECK(run.rows.rows[0].first == doctest::Approx(5).epsilon(1e-12));  // t 2 + P 1+1 + position 1
  CHECK(run.rows.rows[1].first == doctest::Approx(0).epsilon(1e-12));
  CHECK(run.outcome.rows == 2);
  CHECK(run.outcome.exit_status() == 0);
}

TEST_CASE("exercise numbers: a key's own ids, and the ids by place of answers collected before") {
  const AnswerKey& k = numbered_key();
  CHECK(k.question_ids().front() == "P.dot");
  CHECK(k.has_number("P"));
  CHECK(!k.has_number("5"));
  REQUIRE(k.id_of_place_name("2.t") != nullptr);
  CHECK(*k.id_of_place_name("2.t") == "1.t");
  CHECK(k.id_of_place_name("1.t") == nullptr);  // place 1 is the preamble: 1.dot, …
  // "4.t" was the circle's t (place 4) and is now the square's (number 4): a header is read by
  // place only when it has a name that is no id of the key
  CHECK(*k.id_of_place_name("4.t") == "3.t");
  CHECK(!k.only_by_place("4.t"));
  CHECK(k.only_by_place("1.dot"));
  CHECK(key().id_of_place_name("2.t") == nullptr);  // a key numbered by place: nothing to alias
  const std::string circle = "1000-0005-002N,A,1,99\n";
  const auto by_place = grade("sheet,student,1.dot,4.t\n" + circle, true, "", k);
  const auto by_number = grade("sheet,student,P.dot,4.t\n" + circle, true, "", k);
  REQUIRE(by_place.rows.rows.size() == 1);
  REQUIRE(by_number.rows.rows.size() == 1);
  CHECK(has_problem(by_place.outcome, 1, "place"));
  CHECK(!has_problem(by_number.outcome, 1, "place"));
  const std::string row = "1000-0005-002N,A,-0.48,9.41,3.97,before\n";
  const auto now = grade("sheet,student,1.t,1.P.x,1.P.y,1.position\n" + row, true, "", k);
  const auto before = grade("sheet,student,2.t,2.P.x,2.P.y,2.position\n" + row, true, "", k);
  REQUIRE(now.rows.rows.size() == 1);
  REQUIRE(before.rows.rows.size() == 1);
  CHECK(now.rows.rows[0].first == doctest::Approx(5).epsilon(1e-12));
  CHECK(before.rows.rows[0].first == doctest::Approx(5).epsilon(1e-12));
  CHECK(before.outcome.exit_status() == 0);
  // a column named with a number of the key but no question of it is an error, not a warning
  const auto typo = grade("sheet,student,P.dto\n1000-0005-002N,A,1\n", true, "", k);
  CHECK(typo.outcome.exit_status() != 0);
}

TEST_CASE("bad input, each case said with its line, every row reported") {
  SUBCASE("a mistyped id, with the nearest id of the key") {
    const auto run = grade("sheet,2.t\n1000-0005-002M,1\n");
    CHECK(run.rows.rows.size() == 1);
    CHECK(run.rows.rows[0].second == std::vector<std::string>{"unknown_sheet"});
    CHECK(has_problem(run.outcome, 2, "nearest sheet of this key is 1000-0005-002N (1 character away)"));
    CHECK(run.outcome.exit_status() == 1);
  }
  SUBCASE("an id with its dashes left out and lower case still reads") {
    const auto run = grade("sheet,2.t\n10000005002n,-0.48\n");
    CHECK(run.rows.rows[0].first == doctest::Approx(2).epsilon(1e-12));
  }
  SUBCASE("no sheet id") {
    const auto run = grade("sheet,2.t\n,1\n");
    CHECK(run.rows.rows[0].second == std::vector<std::string>{"no_sheet"});
  }
  SUBCASE("a sheet twice: both rows marked, both flagged (later ones without a first pass)") {
    const auto run = grade("sheet,2.t\n1000-0005-002N,1\n1000-0005-002N,-0.48\n");
    CHECK(run.rows.rows[0].first == doctest::Approx(0).epsilon(1e-12));
    CHECK(run.rows.rows[1].first == doctest::Approx(2).epsilon(1e-12));
    CHECK(run.rows.rows[1].second == std::vector<std::string>{"duplicate"});
    CHECK(run.outcome.duplicates.size() == 1);
    CHECK(run.outcome.exit_status() == 0);
  }
  SUBCASE("an unknown column, warned once") {
    const auto run = grade("sheet,remark,2.t\n1000-0005-002N,x,1\n1000-0005-0089,y,1\n");
    int warnings = 0;
    for (const auto& p : run.outcome.problems) warnings += p.message.find("'remark'") != std::string::npos;
    CHECK(warnings == 1);
    CHECK(run.outcome.errors == 0);
  }
  SUBCASE("a value that cannot be read is to check, and said") {
    const auto run = grade("sheet,2.t\n1000-0005-002N,abc\n");
    CHECK(run.rows.rows[0].second == std::vector<std::string>{"to_check"});
    CHECK(has_problem(run.outcome, 2, "answers to check (2 points held until a corrections file settles them): 2.t \"abc\" is not a number"));
  }
  SUBCASE("ragged rows") {
    const auto run = grade("sheet,2.t,2.P.x\n1000-0005-002N,-0.48\n1000-0005-002N,-0.48,9.41,extra\n");
    CHECK(run.rows.rows.size() == 2);
    CHECK(has_problem(run.outcome, 2, "2 cells where the header has 3"));
    CHECK(has_problem(run.outcome, 3, "the extra ones are not read: \"extra\""));
  }
  SUBCASE("an answer to a question the sheet does not ask") {
    // 4.reason is asked on 003K (a miss), not on 002N (a hit)
    const auto run = grade("sheet,4.reason\n1000-0005-002N,miss\n");
    CHECK(run.rows.rows[0].second == std::vector<std::string>{"not_asked"});
  }
  SUBCASE("an empty file") {
    const auto run = grade("");
    CHECK(run.rows.rows.empty());
    CHECK(has_problem(run.outcome, 0, "the file is empty"));
    CHECK(run.outcome.exit_status() == 1);
  }
  SUBCASE("empty rows are skipped, not reported, and counted") {
    const auto run = grade("sheet,2.t\n,\n1000-0005-002N,1\n");
    CHECK(run.rows.rows.size() == 1);
    CHECK(run.outcome.empty_rows == 1);
  }
  SUBCASE("no sheet column: nothing can be graded") { CHECK_THROWS_AS(grade("name,2.t\nx,1\n"), std::runtime_error); }
}

TEST_CASE("what a French teacher reads about the rows is in French") {
  SUBCASE("1. a mistyped id: the check character, and the nearest sheet") {
    const auto run = grade("sheet,2.t\n1000-0005-002M,1\n", true, "fr");
    CHECK(has_problem(run.outcome, 2, "n’est pas un identifiant de feuille valide\u00a0: le caractère de contrôle ne correspond pas"));
    CHECK(has_problem(run.outcome, 2, "la feuille la plus proche dans ce corrigé est 1000-0005-002N (à 1 caractère près)"));
    CHECK_FALSE(has_problem(run.outcome, 2, "check character"));
  }
  SUBCASE("2. an answer to a question the sheet does not ask") {
    const auto run = grade("sheet,4.reason\n1000-0005-002N,miss\n", true, "fr");
    CHECK(has_problem(run.outcome, 2, "réponses à des questions que la feuille 1000-0005-002N ne pose pas, non corrigées"));
  }
  SUBCASE("3. a value that cannot be read, and a short id") {
    const auto run = grade("sheet,2.t\n1000-0005-002N,abc\n1000-0005,1\n", true, "fr");
    CHECK(has_problem(run.outcome, 2, "réponses à vérifier (2 points réservés jusqu’à ce qu’un fichier de corrections les règle)\u00a0: 2.t \"abc\" n’est pas un nombre"));
    CHECK(has_problem(run.outcome, 3, "un identifiant de feuille a 12 caractères, celui-ci en a 8"));
  }
}

TEST_CASE("follow-through on and off change only the follow-through points") {
  // t = AB·AC/‖AB‖ on 002N's projection: A(7,3), B(2,1), C(9,5): AB = (−5,−2), AC = (2,2),
  // AB·AC = −14, ‖AB‖ = √29: t = −2.60, P = A + t·AB = (20, 8.2), still before A
  const std::string csv = "sheet,2.t,2.P.x,2.P.y,2.position\n1000-0005-002N,-2.60,20.00,8.20,before\n";
  const auto on = grade(csv, true), off = grade(csv, false);
  CHECK(on.rows.rows[0].first == doctest::Approx(3).epsilon(1e-12));   // P 1+1 by follow-through, position 1
  CHECK(off.rows.rows[0].first == doctest::Approx(1).epsilon(1e-12));  // the position alone
}

TEST_CASE("edit distance between ids, as typed") {
  CHECK(id_distance("1000-0005-002N", "10000005002n") == 0);
  CHECK(id_distance("1000-0005-002N", "1000-0005-002M") == 1);
  CHECK(id_distance("1000-0005-002N", "1000-0005-020N") == 1);  // two neighbours swapped
  CHECK(id_distance("1000-0005-002N", "1000-0005-O02N") == 0);  // O read as 0
  CHECK(id_distance("", "abc") == 3);
}

TEST_CASE("an id of another draw version, refused when keys are rebuilt, is said in the set's language") {
  const std::vector<epure::SheetId> ids{epure::SheetId{epure::kDrawVersion, 5, 2}, epure::SheetId{9, 5, 0}};
  const AnswerKey rebuilt = key_from_spec(epure::builtin_spec(), ids, "test");
  const std::string other = epure::SheetId{9, 5, 0}.str();
  const auto fr = find_sheet(rebuilt, other, epure::Texts::builtin("fr"));
  CHECK(fr.sheet == nullptr);
  CHECK(fr.why.find("a été tirée par la version 9 du générateur") != std::string::npos);
  const auto en = find_sheet(rebuilt, other, epure::Texts::builtin("en"));
  CHECK(en.why.find("was drawn by generator version 9") != std::string::npos);
}
