#include "output/generate.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "exercises/key_json.h"
#include "exercises/numbers.h"
#include "exercises/sheet_id.h"
#include "exercises/texts.h"
#include "exercises/worksheet.h"
#include "output/atomic_file.h"
#include "output/explore_page.h"
#include "output/index_html.h"
#include "output/parallel.h"
#include "output/sheet_layout.h"
#include "render/layout.h"
#include "render/pdf_document.h"
#include "render/svg_page.h"

namespace epure::output {

namespace {

// Sheets drawn and written per round: enough to keep every job busy, few enough that memory
// stays flat whatever the size of the set. The first rounds are smaller, so that the class-set
// PDFs' drawing, the longest part of a set, starts early (batch_size).
constexpr int kBatch = 64;
constexpr int kFirstBatch = 8;

// Round k's number of sheets: 8, 16, 32, then 64. The bytes written do not depend on it: every
// sheet is drawn from its index, and written in index order.
int batch_size(int round) { return round >= 3 ? kBatch : std::min(kBatch, kFirstBatch << round); }

// A sheet's two documents and their pages; the pages point into the documents' scenes. The
// key's links (to explore.html, when the set has it) go into the class set's keys.pdf.
struct Printed {
  render::Document sheet, key;
  std::vector<render::LaidOutPage> sheet_pages, key_pages;
  std::vector<render::PageLink> sheet_links, key_links;
  std::string layout;  // the sheet in layout.json
};

render::PdfMetadata pdf_metadata(const WorksheetSpec& spec, const std::string& title,
                                 const GenerateOptions& options) {
  render::PdfMetadata m;
  m.title = title;
  m.author = spec.author;
  m.subject = spec.subject.empty() ? spec.course : spec.subject;
  m.creator = "epure " + options.epure_version;
  m.date = options.pdf_date;
  return m;
}

// A class-set PDF written as it is drawn, its links with it (render/pdf_stream_writer.h),
// committed at the end (never a half file). Nothing of the set's PDF is held in memory.
struct ClassSetPdf {
  AtomicFile file;
  render::PdfDocument pdf;
  ClassSetPdf(const std::filesystem::path& path, const render::PdfMetadata& metadata, render::PageSize page)
      : file(path),
        pdf(render::PdfSink{[this](std::string_view bytes) { file.write(bytes); },
                            [this](std::uint64_t offset, std::string_view bytes) { file.overwrite(offset, bytes); }},
            metadata, page) {}

  void add(const std::vector<render::LaidOutPage>& pages, const std::string& id, bool duplex,
           std::span<const render::PageLink> links) {
    pdf.add(pages, id, true, {}, links);
    if (duplex && pdf.pages() % 2 == 1) pdf.add_blank(pages.back().size, id);
  }
  void commit() {
    pdf.finish();
    file.commit();
  }
};

struct Batch {
  std::vector<std::string> ids;
  std::vector<Printed> printed;
};

// sheets.pdf and keys.pdf. A cairo surface is drawn by one thread at a time, in page order, and
// keys.pdf is the longest to draw (about half the CPU of a PDF set: a key has more pages, and
// more on them, than its sheet). So with two jobs or more keys.pdf has a thread of its own,
// drawing one batch while the caller generates the next. With two jobs and no SVG to write, the
// caller draws sheets.pdf itself between batches: generation, layout and sheets.pdf take about
// as long as keys.pdf, and the two cores stay busy without a third thread taking turns with
// keys.pdf's. With SVG pages to write as well, or three jobs or more, sheets.pdf has a thread
// too. With one job, in line. Either way the pages go in id order: the bytes do not depend on
// the number of jobs. And memory does not depend on the number of sheets: add() waits until
// both PDFs have drawn the batch before (a queue one batch deep), so generation runs at most one
// batch ahead of the slower PDF, and two batches at most are held (128 sheets' documents).
class ClassSetWriter {
 public:
  ClassSetWriter(const GenerateOptions& o, const WorksheetSpec& spec, const Printed& first)
      : duplex_(o.duplex),
        keys_threaded_(o.jobs >= 2),
        sheets_threaded_(o.jobs >= 3 || (o.jobs == 2 && o.svg)),
        sheets_(o.out / "sheets.pdf", pdf_metadata(spec, first.sheet.title, o), first.sheet.page),
        keys_(o.out / "keys.pdf", pdf_metadata(spec, first.key.title, o), first.key.page) {}

  // The jobs left for generating and laying out sheets while the PDFs are drawn.
  static int generation_jobs(int jobs) { return std::max(1, jobs - 2); }

  // Waits for the batch before (and rethrows its error), then draws this one.
  void add(std::shared_ptr<const Batch> batch) {
    if (!keys_threaded_) {
      draw(sheets_, *batch, &Printed::sheet_pages, &Printed::sheet_links);
      draw(keys_, *batch, &Printed::key_pages, &Printed::key_links);
      return;
    }
    wait();
    keys_thread_ = std::jthread([this, batch] {
      guarded(keys_error_, [&] { draw(keys_, *batch, &Printed::key_pages, &Printed::key_links); });
    });
    if (sheets_threaded_) {
      sheets_thread_ = std::jthread([this, batch] {
        guarded(sheets_error_, [&] { draw(sheets_, *batch, &Printed::sheet_pages, &Printed::sheet_links); });
      });
    } else {
      draw(sheets_, *batch, &Printed::sheet_pages, &Printed::sheet_links);
    }
  }

  void commit() {
    wait();
    sheets_.commit();
    keys_.commit();
  }

 private:
  using Pages = std::vector<render::LaidOutPage> Printed::*;
  using Links = std::vector<render::PageLink> Printed::*;
  void draw(ClassSetPdf& pdf, const Batch& batch, Pages pages, Links links) {
    for (std::size_t i = 0; i < batch.ids.size(); ++i)
      pdf.add(batch.printed[i].*pages, batch.ids[i], duplex_, batch.printed[i].*links);
  }
  template <class Fn>
  static void guarded(std::exception_ptr& error, Fn&& fn) {
    try {
      fn();
    } catch (...) {
      error = std::current_exception();
    }
  }
  void wait() {
    if (sheets_thread_.joinable()) sheets_thread_.join();
    if (keys_thread_.joinable()) keys_thread_.join();
    for (std::exception_ptr* e : {&sheets_error_, &keys_error_})
      if (*e) std::rethrow_exception(std::exchange(*e, nullptr));
  }

  const bool duplex_, keys_threaded_, sheets_threaded_;
  ClassSetPdf sheets_, keys_;
  std::exception_ptr sheets_error_, keys_error_;
  // Declared last, so joined first when an error unwinds: nothing they use is gone before them.
  std::jthread sheets_thread_, keys_thread_;
};

}  // namespace

GenerateReport generate_set(WorksheetSet& set, const GenerateOptions& options) {
  namespace fs = std::filesystem;
  if (options.sheets < 1 || options.sheets > kMaxSheets)
    throw std::runtime_error(fmt::format("--sheets must be from 1 to {}", kMaxSheets));
  if (set.next_index() != 0) throw std::logic_error("generate_set needs a fresh set");
  if (!options.students.empty() && options.students.size() != static_cast<std::size_t>(options.sheets))
    throw std::logic_error("generate_set: one sheet per student");
  // The combs' widths (what the set's answers reach): drawn first, so that a set that cannot be
  // drawn fails before anything is created on disk
  set.measure_combs(options.sheets);
  if (options.svg || (options.pdf && options.split)) {
    fs::create_directories(options.out / "sheets");
    fs::create_directories(options.out / "keys");
  } else {
    fs::create_directories(options.out);
  }

  AtomicFile key_file(options.out / "key.json");
  fmt::memory_buffer key;
  KeyJson::begin(key, set, options.epure_version);
  std::vector<IndexEntry> index;
  // explore.html beside index.html, every sheet's exercises reachable from their ids, written
  // as the sheets come
  const bool explore = options.svg && explore_available();
  std::optional<AtomicFile> explore_file;
  std::optional<ExplorePageWriter> explore_page;
  if (explore) {
    explore_file.emplace(options.out / "explore.html");
    ExerciseLabels labels;
    for (const char* language : {"en", "fr"})
      for (std::size_t slot = 0; slot < set.spec().exercises.size(); ++slot)
        labels[language].push_back(exercise_label(set.spec(), slot, Texts::builtin(language)));
    explore_page.emplace(set.language(), [&](std::string_view bytes) { explore_file->write(bytes); }, labels);
  }
  const int slots = static_cast<int>(set.spec().exercises.size());
  GenerateReport report;
  // layout.json, where a scan looks, written from the sheets' pages as they come
  const bool laid_out = options.svg || options.pdf;
  std::optional<AtomicFile> layout_file;
  if (laid_out) {
    scan::SetLayout head;
    head.title = set.spec().title;
    head.language = set.language();
    head.decimal_separator = NumberStyle::for_language(set.language()).decimal_comma ? "," : ".";
    head.seed = set.seed();
    head.draw_version = kDrawVersion;
    layout_file.emplace(options.out / "layout.json");
    layout_file->write(scan::layout_json_begin(head));
  }
  std::unique_ptr<ClassSetWriter> class_set;

  // While a class-set PDF is drawn on threads of its own, the rest of the jobs generate.
  const bool class_set_pdf = options.pdf && !options.split;
  const int jobs = class_set_pdf ? ClassSetWriter::generation_jobs(options.jobs) : options.jobs;

  for (int start = 0, round = 0; start < options.sheets; start += batch_size(round++)) {
    const int count = std::min(batch_size(round), options.sheets - start);
    // 1. branches (sequential and cheap), then attempt 0 of every exercise, in parallel
    std::vector<std::string> branches(static_cast<std::size_t>(count * slots));
    for (int i = 0; i < count; ++i)
      for (int s = 0; s < slots; ++s) branches[i * slots + s] = set.branch(start + i, s);
    std::vector<std::vector<ExerciseInstance>> drawn(count, std::vector<ExerciseInstance>(slots));
    parallel_for(count * slots, jobs, [&](int k) {
      const int i = k / slots, s = k % slots;
      drawn[i][s] = set.draw(start + i, s, 0, branches[k]);
    });
    // 2. collisions with earlier sheets settled in index order
    std::vector<Sheet> sheets;
    sheets.reserve(count);
    for (int i = 0; i < count; ++i) sheets.push_back(set.next(&drawn[i]));
    // 3. documents laid out, drawn as SVG (and as split PDFs) in parallel, written in order
    std::vector<Printed> printed(count);
    if (options.svg || options.pdf) {
      parallel_for(count, jobs, [&](int i) {
        Printed& p = printed[i];
        p.sheet = set.sheet_document(sheets[i]);
        const SheetStudent* student = options.students.empty() ? nullptr : &options.students[start + i];
        if (student) {
          p.sheet.student_name = student->name;
          p.sheet.student_number = student->number;
        }
        p.key = set.key_document(sheets[i]);
        const std::string id = sheets[i].id.str();
        // each exercise of the key links to the student's own instance in explore.html
        if (explore)
          for (std::size_t k = 0; k < p.key.sections.size() && k < sheets[i].exercises.size(); ++k)
            p.key.sections[k].link = fmt::format("explore.html#{}.{}", id, sheets[i].exercises[k].n);
        p.sheet_pages = render::layout_document(p.sheet);
        p.key_pages = render::layout_document(p.key);
        scan::SheetLayout sl = sheet_layout(id, p.sheet_pages);
        if (student) sl.student = scan::StudentLayout{student->number, student->name};
        p.layout = scan::layout_json_sheet(sl, start + i == 0);
        if (options.pdf && !options.split) p.key_links = render::section_links(p.key_pages, p.key);
        if (options.svg) {
          write_file_atomically(options.out / "sheets" / (id + ".svg"), render::pages_to_svg(p.sheet_pages, p.sheet));
          write_file_atomically(options.out / "keys" / (id + ".svg"), render::pages_to_svg(p.key_pages, p.key));
        }
        if (options.pdf && options.split) {
          write_file_atomically(options.out / "sheets" / (id + ".pdf"),
                                render::pages_to_pdf(p.sheet_pages, id, pdf_metadata(set.spec(), p.sheet.title, options)));
          write_file_atomically(options.out / "keys" / (id + ".pdf"),
                                render::pages_to_pdf(p.key_pages, id, pdf_metadata(set.spec(), p.key.title, options), {},
                                                     render::section_links(p.key_pages, p.key, "../")));
        }
      });
    }
    if (layout_file)
      for (const Printed& p : printed) layout_file->write(p.layout);
    // 4. the class-set PDFs, in id order (behind the next batch, with two jobs or more)
    if (class_set_pdf) {
      if (!class_set) class_set = std::make_unique<ClassSetWriter>(options, set.spec(), printed[0]);
      auto batch = std::make_shared<Batch>();
      for (const Sheet& s : sheets) batch->ids.push_back(s.id.str());
      batch->printed = std::move(printed);  // the buffer moves, so the pages' scene pointers hold
      class_set->add(std::move(batch));
    }
    for (int i = 0; i < count; ++i) {
      KeyJson::sheet(key, sheets[i], start + i == 0, options.students.empty() ? nullptr : &options.students[start + i]);
      index.push_back({sheets[i].id.str(), static_cast<int>(sheets[i].exercises.size())});
      if (explore) {
        ExploreSheet e{sheets[i].id.str(), {}};
        for (const auto& x : sheets[i].exercises) e.instances.push_back(x.instance);
        explore_page->add(e);
      }
    }
    key_file.write(std::string_view(key.data(), key.size()));
    key.clear();
    if (start == 0) report.first_id = sheets.front().id.str();
    report.last_id = sheets.back().id.str();
    report.sheets += count;
    if (options.progress) options.progress(report.sheets, options.sheets);
  }
  KeyJson::end(key);
  key_file.write(std::string_view(key.data(), key.size()));
  if (class_set) class_set->commit();
  key_file.commit();
  if (layout_file) {
    layout_file->write(scan::layout_json_end());
    layout_file->commit();
  }
  if (options.svg) {
    AtomicFile index_file(options.out / "index.html");
    write_index_html([&](std::string_view bytes) { index_file.write(bytes); }, set.spec().title, set.spec().course,
                     set.language(), index,
                     !options.pdf    ? PdfLinks::none
                     : options.split ? PdfLinks::per_sheet
                                     : PdfLinks::class_set,
                     explore);
    index_file.commit();
  }
  if (explore) {
    explore_page->finish();
    explore_file->commit();
  }
  return report;
}

}  // namespace epure::output
