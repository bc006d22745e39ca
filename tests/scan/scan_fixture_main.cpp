// epure_scan_fixture: a class's scanned sheets, made by the suite (scan_fixture.h).
//
//   epure_scan_fixture --key DIR/key.json --out DIR [--set SET] [--sheets N] [--dpi D]
//                      [--format pdf|pdf-flate|png|jpeg|tiff|tiff-g4]
//                      [--degrade none|copier|bilevel|phone] [--seed S] [--mess]
//
// With --set, the pages are the sheets `epure generate` printed: SET/sheets.pdf rendered at D
// dpi (poppler), written into where SET/layout.json says (copied to DIR/layout.json). Without
// it, the fields of every sheet of the key are laid out here (lay_out_fields: numbers as comb
// fields, yes/no, words and sides as ticks, the student number) and drawn, into DIR/layout.json.
// Writes DIR/truth.json (what was written, per sheet and question, as `epure grade` should read
// it) and the scans:
// DIR/scans.<ext> (one file; PNG and JPEG one file per page, scan-NNN.<ext>). --mess shuffles
// the pages, drops one, duplicates one, adds a blank page and a page of another set.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grading/answer_key.h"
#include "grading/faces.h"
#include "output/atomic_file.h"
#include "exercises/page_code.h"
#include "scan/page_input.h"
#include "scan_fixture.h"

#include <set>

using namespace epure;
using namespace epure::scan;
using namespace epure::scan::fixture;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A key's number as a student writes it with `decimals` decimals and the set's separator.
std::string written(double v, int decimals, const std::string& sep) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s == fmt::format("-{:.{}f}", 0.0, decimals)) s.erase(0, 1);
  if (sep == ",") std::replace(s.begin(), s.end(), '.', ',');
  // trailing zeros of the decimals left empty, as a student often does
  while (decimals > 0 && s.back() == '0') s.pop_back();
  if (s.back() == ',' || s.back() == '.') s.pop_back();
  return s;
}

Degradation profile(const std::string& name, Rng& rng) {
  Degradation d;
  if (name == "none") return d;
  d.rotate_deg = rng.uniform(-5, 5);
  d.upside_down = rng.chance(0.3);
  d.scale = rng.uniform(0.97, 1.03);
  d.shift_x = rng.uniform(-8, 8);
  d.shift_y = rng.uniform(-8, 8);
  if (name == "copier") {
    d.blur_sigma = rng.uniform(0.3, 1.0);
    d.noise = rng.uniform(2, 8);
    d.jpeg_quality = 50;
  } else if (name == "bilevel") {
    d.blur_sigma = 0.5;
    d.bilevel = true;
  } else if (name == "phone") {
    d.blur_sigma = 1.2;
    d.noise = 10;
    d.jpeg_quality = 50;
  }
  return d;
}

const TickStyle kStyles[] = {TickStyle::cross, TickStyle::check, TickStyle::cross, TickStyle::faint};

// The field of a question on a sheet's pages, or null.
const FieldLayout* find_field(const SheetLayout& sheet, const std::string& question) {
  for (const auto& p : sheet.pages)
    for (const auto& f : p.fields)
      if (f.question == question) return &f;
  return nullptr;
}

// The sheets `epure generate` printed (SET/sheets.pdf and SET/layout.json), rendered at `dpi`,
// the key's answers written where layout.json says: every number in its comb, every tick.
// Throws when a key's question has no field or a value does not fit its comb (a sheet a student
// could not answer).
void written_sets(const std::string& set_dir, const grading::AnswerKey& key, int sheets, double dpi, Rng& rng,
                  SetLayout& layout, nlohmann::json& truth, std::vector<std::pair<std::string, cv::Mat>>& pages) {
  layout = read_layout_file(set_dir + "/layout.json");
  const std::string& sep = layout.decimal_separator;
  auto stream = open_pages(set_dir + "/sheets.pdf", static_cast<int>(dpi));
  int tick_count = 0, done = 0;
  for (const auto& sheet : key.sheets()) {
    const SheetLayout* sl = layout.find(sheet.id);
    if (!sl) throw std::runtime_error(fmt::format("layout.json: no sheet {}", sheet.id));
    const bool take = done < sheets;
    Writing w;
    nlohmann::json answers = nlohmann::json::object();
    const std::string number = fmt::format("{:08d}", 20260000 + done);
    if (take) {
      w.comb["student_number"] = number;
      for (const auto& e : sheet.exercises)
        for (const auto& q : e.questions) {
          const FieldLayout* f = find_field(*sl, q.id);
          if (!f) throw std::runtime_error(fmt::format("sheet {}: no field for question {}", sheet.id, q.id));
          if (q.type == grading::AnswerType::number) {
            const std::string v = written(q.number, f->decimals, sep);
            if (comb_cells(*f, v).empty())
              throw std::runtime_error(fmt::format("sheet {}: {} = {} does not fit its comb of {} cells", sheet.id, q.id, v, f->cells.size()));
            w.comb[q.id] = v;
            answers[q.id] = v;
            continue;
          }
          std::vector<std::string> ticked;
          std::string v;
          if (q.type == grading::AnswerType::boolean) {
            v = q.boolean ? "true" : "false";
            ticked = {v};
          } else if (q.type == grading::AnswerType::choice) {
            v = q.word;
            ticked = {v};
          } else if (q.type == grading::AnswerType::faces) {
            for (const auto& value : f->values)
              if (value == "none" ? q.faces == 0 : (q.faces & grading::face_bit(value)) != 0) ticked.push_back(value);
            for (const auto& t : ticked) v += (v.empty() ? "" : " ") + t;
          } else {
            continue;
          }
          w.ticks[q.id] = ticked;
          w.tick_style[q.id] = kStyles[tick_count++ % 4];
          // every fifth tick of a one-box field: another box ticked first, then filled to cancel it
          if (tick_count % 5 == 0 && !f->multiple)
            for (const auto& value : f->values)
              if (value != v) {
                w.cancelled[q.id] = value;
                break;
              }
          answers[q.id] = v;
        }
      truth[sheet.id] = {{"student_number", number}, {"answers", answers}};
    }
    for (const auto& p : sl->pages) {
      auto page = stream->next();
      if (!page || !page->error.empty())
        throw std::runtime_error(fmt::format("{}/sheets.pdf: sheet {} page {}: {}", set_dir, sheet.id, p.page, page ? page->error : "missing"));
      if (!take) continue;
      write_fields(page->image, p, w, dpi, rng);
      pages.emplace_back(fmt::format("{} p{}", sheet.id, p.page), std::move(page->image));
    }
    if (take) ++done;
    else break;
  }
  // only the sheets written
  for (auto it = layout.sheets.begin(); it != layout.sheets.end();)
    it = truth.contains(it->first) ? std::next(it) : layout.sheets.erase(it);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The suite's scans of a set: layout.json, truth.json and the scanned pages"};
  std::string key_file, out, format = "pdf", degrade_name = "copier", set_dir;
  int sheets = 3;
  double dpi = 200;
  std::uint64_t seed = 1;
  bool mess = false;
  app.add_option("--key", key_file)->required();
  app.add_option("--out", out)->required();
  app.add_option("--set", set_dir);
  app.add_option("--sheets", sheets);
  app.add_option("--dpi", dpi);
  app.add_option("--format", format);
  app.add_option("--degrade", degrade_name);
  app.add_option("--seed", seed);
  app.add_flag("--mess", mess);
  CLI11_PARSE(app, argc, argv);
  try {
    const grading::AnswerKey key = grading::read_key_json(read_text(key_file), key_file);
    const std::string sep = key.info.language == "fr" ? "," : ".";
    const int decimals = key.info.decimals;
    Rng rng(seed, 30);
    SetLayout layout;
    layout.title = key.info.title;
    layout.language = key.info.language;
    layout.decimal_separator = sep;
    layout.seed = key.info.seed;
    layout.draw_version = key.info.draw_version;
    nlohmann::json truth = nlohmann::json::object();
    std::vector<std::pair<std::string, cv::Mat>> pages;  // (label, image)
    const auto& styles = kStyles;
    int tick_count = 0;
    if (!set_dir.empty()) written_sets(set_dir, key, sheets, dpi, rng, layout, truth, pages);
    for (const auto& sheet : key.sheets()) {
      if (!set_dir.empty()) break;
      if (static_cast<int>(layout.sheets.size()) >= sheets) break;
      std::vector<FieldSpec> specs;
      Writing w;
      nlohmann::json answers = nlohmann::json::object();
      const std::string number = fmt::format("{:08d}", 20260000 + static_cast<int>(layout.sheets.size()));
      specs.push_back({"student_number", FieldType::comb, 8, 0, false, {}, false});
      w.comb["student_number"] = number;
      for (const auto& e : sheet.exercises)
        for (const auto& q : e.questions) {
          if (q.type == grading::AnswerType::number) {
            const std::string v = written(q.number, decimals, sep);
            FieldSpec f{q.id, FieldType::comb, 3, decimals, true, {}, false};
            const auto probe = lay_out_fields({f});
            if (comb_cells(probe[0].fields[0], v).empty()) continue;  // too large for three integer cells
            specs.push_back(f);
            w.comb[q.id] = v;
            answers[q.id] = v;
          } else if (q.type == grading::AnswerType::boolean) {
            specs.push_back({q.id, FieldType::tick, 0, 0, false, {"true", "false"}, false});
            const std::string v = q.boolean ? "true" : "false";
            w.ticks[q.id] = {v};
            w.tick_style[q.id] = styles[tick_count++ % 4];
            if (tick_count % 5 == 0) w.cancelled[q.id] = q.boolean ? "false" : "true";
            answers[q.id] = v;
          } else if (q.type == grading::AnswerType::faces) {
            // the sides as boxes (a plane figure's four, a solid's six) and "none", as the
            // answers spreadsheet spells them; the expected ones ticked
            const bool space = std::any_of(e.questions.begin(), e.questions.end(),
                                           [](const auto& other) { return other.id.ends_with(".z"); });
            std::vector<std::string> values = {"+x", "-x", "+y", "-y"};
            if (space) values.insert(values.end(), {"+z", "-z"});
            values.push_back("none");
            std::vector<std::string> ticked;
            for (const auto& v : values)
              if (v == "none" ? q.faces == 0 : (q.faces & grading::face_bit(v)) != 0) ticked.push_back(v);
            std::string v;
            for (const auto& t : ticked) v += (v.empty() ? "" : " ") + t;
            specs.push_back({q.id, FieldType::tick, 0, 0, false, values, true});
            w.ticks[q.id] = ticked;
            w.tick_style[q.id] = styles[tick_count++ % 4];
            answers[q.id] = v;
          } else if (q.type == grading::AnswerType::choice) {
            // the expected word and a neighbour, until the sheets lay their own choices out
            const std::string other = q.word == "before" ? "after" : "before";
            specs.push_back({q.id, FieldType::tick, 0, 0, false, {q.word, other}, false});
            w.ticks[q.id] = {q.word};
            w.tick_style[q.id] = styles[tick_count++ % 4];
            answers[q.id] = q.word;
          }
        }
      SheetLayout sl;
      sl.sheet = sheet.id;
      sl.student = StudentLayout{number, fmt::format("Student {}", layout.sheets.size() + 1)};
      sl.pages = lay_out_fields(specs);
      const int count = static_cast<int>(sl.pages.size());
      for (const auto& p : sl.pages) {
        const std::string code = page_code_text({sheet.id, p.page, count});
        pages.emplace_back(fmt::format("{} p{}", sheet.id, p.page), draw_page(p, code, w, dpi, rng));
      }
      truth[sheet.id] = {{"student_number", number}, {"answers", answers}};
      layout.sheets.emplace(sheet.id, std::move(sl));
    }
    std::filesystem::create_directories(out);
    output::write_file_atomically(std::filesystem::path(out) / "layout.json", layout_json(layout));
    nlohmann::json info = {{"sheets", truth}};
    if (mess && pages.size() >= 3) {
      // a page of another set (another seed), a blank page, a duplicate, one page dropped, shuffled
      const auto& first = layout.sheets.begin()->second;
      const std::string foreign = SheetId{key.info.draw_version, (key.info.seed + 1) % kMaxSeed, 0}.str();
      pages.emplace_back("foreign", draw_page(first.pages[0], page_code_text({foreign, 1, static_cast<int>(first.pages.size())}), {}, dpi, rng));
      pages.emplace_back("blank", cv::Mat(pages[0].second.size(), CV_8UC1, cv::Scalar(255)));
      pages.push_back(pages[0]);
      const std::size_t drop = pages.size() / 2;
      info["dropped"] = pages[drop].first;
      pages.erase(pages.begin() + static_cast<std::ptrdiff_t>(drop));
      for (std::size_t i = pages.size() - 1; i > 0; --i)
        std::swap(pages[i], pages[static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(i)))]);
    }
    std::vector<cv::Mat> images;
    nlohmann::json order = nlohmann::json::array();
    for (auto& [label, img] : pages) {
      Degradation d = profile(degrade_name, rng);
      images.push_back(degrade(img, d, dpi, rng));
      order.push_back(label);
    }
    info["pages"] = order;
    output::write_file_atomically(std::filesystem::path(out) / "truth.json", info.dump(1) + "\n");
    const auto base = std::filesystem::path(out);
    if (format == "pdf") write_pdf((base / "scans.pdf").string(), images, dpi, 75);
    else if (format == "pdf-flate") write_pdf((base / "scans.pdf").string(), images, dpi, 0);
    else if (format == "tiff") write_tiff((base / "scans.tif").string(), images, dpi, false);
    else if (format == "tiff-g4") write_tiff((base / "scans.tif").string(), images, dpi, true);
    else if (format == "png" || format == "jpeg")
      for (std::size_t i = 0; i < images.size(); ++i)
        output::write_file_atomically(base / fmt::format("scan-{:03d}.{}", i + 1, format == "png" ? "png" : "jpg"),
                                      format == "png" ? encode_png(images[i]) : encode_jpeg(images[i], 80));
    else throw std::runtime_error("--format: pdf, pdf-flate, png, jpeg, tiff or tiff-g4");
    fmt::print("{} sheets, {} pages\n", layout.sheets.size(), images.size());
  } catch (const std::exception& e) {
    fmt::print(stderr, "epure_scan_fixture: {}\n", e.what());
    return 1;
  }
  return 0;
}
