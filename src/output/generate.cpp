#include "output/generate.h"

#include <exception>
#include <memory>
#include <thread>

#include <fmt/format.h>

#include "exercises/key_json.h"
#include "output/atomic_file.h"
#include "output/index_html.h"
#include "output/parallel.h"
#include "render/layout.h"
#include "render/pdf_document.h"
#include "render/svg_page.h"

namespace epure::output {

namespace {

// Sheets drawn and written per round: enough to keep every job busy, few enough that memory
// stays flat whatever the size of the set.
constexpr int kBatch = 64;

// A sheet's two documents and their pages; the pages point into the documents' scenes.
struct Printed {
  render::Document sheet, key;
  std::vector<render::LaidOutPage> sheet_pages, key_pages;
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

// A class-set PDF written as it is drawn, committed at the end (never a half file).
struct ClassSetPdf {
  AtomicFile file;
  render::PdfDocument pdf;
  ClassSetPdf(const std::filesystem::path& path, const render::PdfMetadata& metadata, render::PageSize page)
      : file(path), pdf([this](std::string_view bytes) { file.write(bytes); }, metadata, page) {}

  void add(const std::vector<render::LaidOutPage>& pages, const std::string& id, bool duplex) {
    pdf.add(pages, id, true);
    if (duplex && pdf.pages() % 2 == 1) pdf.add_blank(pages.back().size, id);
  }
  void commit() {
    pdf.finish();
    file.commit();
  }
};

}  // namespace

GenerateReport generate_set(WorksheetSet& set, const GenerateOptions& options) {
  namespace fs = std::filesystem;
  if (options.sheets < 1 || options.sheets > kMaxSheets)
    throw std::runtime_error(fmt::format("--sheets must be from 1 to {}", kMaxSheets));
  if (set.next_index() != 0) throw std::logic_error("generate_set needs a fresh set");
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
  const int slots = static_cast<int>(set.spec().exercises.size());
  GenerateReport report;
  std::unique_ptr<ClassSetPdf> sheets_pdf, keys_pdf;

  for (int start = 0; start < options.sheets; start += kBatch) {
    const int count = std::min(kBatch, options.sheets - start);
    // 1. branches (sequential and cheap), then attempt 0 of every exercise, in parallel
    std::vector<std::string> branches(static_cast<std::size_t>(count * slots));
    for (int i = 0; i < count; ++i)
      for (int s = 0; s < slots; ++s) branches[i * slots + s] = set.branch(start + i, s);
    std::vector<std::vector<ExerciseInstance>> drawn(count, std::vector<ExerciseInstance>(slots));
    parallel_for(count * slots, options.jobs, [&](int k) {
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
      parallel_for(count, options.jobs, [&](int i) {
        Printed& p = printed[i];
        p.sheet = set.sheet_document(sheets[i]);
        p.key = set.key_document(sheets[i]);
        p.sheet_pages = render::layout_document(p.sheet);
        p.key_pages = render::layout_document(p.key);
        const std::string id = sheets[i].id.str();
        if (options.svg) {
          write_file_atomically(options.out / "sheets" / (id + ".svg"), render::pages_to_svg(p.sheet_pages, p.sheet));
          write_file_atomically(options.out / "keys" / (id + ".svg"), render::pages_to_svg(p.key_pages, p.key));
        }
        if (options.pdf && options.split) {
          write_file_atomically(options.out / "sheets" / (id + ".pdf"),
                                render::pages_to_pdf(p.sheet_pages, id, pdf_metadata(set.spec(), p.sheet.title, options)));
          write_file_atomically(options.out / "keys" / (id + ".pdf"),
                                render::pages_to_pdf(p.key_pages, id, pdf_metadata(set.spec(), p.key.title, options)));
        }
      });
    }
    // 4. the class-set PDFs: one cairo surface each, so drawn in id order
    if (options.pdf && !options.split) {
      if (!sheets_pdf) {
        sheets_pdf = std::make_unique<ClassSetPdf>(options.out / "sheets.pdf",
                                                   pdf_metadata(set.spec(), printed[0].sheet.title, options),
                                                   printed[0].sheet.page);
        keys_pdf = std::make_unique<ClassSetPdf>(options.out / "keys.pdf",
                                                 pdf_metadata(set.spec(), printed[0].key.title, options),
                                                 printed[0].key.page);
      }
      // The two files are independent: with two jobs or more, the keys are drawn on a second
      // thread (each document has its own font map; each is drawn in id order all the same).
      std::exception_ptr keys_error;
      const auto draw_keys = [&] {
        try {
          for (int i = 0; i < count; ++i) keys_pdf->add(printed[i].key_pages, sheets[i].id.str(), options.duplex);
        } catch (...) {
          keys_error = std::current_exception();
        }
      };
      {
        std::jthread keys_thread;
        if (options.jobs > 1) keys_thread = std::jthread(draw_keys);
        for (int i = 0; i < count; ++i) sheets_pdf->add(printed[i].sheet_pages, sheets[i].id.str(), options.duplex);
        if (options.jobs <= 1) draw_keys();
      }
      if (keys_error) std::rethrow_exception(keys_error);
    }
    for (int i = 0; i < count; ++i) {
      KeyJson::sheet(key, sheets[i], start + i == 0);
      index.push_back({sheets[i].id.str()});
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
  if (sheets_pdf) {
    sheets_pdf->commit();
    keys_pdf->commit();
  }
  key_file.commit();
  if (options.svg)
    write_file_atomically(options.out / "index.html",
                          index_html(set.spec().title, set.spec().course, set.language(), index,
                                     !options.pdf    ? PdfLinks::none
                                     : options.split ? PdfLinks::per_sheet
                                                     : PdfLinks::class_set));
  return report;
}

}  // namespace epure::output
