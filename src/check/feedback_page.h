#pragma once
// A student's feedback page, DIR/feedback/<file>.html and .pdf: each function's verdict and
// cases passed, the classic bug named with its sentence, why it stopped (a crash, a loop, a
// forbidden call), and its failing cases drawn on the exercise's construction figure: the key's
// figure for that case, drawn by the kind's own key scene (ExerciseKind::key_of, as the sheets'
// keys and the explorer draw it), with the student's point and normal added beside the right
// ones. The HTML holds its figures as inline SVG; the PDF is laid out and drawn like the sheets.
#include <filesystem>
#include <optional>
#include <string>

#include "check/check.h"
#include "render/document.h"

namespace epure::check {

// The construction figure of a failing case, the student's answer drawn on it; nothing (and why
// in `why_not`) when the case cannot be drawn (a figure at 1e-18 or 1e18).
std::optional<render::Scene> case_figure(Fn fn, const FailedCase& c, const std::string& language, std::string& why_not);

render::Document feedback_document(const FileReport& file, const CheckOptions& options);
std::string feedback_html(const FileReport& file, const CheckOptions& options);

// Every file's page, `options.jobs` at a time.
void write_feedback_pages(const CheckResult& result, const CheckOptions& options, const std::filesystem::path& dir);

}  // namespace epure::check
