#pragma once
// A key's section (worked steps, answers) as the HTML the explorer's page shows beside the
// figure: headings, paragraphs and answer lines, with the templates' label markup (t_{ab},
// r^{2}, \vec{AB}) as <sub>, <sup> and a vector's arrow; the figure's place marked for the page.
#include <string>

#include "render/document.h"

namespace epure::explore {

struct KeyView {
  std::string steps;                // the HTML
  render::Scene* figure = nullptr;  // the section's first figure (in the section)
};

KeyView key_view(render::Section& key);

}  // namespace epure::explore
