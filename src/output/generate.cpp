#include "output/generate.h"

#include <fmt/format.h>

#include "exercises/key_json.h"
#include "output/atomic_file.h"
#include "output/index_html.h"
#include "output/parallel.h"
#include "render/svg_page.h"

namespace epure::output {

namespace {

// Sheets drawn and written per round: enough to keep every job busy, few enough that memory
// stays flat whatever the size of the set.
constexpr int kBatch = 64;

struct Rendered {
  std::string sheet_svg, key_svg;
};

}  // namespace

GenerateReport generate_set(WorksheetSet& set, const GenerateOptions& options) {
  namespace fs = std::filesystem;
  if (options.sheets < 1 || options.sheets > kMaxSheets)
    throw std::runtime_error(fmt::format("--sheets must be from 1 to {}", kMaxSheets));
  if (set.next_index() != 0) throw std::logic_error("generate_set needs a fresh set");
  fs::create_directories(options.out / "sheets");
  fs::create_directories(options.out / "keys");

  AtomicFile key_file(options.out / "key.json");
  fmt::memory_buffer key;
  KeyJson::begin(key, set, options.epure_version);
  std::vector<IndexEntry> index;
  const int slots = static_cast<int>(set.spec().exercises.size());
  GenerateReport report;

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
    // 3. documents drawn as SVG in parallel, written in order
    std::vector<Rendered> rendered(count);
    if (options.svg) {
      parallel_for(count, options.jobs, [&](int i) {
        rendered[i].sheet_svg = render::document_to_svg(set.sheet_document(sheets[i]));
        rendered[i].key_svg = render::document_to_svg(set.key_document(sheets[i]));
        const std::string id = sheets[i].id.str();
        write_file_atomically(options.out / "sheets" / (id + ".svg"), rendered[i].sheet_svg);
        write_file_atomically(options.out / "keys" / (id + ".svg"), rendered[i].key_svg);
      });
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
  key_file.commit();
  if (options.svg)
    write_file_atomically(options.out / "index.html",
                          index_html(set.spec().title, set.spec().course, set.language(), index));
  return report;
}

}  // namespace epure::output
