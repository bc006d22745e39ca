#pragma once
// A printed page's content, as exercises and keys describe it: headings, paragraphs, diagrams,
// answer fields. Knows nothing of exercises (they fill it) nor of the backend (layout.h places
// it, the SVG and PDF backends draw the placed result).
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "render/scene.h"

namespace epure::render {

struct Heading {
  RichText text;
  int level = 1;  // 1: exercise title; 2: sub-heading ("Worked solution")
};

struct Paragraph {
  RichText text;
  bool emphasis = false;  // set apart (the exercise's hint, a "given" box)
};

// An empty field where the student writes an answer, sized to what it should hold.
struct AnswerField {
  std::string question_id;  // "2.t_ab": printed small beside the field, so a scan can be read
  RichText prompt;          // "t_{ab} ="
  enum class Kind { number, point, point3, choice, faces, boolean } kind = Kind::number;
  std::vector<std::string> choices;  // for `choice` and `faces`: the options to tick
  // The last choice says something else than the others ("none" after the sides): a row of its own.
  bool last_choice_apart = false;
  // A number or a point's coordinates as comb fields, one character per cell (a scan reads
  // them): a sign cell, `integer_cells` digit cells, the document's decimal separator printed
  // between cells, `decimals` decimal cells. 0 integer cells: one plain box per value.
  int integer_cells = 0;
  int decimals = 0;
  // For `choice` and `faces`: what each option stands for, as a student types it in the answers
  // spreadsheet ("before", "-x", "none"), where it differs from the printed option; empty: the
  // printed options themselves.
  std::vector<std::string> choice_values{};
};

// In a key: a question and its expected answer.
struct AnswerLine {
  std::string question_id;
  RichText prompt;
  RichText answer;  // "≈ 2.17 (exact: 5 − 2√2)"
  // What was read for it, drawn under the prompt (a feedback sheet's crop of the scanned
  // field, so that a student sees why a 7 was read as 1); empty: none.
  Raster shown{};
};

struct Figure {
  Scene scene;
  double width_fraction = 0.6;  // of the text width; height follows the panels' aspect ratios
};

using Block = std::variant<Heading, Paragraph, AnswerField, AnswerLine, Figure>;

// One exercise (or the preamble): a unit that layout keeps together as Document::breaks says,
// and never separates a Figure from the Paragraph just before it nor from the fields or answers
// just after it.
struct Section {
  std::vector<Block> blocks;
  // Where the section's heading links to in a PDF (a URI relative to the set's directory: the
  // explorer's page of this exercise, "explore.html#<sheet id>.<n>"); empty for none. The SVG
  // pages do not carry it.
  std::string link;
  template <class T>
  Section& add(T block) {
    blocks.emplace_back(std::move(block));
    return *this;
  }
};

struct PageSize {
  double width_pt = 595.276, height_pt = 841.89;  // A4 by default
  static PageSize a4() { return {595.276, 841.89}; }
  static PageSize letter() { return {612, 792}; }
};

// The words the page furniture prints (header, name fields, yes/no boxes), taken from the
// templates of the sheet's language: no sentence is written in C++. Punctuation belongs to the
// word, since it differs by language ("Name:" / "Nom :").
struct PageWords {
  std::string name = "Name:";
  std::string student_number = "Student number:";
  std::string page = "page";  // "page 1/2"
  std::string yes = "yes";
  std::string no = "no";
};

struct Document {
  std::string title;     // "Ray tracer utilities — worksheet"
  std::string course;    // "Computer graphics, M1"
  std::string sheet_id;  // printed in every page header
  std::string language;  // "en" or "fr": the SVG/PDF language tag
  std::string header_note;  // RichText at the top of the first page, under the name fields
  // The first page's name and student number fields, drawn as writing lines with
  // words.name and words.student_number: set for a student's sheet, left off for a key.
  bool student_fields = false;
  // The most pages the document should take, 0 for no limit: a student's sheet is two sheets of
  // paper printed duplex. The layout meets it, where it can, by setting its tallest figures
  // smaller (layout.h), never by crowding the text.
  int page_budget = 0;
  // Where a page may end inside a section. Wherever it ends, it ends between blocks or between
  // sentences of a paragraph: never inside a sentence or a parenthesis, never right after a
  // heading, never between a figure and the paragraph before it or the fields after it.
  enum class Breaks {
    // Nowhere, unless the section alone is taller than a page: an exercise read on one page, its
    // heading, statement, figure and fields together (a student's sheet).
    whole,
    // Between its paragraphs and blocks too, where the rules above allow (a key, whose worked
    // steps may run on to the next page; its figure and answer table stay with the last steps).
    between_blocks,
  } breaks = Breaks::whole;
  // The scan furniture of a student's sheet: when set, every page carries four corner marks and
  // a QR code of the text page_code(page, pages) gives (a page number and the page count, known
  // only once the document is laid out). What the text means is the caller's business.
  std::function<std::string(int page, int pages)> page_code;
  // Printed between a comb's integer and decimal cells ("," in French).
  std::string decimal_separator = ".";
  // The student number on the first page: a comb of this many cells (a scan reads it), or, when
  // 0, a writing line.
  int student_number_cells = 0;
  // A roster's student, printed on the first page instead of the writing line and the comb.
  std::string student_name, student_number;
  PageWords words;
  PageSize page;
  std::vector<Section> sections;
};

}  // namespace epure::render
