#pragma once
// layout.json's sheets from the pages the PDF is drawn from: every page's corner marks and code,
// every comb cell and tick box (render's PlacedBox, with its question id and what it stands
// for), gathered into the fields a scan reads. render knows nothing of scans nor of exercises;
// scan's layout format knows nothing of pages laid out: this is where the two meet.
#include <string>
#include <vector>

#include "render/layout.h"
#include "scan/layout_file.h"

namespace epure::output {

// One sheet's pages as a scan reads them. A field's question is its boxes' question id, with a
// point's coordinate after it ("3.P.x"); the student number's comb is `student_number`.
// Throws std::logic_error for a page without scan furniture (no marks or no code).
scan::SheetLayout sheet_layout(const std::string& sheet_id, const std::vector<render::LaidOutPage>& pages);

}  // namespace epure::output
