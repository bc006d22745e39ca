#pragma once
// Text escaped for XML and HTML, the one home of it: the SVG writer's strict escaping (a document
// that always parses), and the plain one of the four specials that every other writer of markup
// uses (the set's index page, the platform exports, the explorer's key).
#include <string>
#include <string_view>

namespace epure::render {

// Appends `s` escaped for XML: & < > always, " in attribute values, and tab, newline and carriage
// return as character references in attribute values (so they survive attribute normalisation).
// Characters XML 1.0 forbids (other C0 controls, U+FFFE, U+FFFF) are dropped and invalid UTF-8
// becomes U+FFFD, so the output always parses.
void append_escaped(std::string& out, std::string_view s, bool attribute);

// Appends `s` with & < > " as entities and every other byte as it is: text and attribute values
// of HTML and XML made of our own texts (valid UTF-8 by construction).
void append_markup_escaped(std::string& out, std::string_view s);
std::string markup_escaped(std::string_view s);

}  // namespace epure::render
