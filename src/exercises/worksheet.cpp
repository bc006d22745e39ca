#include "exercises/worksheet.h"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "exercises/numbers.h"
#include "exercises/page_code.h"
#include "exercises/points.h"
#include "exercises/texts.h"

namespace epure {

WorksheetSet::WorksheetSet(WorksheetSpec spec, std::uint64_t seed, const SetOptions& options)
    : spec_(std::move(spec)), seed_(seed) {
  if (seed_ > kMaxSeed)
    throw SpecError(fmt::format("seed {} is out of range: sheet ids hold seeds from 0 to {}", seed_, kMaxSeed));
  language_ = options.language.value_or(spec_.language);
  Texts::builtin(language_);  // throws for a language without texts
  // From here on the spec speaks the set's language: pages, key.json, index and metadata.
  const SpecWords words = spec_.words_in(language_);
  spec_.title = words.title;
  spec_.course = words.course;
  spec_.author = words.author;
  spec_.subject = words.subject;
  if (options.page) spec_.page = *options.page;
  if (options.difficulty)
    for (auto& e : spec_.exercises) e.difficulty = *options.difficulty;
  for (std::size_t slot = 0; slot < spec_.exercises.size(); ++slot) {
    const auto& e = spec_.exercises[slot];
    auto weights = e.branches.empty() ? find_kind(e.kind)->default_branches() : e.branches;
    schedules_.emplace_back(std::move(weights), mix64(seed_ ^ (0x5EEDULL + slot)));
    fixed_points_.push_back(e.points);
    if (!e.points) pool_ += find_kind(e.kind)->default_points();
  }
  used_.resize(spec_.exercises.size());
}

ExerciseContext WorksheetSet::context(int slot, int n, const std::string& branch) const {
  const auto& texts = Texts::builtin(language_);
  ExerciseContext ctx{n, spec_.exercises[slot], texts, NumberStyle::for_language(language_),
                      spec_.decimals, branch};
  ctx.label = exercise_label(spec_, static_cast<std::size_t>(slot), texts);
  ctx.number = exercise_id(spec_, static_cast<std::size_t>(slot));
  return ctx;
}

std::string exercise_label(const WorksheetSpec& spec, std::size_t slot, const Texts& texts) {
  if (slot < spec.exercises.size()) {
    std::string own = spec.exercises[slot].heading_in(texts.language());
    if (!own.empty()) return own;
  }
  return texts.format("common.exercise_label", {{"n", exercise_id(spec, slot)}});
}

ExerciseInstance WorksheetSet::draw(int index, int slot, int attempt, const std::string& branch,
                                    const std::unordered_set<std::uint64_t>* taken, int widening) const {
  const std::uint64_t sheet_seed = mix64(mix64(seed_) + static_cast<std::uint64_t>(index));
  Rng rng(sheet_seed, (static_cast<std::uint64_t>(slot) << 16) | static_cast<std::uint64_t>(attempt));
  ExerciseContext ctx = context(slot, slot + 1, branch);
  ctx.taken = taken;
  ctx.widening = widening;
  ctx.sections = ctx.tolerances = !values_only_;
  const ExerciseKind& kind = *find_kind(spec_.exercises[slot].kind);
  ExerciseInstance instance = kind.make(rng, ctx);
  instance.number = ctx.number;
  return instance;
}

void WorksheetSet::measure_work() {
  if (!work_) {
    work_.emplace(spec_.exercises.size());
    for (std::size_t s = 0; s < spec_.exercises.size(); ++s) {
      if (fixed_points_[s]) continue;
      const auto& e = spec_.exercises[s];
      const auto weights = e.branches.empty() ? find_kind(e.kind)->default_branches() : e.branches;
      for (const auto& [name, weight] : weights) {
        if (!(weight > 0)) continue;
        // A branch asks the same questions on every instance (the course's cases): one instance
        // measures it. One that cannot be drawn (ExerciseKind::make's runtime_error: no instance
        // meets the constraints) weighs nothing here; its draw says why when the sheet needs it.
        // A logic_error is a bug in a kind and is not caught.
        double work = 0;
        try {
          for (const Question& q : draw(0, static_cast<int>(s), 0, name).questions) work += q.points;
        } catch (const std::runtime_error&) {
          work = 0;
        }
        (*work_)[s].emplace_back(name, work);
      }
    }
  }
}

const std::vector<std::pair<std::string, double>>& WorksheetSet::branch_work(int slot) {
  measure_work();
  return work_->at(static_cast<std::size_t>(slot));
}

std::string WorksheetSet::branch(int index, int slot) {
  if (!balance_) {
    measure_work();
    balance_.emplace(schedules_, *work_);
  }
  return balance_->at(index, slot);
}

double WorksheetSet::sheet_points() const {
  double total = pool_;
  for (const auto& p : fixed_points_) total += p.value_or(0);
  return total;
}

Sheet WorksheetSet::next(std::vector<ExerciseInstance>* first_attempts) {
  const int index = next_index_++;
  Sheet sheet;
  sheet.id = SheetId{kDrawVersion, seed_, index};
  for (std::size_t slot = 0; slot < spec_.exercises.size(); ++slot) {
    const int s = static_cast<int>(slot);
    const std::string scheduled = branch(index, s);
    // Attempt 0 of the scheduled branch first, given (drawn in parallel by generate) or drawn
    // here: the same instance either way, and the retries after a collision start at attempt 1
    // either way, so a sheet is the same however it is made (generate, the combs' probe,
    // rebuild, which grade and check use). Starting the sequential retries at attempt 0 drew
    // that collision again and left the scheduled branch one try short: once a branch ran out,
    // every later attempt number, and so the sheet, differed.
    std::optional<ExerciseInstance> chosen;
    ExerciseInstance first = first_attempts ? std::move((*first_attempts)[slot]) : draw(index, s, 0, scheduled, &used_[slot]);
    if (!used_[slot].count(first.fingerprint)) chosen = std::move(first);
    // A collision draws again. A branch whose instances are all taken (a small grid: a ray from
    // inside the canonical square has one integer origin) gives way to the kind's other branches
    // in the schedule's order, rather than repeating an instance or looping forever.
    std::vector<std::string> branches{scheduled};
    const auto& kind = *find_kind(spec_.exercises[slot].kind);
    auto weights = spec_.exercises[slot].branches.empty() ? kind.default_branches() : spec_.exercises[slot].branches;
    for (const auto& [name, weight] : weights)
      if (weight > 0 && name != scheduled) branches.push_back(name);
    // When every branch has run out, the kind's data ranges widen (ExerciseContext::widening).
    int attempt = 1;
    for (int widening = 0; !chosen && widening <= kMaxWidening; ++widening) {
      for (std::size_t b = 0; !chosen && b < branches.size(); ++b) {
        for (int tries = 0; tries < kAttemptsPerBranch && !chosen; ++tries, ++attempt) {
          // Only a new instance is built: with a large set, most draws of a small branch collide.
          ExerciseInstance inst = draw(index, s, attempt, branches[b], &used_[slot], widening);
          if (!used_[slot].count(inst.fingerprint)) chosen = std::move(inst);
        }
      }
    }
    if (!chosen)
      throw SpecError(fmt::format(
          "exercise {} ({}): every branch has run out of new instances after {} sheets, even with "
          "wider data ranges; the set "
          "cannot hold more distinct sheets at this difficulty (try fewer sheets or another difficulty)",
          slot + 1, spec_.exercises[slot].kind, index));
    used_[slot].insert(chosen->fingerprint);
    sheet.exercises.push_back(std::move(*chosen));
  }
  // the questions' weights become their shares of the sheet's points (points.h)
  spread_sheet_points(sheet.exercises, fixed_points_, pool_);
  return sheet;
}

Sheet WorksheetSet::rebuild(const SheetId& id) {
  if (id.version != kDrawVersion)
    throw SpecError(fmt::format("sheet {} was drawn by generator version {}; this epure draws version {} "
                                "and would build a different sheet: use the epure that made it",
                                id.str(), id.version, kDrawVersion));
  if (id.seed != seed_)
    throw SpecError(fmt::format("sheet {} belongs to the set of seed {}, not {}", id.str(), id.seed, seed_));
  if (id.index < next_index_) {
    // replay from the start: the fingerprints of earlier sheets decide collisions
    for (auto& u : used_) u.clear();
    next_index_ = 0;
  }
  while (next_index_ < id.index) next();
  return next();
}

namespace {

// A student's sheet on two sheets of paper, printed duplex (issue 18's budget).
constexpr int kSheetPageBudget = 4;

render::PageSize page_size(const std::string& page) {
  return page == "letter" ? render::PageSize::letter() : render::PageSize::a4();
}

render::PageWords page_words(const Texts& texts) {
  return {texts.get("common.field_name"), texts.get("common.field_student_number"),
          texts.get("common.page_word"), texts.get("common.yes"), texts.get("common.no")};
}

}  // namespace

namespace {

// A number field's id on the sheet: a point's coordinates share their point's comb width.
std::string comb_field(const ExerciseInstance& e, const Question& q) {
  return fmt::format("{}.{}", e.number, q.point_group.empty() ? q.field : q.point_group);
}

}  // namespace

void WorksheetSet::comb_reach(const Sheet& sheet, CombCells& cells) const {
  for (const auto& e : sheet.exercises)
    for (const auto& q : e.questions) {
      const auto* v = std::get_if<double>(&q.expected);
      if (!v || !std::isfinite(*v)) continue;
      // as a student writes it: rounded to the set's decimals, its integer part's digits
      const std::string written = fmt::format("{:.{}f}", std::fabs(*v), spec_.decimals);
      const int digits = static_cast<int>(std::min(written.find('.'), written.size()));
      int& n = cells[comb_field(e, q)];
      n = std::max({n, digits, 1});
    }
}

void WorksheetSet::measure_combs(int sheets) {
  measure_work();  // with built instances, as branch() would (and once: the probe shares it)
  // The probe draws the same sheets (the same data, collisions and branches) with their answers
  // only: the combs need no pages, and building them cost as much as the pages' own draw.
  WorksheetSet probe = *this;
  probe.values_only_ = true;
  CombCells cells;
  for (int i = 0; i < std::max(sheets, kReachSheets); ++i) comb_reach(probe.next(), cells);
  comb_cells_ = std::move(cells);
}

render::Document WorksheetSet::sheet_document(const Sheet& sheet) const {
  const auto& texts = Texts::builtin(language_);
  render::Document doc;
  doc.title = texts.format("common.sheet_title", {{"title", spec_.title}});
  doc.course = spec_.course;
  doc.sheet_id = sheet.id.str();
  doc.language = language_;
  doc.student_fields = true;
  doc.page_budget = kSheetPageBudget;
  doc.words = page_words(texts);
  doc.page = page_size(spec_.page);
  // The scan furniture: marks and a page code on every page, numbers as combs, the student
  // number as a comb.
  doc.page_code = [id = doc.sheet_id](int page, int pages) { return page_code_text({id, page, pages}); };
  doc.decimal_separator = NumberStyle::for_language(language_).decimal_comma ? "," : ".";
  doc.student_number_cells = spec_.student_number_digits;
  render::Section intro;
  intro.add(render::Paragraph{texts.format("common.rounding", {{"decimals", std::to_string(spec_.decimals)}}) + " " +
                                  texts.get("common.tick_help"),
                              true});
  doc.sections.push_back(std::move(intro));
  using K = render::AnswerField::Kind;
  for (const auto& e : sheet.exercises) {
    doc.sections.push_back(e.sheet);
    for (auto& block : doc.sections.back().blocks)
      if (auto* f = std::get_if<render::AnswerField>(&block); f && (f->kind == K::number || f->kind == K::point || f->kind == K::point3)) {
        auto it = comb_cells_.find(f->question_id);
        f->integer_cells = it == comb_cells_.end() ? kDefaultIntegerCells : it->second;
        f->decimals = spec_.decimals;
      }
  }
  return doc;
}

render::Document WorksheetSet::key_document(const Sheet& sheet) const {
  const auto& texts = Texts::builtin(language_);
  render::Document doc;
  doc.title = texts.format("common.key_title", {{"title", spec_.title}});
  doc.course = spec_.course;
  doc.sheet_id = sheet.id.str();
  doc.language = language_;
  doc.words = page_words(texts);
  doc.page = page_size(spec_.page);
  doc.breaks = render::Document::Breaks::between_blocks;  // the worked steps may run on
  doc.page_budget = 6;
  for (const auto& e : sheet.exercises) doc.sections.push_back(e.key);
  return doc;
}

}  // namespace epure
