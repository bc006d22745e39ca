#include "grading/report_json.h"

#include <cmath>

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
    case AnswerType::number: w.number(q.number); break;
    case AnswerType::boolean: w.boolean(q.boolean); break;
    case AnswerType::word: w.string(q.word); break;
    case AnswerType::faces: {
      w.begin_array();
      for (const char* name : {"+x", "+y", "+z", "-x", "-y", "-z"})
        if (q.faces & face_bit(name)) w.string(name);
      w.end_array();
      break;
    }
  }
}

}  // namespace

struct JsonReport::Impl {
  output::AtomicFile file;
  const AnswerKey& key;
  const FeedbackText& text;
  fmt::memory_buffer buf;
  JsonWriter w{buf};

  Impl(const std::filesystem::path& path, const AnswerKey& k, const FeedbackText& t) : file(path), key(k), text(t) {}
  void flush() {
    file.write(std::string_view(buf.data(), buf.size()));
    buf.clear();
  }
};

JsonReport::JsonReport(const std::filesystem::path& path, const AnswerKey& key, const FeedbackText& text,
                       std::string_view answers_name, bool follow_through)
    : impl_(std::make_unique<Impl>(path, key, text)) {
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
  w.field("marked", s.marked());
  if (s.marked()) {
    w.field("score", s.score);
    w.field("max", s.max);
    if (m.key.info.scale) w.field("mark", s.max > 0 ? std::round(s.score / s.max * *m.key.info.scale * 100) / 100 : 0.0);
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
  if (m.key.info.scale) {
    w.field("scale", *m.key.info.scale);
    w.field("mean_mark", stats.mean_percent() / 100 * *m.key.info.scale);
    w.field("median_mark", stats.median_percent() / 100 * *m.key.info.scale);
  }
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
  w.end_object();
  w.key("problems").begin_array();
  for (const auto& p : outcome.problems) {
    w.begin_object();
    w.key("line").integer(p.line);
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
