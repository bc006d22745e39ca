// key.json read sheet by sheet: the fields grading needs, errors that name the file and the
// place, the report order of question ids, keys rebuilt from a spec; and the field names the
// kinds ask by, which must hash apart (ExerciseKey::find compares hashes only).
#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "exercises/exercise.h"
#include "exercises/key_json.h"
#include "exercises/spec.h"
#include "grading/answer_key.h"
#include "grading/kind_grader.h"

using namespace epure::grading;

namespace {
std::string small_key() {
  std::ifstream in(EPURE_SOURCE_DIR "/tests/grading/data/key_small.json");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("the small key: sheets, exercises, questions, prepared graders") {
  const AnswerKey key = read_key_json(small_key(), "key_small.json");
  CHECK(key.sheets().size() == 4);
  CHECK(key.info.seed == 5);
  CHECK(key.info.draw_version == 1);  // written before the work-fair draw (version 2): graded by its own content
  CHECK(key.info.follow_through);
  const SheetKey* s = key.find("1000-0005-002N");
  REQUIRE(s);
  CHECK(s->exercises.size() == 5);
  for (const auto& e : s->exercises) {
    CHECK(e.grader != nullptr);
    CHECK(e.prepared.has_value());
    CHECK(e.hot.size() == e.questions.size());
  }
  const auto& q = s->exercises[1].questions[0];
  CHECK(q.id == "2.t");
  CHECK(q.field == "t");
  CHECK(q.type == AnswerType::number);
  CHECK(q.rule.kind == epure::ToleranceRule::Kind::isclose);
  CHECK(s->exercises[4].questions[0].faces == (face_bit("+x") | face_bit("-y")));
  // ids by exercise, as the sheets ask them
  const auto& ids = key.question_ids();
  CHECK(ids.front() == "1.dot");
  CHECK(std::is_sorted(ids.begin(), ids.end(), [](const std::string& a, const std::string& b) {
    return std::stoi(a) < std::stoi(b);
  }));
}

TEST_CASE("a file that is not a key: the message names it and what is wrong") {
  SUBCASE("not JSON") { CHECK_THROWS_WITH_AS(read_key_json("{", "k.json"), doctest::Contains("k.json: not valid JSON"), KeyError); }
  SUBCASE("not an object") { CHECK_THROWS_AS(read_key_json("[1]", "k.json"), KeyError); }
  SUBCASE("no spec") {
    CHECK_THROWS_WITH_AS(read_key_json(R"({"seed":1})", "k.json"), doctest::Contains("missing 'spec'"), KeyError);
  }
  SUBCASE("no sheets") {
    CHECK_THROWS_WITH_AS(read_key_json(R"({"spec":{},"seed":1,"version":{"epure":"0","draw":1},"sheets":[]})", "k.json"),
                         doctest::Contains("no sheets"), KeyError);
  }
  SUBCASE("a question without points, named with its sheet") {
    std::string text = small_key();
    const auto at = text.find("\"points\":");
    text.replace(at, 9, "\"pointz\":");
    CHECK_THROWS_WITH_AS(read_key_json(text, "k.json"), doctest::Contains("sheet 1000-0005-002N: question 1.dot: missing 'points'"),
                         KeyError);
  }
  SUBCASE("a bad sheet id") {
    std::string text = small_key();
    const auto at = text.find("1000-0005-002N");
    text.replace(at, 14, "1000-0005-002M");
    CHECK_THROWS_WITH_AS(read_key_json(text, "k.json"), doctest::Contains("check character"), KeyError);
  }
}

// A key.json written now, read back: what grade --key sees.
std::string written_key(const epure::WorksheetSpec& spec, std::uint64_t seed, int sheets) {
  epure::WorksheetSet set(spec, seed);
  fmt::memory_buffer out;
  epure::KeyJson::begin(out, set, "test");
  for (int i = 0; i < sheets; ++i) epure::KeyJson::sheet(out, set.next(), i == 0);
  epure::KeyJson::end(out);
  return fmt::to_string(out);
}

TEST_CASE("keys rebuilt from the spec ask key.json's questions, under the spec's exercise numbers") {
  const AnswerKey from_json = read_key_json(written_key(epure::builtin_spec(), 5, 6), "key.json");
  REQUIRE(from_json.sheets().size() == 6);
  std::vector<epure::SheetId> ids;
  for (const auto& s : from_json.sheets()) ids.push_back(s.sheet);
  ids.push_back(epure::SheetId{9, 5, 0});  // another generator version: refused, not rebuilt
  const AnswerKey rebuilt = key_from_spec(epure::builtin_spec(), ids, "test");
  CHECK(rebuilt.sheets().size() == 6);
  REQUIRE(rebuilt.refused().size() == 1);
  CHECK(rebuilt.refused().begin()->second.find("version") != std::string::npos);
  for (const auto& s : from_json.sheets()) {
    CAPTURE(s.id);
    const SheetKey* r = rebuilt.find(s.id);
    REQUIRE(r);
    REQUIRE(r->exercises.size() == s.exercises.size());
    for (std::size_t e = 0; e < s.exercises.size(); ++e) {
      CHECK(r->exercises[e].branch == s.exercises[e].branch);
      REQUIRE(r->exercises[e].questions.size() == s.exercises[e].questions.size());
      for (std::size_t q = 0; q < s.exercises[e].questions.size(); ++q) {
        const auto& want = s.exercises[e].questions[q];
        const auto& got = r->exercises[e].questions[q];
        CHECK(got.field == want.field);
        CHECK(got.id == want.id);
        CHECK(got.id.rfind(epure::exercise_id(epure::builtin_spec(), e) + ".", 0) == 0);
        CHECK(got.points == want.points);  // the sheet's share of the total, as printed
        CHECK(got.number == doctest::Approx(want.number).epsilon(1e-15));
      }
    }
  }
}

TEST_CASE("a key.json of an earlier draw version is not rebuilt from the spec: its ids are refused, with why") {
  // key_small.json was written under draw version 1 (before the work-fair draw): the spec now
  // draws other sheets for the same seed and index, so rebuilding them would grade against
  // sheets the students never had.
  const AnswerKey old = read_key_json(small_key(), "key_small.json");
  std::vector<epure::SheetId> ids;
  for (const auto& s : old.sheets()) ids.push_back(s.sheet);
  const AnswerKey rebuilt = key_from_spec(epure::builtin_spec(), ids, "test");
  CHECK(rebuilt.sheets().empty());
  REQUIRE(rebuilt.refused().size() == old.sheets().size());
  for (const auto& [id, why] : rebuilt.refused()) {
    CAPTURE(id);
    CHECK(why.find("version 1") != std::string::npos);
  }
}

TEST_CASE("every field name the kinds ask by hashes apart") {
  std::set<std::string> names;
  for (const auto* kind : epure::all_kinds())
    for (const auto& f : kind->fields()) {
      names.insert(f);
      names.insert(f + ".x");
      names.insert(f + ".y");
    }
  for (const char* extra : {"Ac", "uc", "Ac.x", "Ac.y", "uc.x", "uc.y", "P", "I", "N"}) names.insert(extra);
  std::set<std::uint32_t> hashes;
  for (const auto& n : names) hashes.insert(field_hash(n));
  CHECK(hashes.size() == names.size());
}
