#include "scan/scan_session.h"

#include <fmt/format.h>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <deque>
#include <exception>
#include <iterator>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "exercises/sheet_id.h"
#include "output/atomic_file.h"
#include "scan/page_input.h"
#include "scan/registration.h"
#include "support/safe_file_name.h"

namespace epure::scan {

namespace {

// What reading one page gives, before the pages are gathered by sheet.
struct PageOutcome {
  PageRecord record;
  std::vector<FieldResult> fields;
  std::vector<std::string> crops;  // each field's PNG, "" when not kept
};

// A crop (--crops) to write once its page is gathered.
struct CropFile {
  std::filesystem::path path;
  std::string png;
};

constexpr double kCropScale = 3.0;  // crops: 3 pixels per point, 216 dpi, which each crop's PNG states (pHYs)

PageOutcome read_page(InputPage in, const SetLayout& layout, const PageFrame& frame, const ScanOptions& options,
                      const DigitClassifier& net) {
  PageOutcome out;
  PageRecord& r = out.record;
  r.file = in.file;
  r.page = in.page;
  if (!in.error.empty()) {
    r.status = PageStatus::unreadable;
    r.detail = in.error;
    return out;
  }
  const PageFinding found = find_page(in.image, frame);
  r.marks = found.marks;
  r.residual = found.residual;
  if (found.blank) {
    r.status = PageStatus::blank;
    return out;
  }
  if (!found.code) {
    r.status = PageStatus::unknown;
    r.detail = found.code_text.empty() ? found.problem : fmt::format("a code that is not an epure page code: \"{}\"", found.code_text);
    return out;
  }
  r.sheet = found.code->sheet;
  r.sheet_page = found.code->page;
  const SheetLayout* sheet = layout.find(r.sheet);
  if (!sheet) {
    const auto id = parse_sheet_id(r.sheet);
    if (id.id && (id.id->seed != layout.seed || id.id->version != layout.draw_version)) {
      r.status = PageStatus::another_set;
      r.detail = fmt::format("sheet {} is of another set (seed {}, this set's is {})", r.sheet, id.id->seed, layout.seed);
    } else {
      r.status = PageStatus::unknown;
      r.detail = fmt::format("sheet {} is not in this set's layout.json", r.sheet);
    }
    return out;
  }
  if (found.code->page > static_cast<int>(sheet->pages.size()) || found.code->pages != static_cast<int>(sheet->pages.size())) {
    r.status = PageStatus::unknown;
    r.detail = fmt::format("page {}/{} of sheet {}, which has {} pages", found.code->page, found.code->pages, r.sheet, sheet->pages.size());
    return out;
  }
  if (!found.map) {
    r.status = PageStatus::unreadable;
    r.detail = found.problem;
    return out;
  }
  const PageLayout& page = sheet->pages[static_cast<std::size_t>(found.code->page - 1)];
  // The page's own marks and code, when they differ from the set's first page (another paper size)
  PageMap map = *found.map;
  double ink = found.ink;
  const PageFrame own = frame_of(page);
  if (own.marks[0].x != frame.marks[0].x || own.marks[0].y != frame.marks[0].y || own.width != frame.width) {
    const PageFinding again = find_page(in.image, own);
    if (!again.map) {
      r.status = PageStatus::unreadable;
      r.detail = again.problem;
      return out;
    }
    map = *again.map;
    ink = again.ink;
  }
  r.status = PageStatus::identified;
  const double paper = paper_level(in.image);
  for (const auto& f : page.fields) {
    FieldResult fr;
    fr.page = page.page;
    fr.reading = read_field(in.image, map, f, paper, ink, layout.decimal_separator, net);
    out.crops.push_back(fr.reading.uncertain || options.all_crops ? encode_png(field_image(in.image, map, f, kCropScale), kCropScale * 72)
                                                                  : std::string());
    out.fields.push_back(std::move(fr));
  }
  return out;
}

// Gathers the next page in input order into its sheet: the first registered copy of a page
// counts, a later one is a duplicate and its readings are dropped. The crops of the fields kept
// go to the spool (uncertain fields) and, with --crops, are returned to be written (the sheet's
// directory is made here, once).
std::vector<CropFile> gather(PageOutcome& o, const SetLayout& layout, const ScanOptions& options, ScanResult& result,
                             std::set<std::string>& crop_dirs) {
  std::vector<CropFile> files;
  PageRecord& r = o.record;
  if (r.status == PageStatus::identified) {
    const SheetLayout& layout_sheet = *layout.find(r.sheet);
    auto [it, fresh] = result.sheets.try_emplace(r.sheet);
    SheetResult& s = it->second;
    if (fresh) {
      s.sheet = r.sheet;
      s.pages = static_cast<int>(layout_sheet.pages.size());
      s.seen.assign(static_cast<std::size_t>(s.pages), false);
      if (layout_sheet.student) {
        s.student_name = layout_sheet.student->name;
        s.roster_number = layout_sheet.student->number;
        s.number_printed = true;
        for (const auto& p : layout_sheet.pages)
          for (const auto& f : p.fields) s.number_printed = s.number_printed && f.question != "student_number";
      }
    }
    if (s.seen[static_cast<std::size_t>(r.sheet_page - 1)]) {
      r.status = PageStatus::duplicate;
      r.detail = fmt::format("page {} of sheet {} was read from an earlier page", r.sheet_page, r.sheet);
    } else {
      s.seen[static_cast<std::size_t>(r.sheet_page - 1)] = true;
      for (std::size_t i = 0; i < o.fields.size(); ++i) {
        FieldResult& f = o.fields[i];
        std::string& png = o.crops[i];
        const std::string question = f.reading.question;
        if (question == "student_number" && !f.reading.uncertain) s.student_number = f.reading.value;
        auto [at, kept] = s.fields.emplace(question, std::move(f));
        if (!kept || png.empty()) continue;
        if (at->second.reading.uncertain) at->second.crop = result.spool->add(png);
        if (options.all_crops && question != "student_number" && safe_file_name(r.sheet) && safe_file_name(question)) {
          const std::filesystem::path dir = options.out / "crops" / r.sheet;
          if (crop_dirs.insert(r.sheet).second) std::filesystem::create_directories(dir);
          files.push_back({dir / (question + ".png"), std::move(png)});
        }
      }
    }
  }
  result.pages.push_back(std::move(r));
  return files;
}

}  // namespace

const char* page_status_name(PageStatus s) {
  switch (s) {
    case PageStatus::identified: return "identified";
    case PageStatus::duplicate: return "duplicate";
    case PageStatus::unknown: return "unknown";
    case PageStatus::blank: return "blank";
    case PageStatus::another_set: return "another set";
    case PageStatus::unreadable: return "unreadable";
  }
  return "?";
}

ScanResult scan_inputs(const std::vector<std::string>& inputs, const SetLayout& layout, const ScanOptions& options,
                       const DigitClassifier& net) {
  if (layout.sheets.empty()) throw std::runtime_error("layout.json holds no sheet");
  const PageFrame frame = frame_of(layout.sheets.begin()->second.pages.front());
  // OpenCV's own threads would only compete with ours
  cv::setNumThreads(1);
  const int jobs = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  ScanResult result;
  if (!options.out.empty()) std::filesystem::create_directories(options.out);
  result.spool = std::make_shared<CropSpool>(options.out.empty() ? std::filesystem::temp_directory_path() : options.out);

  // One thread decodes pages in input order into a short queue; `jobs` workers read them, and
  // the worker that finishes the next page in input order gathers it and those after it already
  // read. The decoder stays at most `window` pages ahead of the gathering, so the pages read but
  // not yet gathered (waiting for a slow one before them) are few whatever the stack.
  std::mutex mu;
  std::condition_variable cv_space, cv_work;
  std::deque<std::pair<std::size_t, InputPage>> queue;
  std::map<std::size_t, PageOutcome> ready;  // read, waiting for the pages before them
  std::size_t gathered = 0;                  // the pages gathered, in input order
  std::set<std::string> crop_dirs;           // the sheets whose crops directory is made
  bool done = false;
  std::exception_ptr failure;  // a crop or the spool that could not be written: the run stops
  const std::size_t capacity = static_cast<std::size_t>(2 * jobs);
  const std::size_t window = capacity + static_cast<std::size_t>(2 * jobs);

  auto worker = [&] {
    for (;;) {
      std::pair<std::size_t, InputPage> item;
      {
        std::unique_lock lock(mu);
        cv_work.wait(lock, [&] { return !queue.empty() || done; });
        if (queue.empty()) return;
        item = std::move(queue.front());
        queue.pop_front();
        cv_space.notify_one();
        if (failure) continue;
      }
      PageOutcome o;
      try {
        o = read_page(std::move(item.second), layout, frame, options, net);
      } catch (const std::exception& e) {
        o.record.status = PageStatus::unreadable;
        o.record.detail = e.what();
      }
      std::vector<CropFile> files;
      {
        std::lock_guard lock(mu);
        if (failure) continue;
        ready.emplace(item.first, std::move(o));
        try {
          for (auto next = ready.begin(); next != ready.end() && next->first == gathered; next = ready.begin()) {
            auto more = gather(next->second, layout, options, result, crop_dirs);
            ready.erase(next);
            ++gathered;
            std::move(more.begin(), more.end(), std::back_inserter(files));
          }
        } catch (...) {
          failure = std::current_exception();
        }
        cv_space.notify_one();
      }
      // each file is one field's of one sheet, written by one worker: no lock needed
      try {
        for (const auto& f : files) output::write_file_atomically(f.path, f.png);
      } catch (...) {
        std::lock_guard lock(mu);
        if (!failure) failure = std::current_exception();
        cv_space.notify_one();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < jobs; ++i) threads.emplace_back(worker);
  std::size_t index = 0;
  for (const auto& path : inputs) {
    auto stream = open_pages(path, options.render_dpi);
    for (;;) {
      std::optional<InputPage> page;
      try {
        page = stream->next();
      } catch (const std::exception& e) {
        page = InputPage{path, 0, {}, e.what(), 0};
      }
      if (!page) break;
      const bool failed = page->page == 0;  // the stream failed: on to the next file
      std::unique_lock lock(mu);
      cv_space.wait(lock, [&] { return failure || (queue.size() < capacity && index - gathered < window); });
      if (failure) break;
      queue.emplace_back(index++, std::move(*page));
      cv_work.notify_one();
      if (failed) break;
    }
    std::lock_guard lock(mu);
    if (failure) break;
  }
  {
    std::lock_guard lock(mu);
    done = true;
  }
  cv_work.notify_all();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  return result;
}

void apply_corrections(ScanResult& result, const grading::Corrections& corrections, const Texts& texts) {
  if (!corrections.readable) return;
  auto say = [&](const grading::Correction& c, std::string code, TextVars vars) {
    result.problems.push_back(fmt::format("{}: {}", corrections.source,
                                          grading::describe({c.entry, std::move(code), std::move(vars)}, texts)));
  };
  auto same_letters = [](std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
  };
  std::map<std::pair<std::string, std::string>, int> applied;  // (sheet, question) → entry
  for (const auto& c : corrections.entries) {
    const auto parsed = parse_sheet_id(c.sheet);
    const std::string id = parsed.id ? parsed.id->str() : c.sheet;
    const auto s = result.sheets.find(id);
    if (s == result.sheets.end()) {
      say(c, "not_scanned", {{"sheet", c.sheet}});
      continue;
    }
    auto f = s->second.fields.find(c.question);
    if (f == s->second.fields.end())
      f = std::find_if(s->second.fields.begin(), s->second.fields.end(),
                       [&](const auto& field) { return same_letters(field.first, c.question); });
    if (f == s->second.fields.end()) {
      say(c, "not_on_pages", {{"sheet", id}, {"question", c.question}});
      continue;
    }
    if (auto [at, fresh] = applied.try_emplace({id, f->first}, c.entry); !fresh) {
      say(c, "repeated", {{"first", std::to_string(at->second)}, {"sheet", id}, {"question", f->first}});
      at->second = c.entry;
    }
    FieldReading& r = f->second.reading;
    r.value = c.value;
    r.blank = c.value.empty();
    r.uncertain = false;
    f->second.corrected = true;
    f->second.note = c.note;
    if (f->first == "student_number") s->second.student_number = c.value;
  }
}

}  // namespace epure::scan
