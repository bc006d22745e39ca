// layout_pages: the page economy and the cost of laying out a set's sheets and keys, in process,
// from the layout's own pages (no SVG or PDF written). For bench/README.md, "Pages".
//
//   layout_pages [--spec builtin|builtin:3d] [--sheets N] [--seeds A-B] [--lang en|fr|both]
//                [--difficulty easy|standard|hard|all] [--paper a4|letter|both]
//                [--shrink PT] [--min-scale S] [--time RUNS]
//
// Prints, for each set (spec, seed, language, difficulty, paper): the sheets' pages (mean, max,
// how many over 4), how many sheets have figures set smaller to meet the budget and the smallest
// scale any figure took, the keys' (mean, max, how many set smaller), and how much room a
// sheet's pages leave: the smallest, over the sheet's pages, of the text height left empty at
// the foot of a page (but its last), in points. --shrink PT lays every document out again with a
// text height PT points shorter (a taller bottom margin): how many sheets still keep their
// budget when page furniture takes that much more of every page. --min-scale S lets figures
// shrink further than the default (LayoutStyle::figure_min_scale) to meet the budget. --time
// RUNS lays every document out RUNS times and prints the CPU time a document and a page (the
// documents are made once, before the clock starts).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "render/layout.h"

using namespace epure;

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::vector<std::string> list(const std::string& value, const std::string& all, const std::vector<std::string>& every) {
  if (value == all) return every;
  return {value};
}

// The empty text height at the foot of each page but the last, the least of them (points).
double least_room(const std::vector<render::LaidOutPage>& pages, const render::LayoutStyle& style) {
  double least = 1e300;
  for (std::size_t p = 0; p + 1 < pages.size(); ++p) {
    double lowest = 0;
    for (const auto& b : pages[p].blocks)
      if (b.section >= 0 || b.block >= 0) lowest = std::max(lowest, b.rect.bottom());
    least = std::min(least, pages[p].size.height_pt - style.margin_bottom - lowest);
  }
  return least;
}

// The smallest ratio of a figure's width in `pages` to its width when the same document is laid
// out without a budget, figure by figure in document order: 1 when no figure was set smaller.
// A figure set beside its fields in one layout and above them in the other changes width too, so
// this reads the figures' sizes as printed, not the scale the layout chose.
double smallest_scale(const render::Document& doc, const std::vector<render::LaidOutPage>& pages,
                      const render::LayoutStyle& style) {
  if (doc.page_budget == 0) return 1;
  render::Document free = doc;
  free.page_budget = 0;
  const auto full = render::layout_document(free, style);
  std::vector<double> a, b;
  for (const auto& p : pages)
    for (const auto& f : p.figures) a.push_back(f.rect.width);
  for (const auto& p : full)
    for (const auto& f : p.figures) b.push_back(f.rect.width);
  double least = 1;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) least = std::min(least, a[i] / b[i]);
  return least;
}

}  // namespace

int main(int argc, char** argv) {
  std::string spec_name = "builtin", lang = "both", difficulty = "all", paper = "both";
  int sheets = 30, seed_from = 1, seed_to = 3, runs = 0;
  double shrink = 0, min_scale = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--spec") spec_name = value;
    else if (key == "--sheets") sheets = std::atoi(value.c_str());
    else if (key == "--seeds") {
      const auto dash = value.find('-');
      seed_from = std::atoi(value.substr(0, dash).c_str());
      seed_to = dash == std::string::npos ? seed_from : std::atoi(value.substr(dash + 1).c_str());
    } else if (key == "--lang") lang = value;
    else if (key == "--difficulty") difficulty = value;
    else if (key == "--paper") paper = value;
    else if (key == "--shrink") shrink = std::atof(value.c_str());
    else if (key == "--min-scale") min_scale = std::atof(value.c_str());
    else if (key == "--time") runs = std::atoi(value.c_str());
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  const auto spec = builtin_spec(spec_name);
  if (!spec) {
    std::fprintf(stderr, "no built-in spec %s\n", spec_name.c_str());
    return 2;
  }
  render::LayoutStyle style;
  style.margin_bottom += shrink;
  if (min_scale > 0) style.figure_min_scale = min_scale;

  std::printf("| set | sheets: mean | max | over 4 | smaller figures | least scale | least room (pt) | keys: mean | max | smaller |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  int all_sheets = 0, all_over = 0, all_smaller = 0, all_keys_smaller = 0;
  double all_least_scale = 1;
  double all_sheet_pages = 0, all_key_pages = 0, worst_room = 1e300;
  double cpu = 0;
  std::size_t timed_docs = 0, timed_pages = 0;
  for (int seed = seed_from; seed <= seed_to; ++seed) {
    for (const auto& l : list(lang, "both", {"en", "fr"})) {
      for (const auto& d : list(difficulty, "all", {"easy", "standard", "hard"})) {
        for (const auto& p : list(paper, "both", {"a4", "letter"})) {
          SetOptions options;
          options.language = l;
          options.page = p;
          options.difficulty = d == "easy" ? Difficulty::easy : d == "hard" ? Difficulty::hard : Difficulty::standard;
          WorksheetSet set(*spec, static_cast<std::uint64_t>(seed), options);
          std::vector<render::Document> docs;
          for (int i = 0; i < sheets; ++i) {
            const Sheet sheet = set.next();
            docs.push_back(set.sheet_document(sheet));
            docs.push_back(set.key_document(sheet));
          }
          int sheet_max = 0, key_max = 0, over = 0, smaller = 0, keys_smaller = 0;
          double sheet_pages = 0, key_pages = 0, room = 1e300, least_scale = 1;
          for (std::size_t k = 0; k < docs.size(); ++k) {
            const auto pages = render::layout_document(docs[k], style);
            const int n = static_cast<int>(pages.size());
            const double scale = smallest_scale(docs[k], pages, style);
            least_scale = std::min(least_scale, scale);
            if (k % 2 == 0) {
              smaller += scale < 1 - 1e-9;
              sheet_pages += n;
              sheet_max = std::max(sheet_max, n);
              over += n > 4;
              room = std::min(room, least_room(pages, style));
            } else {
              keys_smaller += scale < 1 - 1e-9;
              key_pages += n;
              key_max = std::max(key_max, n);
            }
          }
          for (int r = 0; r < runs; ++r) {
            const double t0 = cpu_seconds();
            for (const auto& doc : docs) timed_pages += render::layout_document(doc, style).size();
            cpu += cpu_seconds() - t0;
            timed_docs += docs.size();
          }
          std::printf("| %s %d %s %s %s | %.2f | %d | %d | %d | %.2f | %.0f | %.2f | %d | %d |\n", spec_name.c_str(), seed,
                      l.c_str(), d.c_str(), p.c_str(), sheet_pages / sheets, sheet_max, over, smaller, least_scale, room,
                      key_pages / sheets, key_max, keys_smaller);
          all_smaller += smaller;
          all_keys_smaller += keys_smaller;
          all_least_scale = std::min(all_least_scale, least_scale);
          all_sheets += sheets;
          all_over += over;
          all_sheet_pages += sheet_pages;
          all_key_pages += key_pages;
          worst_room = std::min(worst_room, room);
        }
      }
    }
  }
  std::printf("all: %d sheets, %.3f pages a sheet, %d over 4 pages, %d with figures set smaller (least scale %.2f), "
              "least room %.0f pt; keys %.3f pages on average, %d set smaller\n",
              all_sheets, all_sheet_pages / all_sheets, all_over, all_smaller, all_least_scale, worst_room,
              all_key_pages / all_sheets, all_keys_smaller);
  if (runs > 0)
    std::printf("layout CPU: %.3f ms a document, %.4f ms a page (%zu documents, %zu pages)\n", 1e3 * cpu / timed_docs,
                1e3 * cpu / timed_pages, timed_docs, timed_pages);
  return all_over == 0 ? 0 : 1;
}
