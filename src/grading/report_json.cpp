#include "grading/report_json.h"

#include <cmath>

#include "grading/class_words.h"
#include "grading/encoding.h"
#include "grading/session.h"
#include "grading/statistics.h"
#include "output/atomic_file.h"
#include "solve/json_out.h"

namespace epure::grading {

namespace {

// Cells from a Windows-1252 file are not UTF-8: JSON text must be.
std::string utf8(std::string_view s) { return valid_utf8(s) ? std::string(s) : cp1252_to_utf8(s); }

void expected_value(JsonWriter& w, const QuestionKey& q) {
  switch (q.type) {
    case AnswerType::point:  // never a key's question: read as the number it would be
    case AnswerType::number: w.number(q.number); break;
    case AnswerType::boolean: w.boolean(q.boolean); break;
    case AnswerType::choice: w.string(q.word); break;
    case AnswerType::faces: {
      w.begin_array();
      for (const std::string_view name : geo::kFaceNames)
        if (q.faces & face_bit(name)) w.string(name);
      w.end_array();
      break;
    }
  }
}

void optional_number(JsonWriter& w, std::string_view key, const std::optional<double>& x) {
  w.key(key);
  if (x && std::isfinite(*x)) w.number(*x);
  else w.raw("null");
}

// The item analysis (item_analysis.h): per question, exercise and branch, Cronbach's α, the
// named mistakes and the follow-through credit.
void write_items(JsonWriter& w, const ItemAnalysis& a, const ClassWords& words) {
  w.key("items").begin_object();
  w.key("submissions").integer(a.submissions);
  w.field("provisional", a.provisional);
  optional_number(w, "alpha", a.alpha);
  w.key("alpha_items").integer(a.alpha_items);
  w.field("score_variance", a.score_variance);
  w.key("follow_through").integer(a.follow_through);
  w.field("follow_through_points", a.follow_through_points);
  w.key("questions").begin_array();
  for (const auto& q : a.questions) {
    w.begin_object();
    w.field("id", std::string_view(q.id));
    // its exercise's place (exercises[].n): an id's number ("3.3") is not a place
    w.key("exercise").integer(static_cast<long long>(q.exercise) + 1);
    w.key("answers").integer(q.answers);
    w.field("facility", q.facility);
    optional_number(w, "discrimination", q.discrimination);
    w.key("follow_through").integer(q.follow_through);
    w.field("follow_through_points", q.follow_through_points);
    w.key("to_check").integer(q.to_check);
    w.end_object();
  }
  w.end_array();
  w.key("exercises").begin_array();
  for (const auto& e : a.exercises) {
    w.begin_object();
    w.key("n").integer(e.n);
    w.field("number", std::string_view(e.number));
    w.field("kind", std::string_view(e.kind));
    w.field("label", std::string_view(words.exercise(e.n)));
    w.key("submissions").integer(e.submissions);
    w.field("max_points", e.max_points);
    w.field("facility", e.facility);
    w.field("variance", e.variance);
    w.key("follow_through").integer(e.follow_through);
    w.field("follow_through_points", e.follow_through_points);
    w.key("mistakes").begin_array();
    for (const auto& [code, count] : e.mistakes) {
      w.begin_object();
      w.field("code", code);
      w.key("count").integer(count);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.key("branches").begin_array();
  for (const auto& b : a.branches) {
    w.begin_object();
    w.key("exercise").integer(a.exercises[b.exercise].n);
    w.field("branch", std::string_view(b.branch));
    w.field("name", std::string_view(words.branch(b.branch)));
    w.key("submissions").integer(b.submissions);
    w.field("facility", b.facility);
    w.field("sd", b.sd);
    optional_number(w, "others_facility", b.others_facility);
    optional_number(w, "t", b.t);
    optional_number(w, "df", b.df);
    optional_number(w, "p", b.p);
    w.key("tested").integer(b.tested);
    w.field("threshold", b.tested > 0 ? kBranchAlpha / b.tested : 0.0);
    w.field("harder", b.harder);
    w.end_object();
  }
  w.end_array();
  w.key("mistakes").begin_array();
  for (const auto& m : a.mistakes) {
    w.begin_object();
    w.field("code", m.code);
    w.field("name", std::string_view(words.mistake(m.code)));
    w.key("count").integer(m.count);
    w.key("exercises").begin_array();
    for (const auto& [e, count] : m.by_exercise) {
      w.begin_object();
      w.key("n").integer(a.exercises[e].n);
      w.key("count").integer(count);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

}  // namespace

struct JsonReport::Impl {
  output::AtomicFile file;
  const AnswerKey& key;
  const FeedbackText& text;
  ClassWords words;
  MarkScale scale;
  fmt::memory_buffer buf;
  JsonWriter w{buf};

  Impl(const std::filesystem::path& path, const AnswerKey& k, const FeedbackText& t, MarkScale s)
      : file(path), key(k), text(t), words(k, t.texts()), scale(s) {}
  void flush() {
    file.write(std::string_view(buf.data(), buf.size()));
    buf.clear();
  }
};

JsonReport::JsonReport(const std::filesystem::path& path, const AnswerKey& key, const FeedbackText& text,
                       std::string_view answers_name, bool follow_through, MarkScale scale)
    : impl_(std::make_unique<Impl>(path, key, text, scale)) {
  auto& w = impl_->w;
  w.begin_object();
  w.field("answers", answers_name);
  w.key("key").begin_object();
  w.field("source", std::string_view(key.info.source));
  w.key("seed").integer(static_cast<long long>(key.info.seed));
  w.key("version").begin_object();
  w.field("epure", std::string_view(key.info.epure_version));
  w.key("draw").integer(key.info.draw_version);
  w.end_object();
  w.end_object();
  w.field("follow_through", follow_through);
  w.field("language", std::string_view(text.texts().language()));
  // the mark: score / max × out_of, to the nearest multiple of step, halves up (mark_scale.h)
  w.key("mark_scale").begin_object();
  w.key("out_of");
  if (scale.out_of) w.number(*scale.out_of);
  else w.raw("null");
  w.field("step", scale.step);
  w.field("rounding", "nearest, halves up");
  w.end_object();
  w.key("submissions").begin_array();
}

JsonReport::~JsonReport() = default;

void JsonReport::submission(const Submission& s) {
  auto& m = *impl_;
  auto& w = m.w;
  m.buf.push_back('\n');
  w.begin_object();
  w.key("line").integer(s.line);
  w.field("sheet", std::string_view(s.sheet ? s.sheet->id : utf8(s.sheet_text)));
  w.field("student", std::string_view(s.student));
  if (!s.student_number.empty()) w.field("student_number", std::string_view(utf8(s.student_number)));
  w.field("marked", s.marked());
  if (s.marked()) {
    w.field("score", s.score);
    w.field("max", s.max);
    if (m.scale.out_of) w.field("mark", m.scale.mark(s.score, s.max));
    // held: the points of the answers still to check, neither given nor refused
    w.field("held", s.held);
    w.key("to_check").integer(s.to_check);
    w.key("exercises").begin_array();
    for (std::size_t e = 0; e < s.marks.size(); ++e) {
      const ExerciseKey& ex = s.sheet->exercises[e];
      double earned = 0, worth = 0;
      for (std::size_t q = 0; q < s.marks[e].size(); ++q) {
        earned += s.marks[e][q].points;
        worth += ex.hot[q].points;
      }
      w.begin_object();
      w.key("n").integer(ex.n);
      w.field("number", std::string_view(ex.number));
      w.field("kind", std::string_view(ex.kind));
      w.field("branch", std::string_view(ex.branch));
      w.field("points", earned);
      w.field("max_points", worth);
      w.end_object();
    }
    w.end_array();
  }
  w.key("flags").begin_array();
  for (const auto& f : s.flags) {
    w.begin_object();
    w.field("code", f.code);
    w.field("message", std::string_view(utf8(f.message)));
    w.end_object();
  }
  w.end_array();
  w.key("questions").begin_array();
  for (std::size_t e = 0; e < s.marks.size(); ++e) {
    const ExerciseKey& ex = s.sheet->exercises[e];
    for (std::size_t q = 0; q < s.marks[e].size(); ++q) {
      const QuestionKey& qk = ex.questions[q];
      const QuestionMark& mk = s.marks[e][q];
      w.begin_object();
      w.field("id", std::string_view(qk.id));
      w.key("expected");
      expected_value(w, qk);
      if (qk.exact) w.field("exact", std::string_view(*qk.exact));
      w.key("given");
      if (mk.given.state == Given::State::blank) w.raw("null");
      else w.string(utf8(mk.given.raw));
      w.field("verdict", to_string(mk.verdict));
      w.field("points", mk.points);
      w.field("max_points", qk.points);
      w.field("feedback", std::string_view(m.text.sentence(qk, mk)));
      w.key("mistake");
      if (mk.mistake.empty()) w.raw("null");
      else w.string(mk.mistake);
      if (!mk.from.empty()) {
        w.field("from", mk.from);
        w.field("from_answers", std::string_view(utf8(mk.detail)));
      }
      if (!mk.note.empty()) w.field("read", mk.note);
      if (!mk.note_field.empty()) w.field("read_from", mk.note_field);
      if (mk.corrected) w.field("corrected", true);
      w.end_object();
    }
  }
  w.end_array();
  w.end_object();
  if (m.buf.size() > (1 << 16)) m.flush();
}

void JsonReport::finish(const ClassStatistics& stats, const Outcome& outcome) {
  auto& m = *impl_;
  auto& w = m.w;
  m.buf.push_back('\n');
  w.end_array();
  w.key("statistics").begin_object();
  w.key("rows").integer(stats.rows());
  w.key("marked").integer(stats.marked());
  w.key("empty_rows").integer(outcome.empty_rows);
  w.field("mean", stats.mean());
  w.field("median", stats.median());
  w.field("min", stats.min());
  w.field("max", stats.max());
  w.field("max_points", stats.max_points());
  // the class compared on one scale: each score in percent of its sheet's maximum
  w.field("mean_percent", stats.mean_percent());
  w.field("median_percent", stats.median_percent());
  w.field("min_percent", stats.min_percent());
  w.field("max_percent", stats.max_percent());
  if (m.scale.out_of) {
    w.field("scale", *m.scale.out_of);
    w.field("mean_mark", stats.mean_percent() / 100 * *m.scale.out_of);
    w.field("median_mark", stats.median_percent() / 100 * *m.scale.out_of);
  }
  w.key("to_check_rows").integer(stats.to_check_rows());
  w.key("questions").begin_array();
  for (const auto& q : stats.questions()) {
    w.begin_object();
    w.field("id", std::string_view(q.id));
    w.key("asked").integer(q.asked);
    w.key("credited").integer(q.credited);
    w.field("success_rate", q.rate());
    w.field("success_percent", 100 * q.rate());
    w.key("follow_through").integer(q.follow_through);
    w.key("unanswered").integer(q.unanswered);
    w.end_object();
  }
  w.end_array();
  w.key("mistakes").begin_array();
  for (const auto& c : stats.mistakes()) {
    w.begin_object();
    w.field("code", c.code);
    w.field("question", std::string_view(c.question));
    w.key("count").integer(c.count);
    w.end_object();
  }
  w.end_array();
  w.key("histogram").begin_array();
  for (const auto& b : stats.histogram()) {
    w.begin_object();
    w.field("from", b.from);
    w.field("to", b.to);
    w.key("count").integer(b.count);
    w.end_object();
  }
  w.end_array();
  write_items(w, stats.items(), m.words);
  w.end_object();
  w.key("problems").begin_array();
  for (const auto& p : outcome.problems) {
    w.begin_object();
    w.key("line").integer(p.line);
    if (!p.file.empty()) w.field("file", std::string_view(p.file));
    w.field("severity", p.error ? "error" : "warning");
    w.field("message", std::string_view(utf8(p.message)));
    w.end_object();
  }
  w.end_array();
  w.key("problems_not_listed").integer(outcome.problems_not_kept);
  w.key("errors").integer(outcome.errors);
  w.key("warnings").integer(outcome.warnings);
  w.key("exit_status").integer(outcome.exit_status());
  w.end_object();
  m.buf.push_back('\n');
  m.flush();
  m.file.commit();
}

}  // namespace epure::grading
