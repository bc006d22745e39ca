// What scan writes from its readings (src/scan/scan_outputs.cpp) and the teacher's corrections
// applied to them (scan_session.cpp: the file epure grade reads, grading/corrections.h).
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>

#include "grading/corrections.h"
#include "scan/page_input.h"
#include "scan/scan_outputs.h"
#include "scan/scan_session.h"
#include "support/base64.h"
#include "support/png_size.h"

using namespace epure;
using namespace epure::scan;

namespace {

FieldResult field(std::string question, std::string value, bool uncertain) {
  FieldResult f;
  f.page = 1;
  f.reading.question = std::move(question);
  f.reading.value = std::move(value);
  f.reading.uncertain = uncertain;
  f.reading.why = uncertain ? "a cell below 0.75" : "";
  return f;
}

ScanResult sample() {
  ScanResult r;
  SheetResult& s = r.sheets["1000-0005-000S"];
  s.sheet = "1000-0005-000S";
  s.pages = 1;
  s.seen = {true};
  for (auto f : {field("1.t", "0,4", true), field("1.position", "between", false), field("student_number", "20260000", false)})
    s.fields.emplace(f.reading.question, f);
  return r;
}

}  // namespace

TEST_CASE("scan outputs: review.html's data cannot close or escape its script, whatever layout.json names") {
  ScanResult r = sample();
  SheetResult& s = r.sheets.begin()->second;
  s.fields.emplace("</script><!--<script>", field("</script><!--<script>", "1", true));
  SetLayout layout;
  layout.language = "fr";
  const std::string page = review_html(r, layout);
  const auto data_at = page.find("id=\"review-data\"");
  REQUIRE(data_at != std::string::npos);
  const auto open_end = page.find('>', data_at) + 1;
  const auto close = page.find("</script>", open_end);
  REQUIRE(close != std::string::npos);
  const std::string data = page.substr(open_end, close - open_end);
  CHECK(data.find('<') == std::string::npos);
  const auto parsed = nlohmann::json::parse(data);
  bool found = false;
  for (const auto& f : parsed["fields"]) found |= f["question"] == "</script><!--<script>";
  CHECK(found);
  CHECK(parsed["fields"].size() == 2);  // the fields to review only
}

TEST_CASE("scan outputs: review.html's crops come back from the spool, the uncertain fields' only, written a piece at a time") {
  ScanResult r = sample();
  r.spool = std::make_shared<CropSpool>(std::filesystem::temp_directory_path());
  SheetResult& s = r.sheets.begin()->second;
  s.fields.at("1.t").crop = r.spool->add("crop of 1.t");
  FieldResult other = field("2.t", "3", true);
  other.crop = r.spool->add(std::string("\0\xff", 2));
  s.fields.emplace("2.t", other);
  SetLayout layout;
  layout.language = "en";
  std::string pieces;
  int count = 0;
  write_review_html(r, layout, [&](std::string_view bytes) { pieces += bytes, ++count; });
  const std::string page = review_html(r, layout);
  CHECK(pieces == page);
  CHECK(count > 3);
  const auto open_end = page.find('>', page.find("id=\"review-data\"")) + 1;
  const auto parsed = nlohmann::json::parse(page.substr(open_end, page.find("</script>", open_end) - open_end));
  REQUIRE(parsed["fields"].size() == 2);
  CHECK(parsed["fields"][0]["question"] == "1.t");
  CHECK(parsed["fields"][0]["crop"] == base64("crop of 1.t"));
  CHECK(parsed["fields"][1]["crop"] == base64(std::string("\0\xff", 2)));
  CHECK(parsed["words"]["sheet"].is_string());
}

TEST_CASE("scan corrections: the file epure grade reads, each entry placed or said with its number") {
  ScanResult r = sample();
  const grading::Corrections c = grading::read_corrections(R"({"format": "epure-corrections", "version": 1, "corrections": [
      {"sheet": "1000-0005-000s", "question": "1.T", "value": "0,48", "note": "a 4"},
      {"sheet": "1000-0005-001Q", "question": "1.t", "value": "1"},
      {"sheet": "10000005000s", "question": "2.t", "value": "1"},
      {"sheet": "1000-0005-000S", "question": "student_number", "value": "20260001"},
      {"sheet": "1000-0005-000S", "question": "1.t", "value": "0,49"}]})",
                                                           "c.json");
  REQUIRE(c.readable);
  apply_corrections(r, c, Texts::builtin("en"));
  const SheetResult& s = r.sheets.begin()->second;
  const FieldResult& t = s.fields.at("1.t");
  CHECK(t.corrected);
  CHECK(t.reading.value == "0,49");  // the later of two entries wins, as in epure grade
  CHECK_FALSE(t.reading.uncertain);
  CHECK(s.student_number == "20260001");
  CHECK(fields_to_review(r) == 0);
  CHECK(r.problems == std::vector<std::string>{
                          "c.json: entry 2: sheet 1000-0005-001Q was not scanned: not applied",
                          "c.json: entry 3: sheet 1000-0005-000S has no field 2.t on its scanned pages: not applied",
                          "c.json: entry 5: corrects 1.t of sheet 1000-0005-000S again, after entry 1: this one is applied"});
  // answers.json holds the corrected value, not the one read
  const auto answers = nlohmann::json::parse(answers_json(r));
  CHECK(answers[0]["answers"]["1.t"] == "0,49");
}

TEST_CASE("scan crops: a crop's PNG states its resolution, read back by grading's size and by libpng") {
  cv::Mat grey(30, 80, CV_8UC1, cv::Scalar(255));
  grey(cv::Rect(10, 5, 20, 10)).setTo(0);
  const std::string png = encode_png(grey, 216);
  const auto size = png_size(png);
  REQUIRE(size);
  CHECK(size->width == 80);
  CHECK(size->height == 30);
  CHECK(size->dots_per_inch == doctest::Approx(216).epsilon(1e-4));  // 8504 pixels a metre
  CHECK(png_size(encode_png(grey))->dots_per_inch == 0);             // no pHYs: unstated
  // the chunk right after IHDR, its CRC as Python's zlib.crc32 gives it (libpng only warns of a
  // bad CRC on an ancillary chunk, so the bytes are compared)
  const std::string phys("\x00\x00\x00\x09pHYs\x00\x00\x21\x38\x00\x00\x21\x38\x01\x45\x96\x31\x60", 21);
  CHECK(png.substr(33, 21) == phys);
  // and the file still decodes to the same pixels
  auto pages = open_pages_in_memory(png, "crop.png");
  const auto page = pages->next();
  REQUIRE(page);
  CHECK(page->error.empty());
  REQUIRE(page->image.rows == 30);
  CHECK(page->image.at<unsigned char>(10, 20) == 0);
  CHECK(page->image.at<unsigned char>(25, 70) == 255);
}
