#include "cli/man_page.h"

#include <doctest/doctest.h>

namespace {

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("roff_escape: what roff would misread") {
  using epure::cli::roff_escape;
  SUBCASE("1. a backslash is printed, not an escape") { CHECK(roff_escape("a\\b") == "a\\eb"); }
  SUBCASE("2. option dashes are minus signs; a word's hyphen stays") {
    CHECK(roff_escape("use --key or -k") == "use \\-\\-key or \\-k");
    CHECK(roff_escape("double-sided") == "double-sided");
    CHECK(roff_escape("(--spec)") == "(\\-\\-spec)");
  }
  SUBCASE("3. a line starting with a period or a quote is text, not a request") {
    CHECK(roff_escape(".hidden") == "\\&.hidden");
    CHECK(roff_escape("a\n'b") == "a\n\\&'b");
    CHECK(roff_escape("a.b") == "a.b");
  }
  SUBCASE("4. characters outside ASCII as groff's \\[uXXXX]") {
    CHECK(roff_escape("ℝ, x²") == "\\[u211D], x\\[u00B2]");
    CHECK(roff_escape("miss, … 3×4 – a") == "miss, ... 3\\(mu4 \\(en a");  // named: rendered in ASCII too
    CHECK(roff_escape("ℝ³") == "\\[u211D]\\[u00B3]");
    CHECK(roff_escape("\xff") == "\\[uFFFD]");  // malformed UTF-8
  }
}

TEST_CASE("man_pages: a page per command, every option with its value, default and limits") {
  CLI::App app{"a sample tool", "tool"};
  int sheets = 30;
  std::string lang, kind, key;
  bool quiet = false;
  auto* gen = app.add_subcommand("generate", "Write a set");
  gen->add_option("--sheets,-n", sheets, "Number of sheets")->check(CLI::Range(1, 99))->capture_default_str();
  gen->add_option("--lang", lang, "Language")->check(CLI::IsMember({"en", "fr"}));
  gen->add_flag("--quiet,-q", quiet, "No summary");
  gen->add_option("--key", key, "Key")->envname("TOOL_KEY");
  auto* preview = app.add_subcommand("preview", "Draw a kind");
  preview->add_option("kind", kind, "Kind")->required()->check(CLI::IsMember({"dot", "cross"}));
  auto* exp = app.add_subcommand("export", "Export");
  exp->require_subcommand(1);
  exp->add_subcommand("qti", "QTI package")->add_option("--key", key, "Key")->required();

  const auto pages = epure::cli::man_pages(epure::cli::describe_commands(app), "9.8.7", 4);
  REQUIRE(pages.size() == 5);
  CHECK(pages[0].name == "tool");
  CHECK(pages[1].name == "tool-generate");
  CHECK(pages[4].name == "tool-export-qti");
  for (const auto& p : pages) {
    CAPTURE(p.name);
    CHECK(contains(p.roff, "\n.TH "));
    CHECK(contains(p.roff, "\"epure 9.8.7\""));
    CHECK(contains(p.roff, "\n.SH NAME\n"));
    CHECK(contains(p.roff, "\n.SH SYNOPSIS\n"));
  }
  const std::string& root = pages[0].roff;
  CHECK(contains(root, "draw version 4"));
  CHECK(contains(root, ".SH COMMANDS"));
  CHECK(contains(root, "\\fBtool\\-export\\-qti\\fR(1)"));  // SEE ALSO names every page
  CHECK(contains(root, ".SH EXIT STATUS"));

  const std::string& g = pages[1].roff;
  CHECK(contains(g, ".TH TOOL\\-GENERATE 1"));
  CHECK(contains(g, "tool\\-generate \\- Write a set"));
  CHECK(contains(g, "\\fB\\-n\\fR, \\fB\\-\\-sheets\\fR \\fISHEETS\\fR\nNumber of sheets.\nFrom 1 to 99.\nDefault: \\fB30\\fR.\n"));
  CHECK(contains(g, "\\fB\\-\\-lang\\fR \\fILANG\\fR\nLanguage.\nOne of: \\fBen\\fR, \\fBfr\\fR.\n"));
  CHECK(contains(g, "\\fB\\-q\\fR, \\fB\\-\\-quiet\\fR\nNo summary.\n"));
  CHECK(contains(g, "\\fB\\-\\-key\\fR \\fIKEY\\fR\nKey.\nAlso read from \\fBTOOL_KEY\\fR.\n"));

  const std::string& p = pages[2].roff;
  CHECK(contains(p, ".SH ARGUMENTS\n.TP\n\\fIKIND\\fR\nKind.\nOne of: \\fBdot\\fR, \\fBcross\\fR.\nRequired.\n"));
  CHECK(contains(p, ".B tool preview\n[\\fIOPTIONS\\fR]\n\\fIKIND\\fR\n"));

  CHECK(contains(pages[3].roff, "\\fICOMMAND\\fR [\\fIARGS\\fR]"));
  CHECK(contains(pages[4].roff, ".B tool export qti\n\\fB\\-\\-key\\fR \\fIKEY\\fR\n[\\fIOPTIONS\\fR]\n"));
  CHECK(contains(pages[4].roff, "\\fBtool\\-export\\fR(1)"));  // its parent's page
}

TEST_CASE("man_pages: names that do not break, choices told from their commas, the root's own name once") {
  CLI::App app{"tool: a sample tool", "tool"};
  std::string delimiter;
  bool a = false, b = false;
  auto* grade = app.add_subcommand("grade", "Grade");
  grade->add_option("--delimiter", delimiter, "Delimiter")->check(CLI::IsMember({",", ";", "tab"}));
  auto* on = grade->add_flag("--follow-through", a, "Credit; see --no-follow-through");
  auto* off = grade->add_flag("--no-follow-through", b, "Do not");
  on->excludes(off);
  const auto pages = epure::cli::man_pages(epure::cli::describe_commands(app), "1.0", 1);
  REQUIRE(pages.size() == 2);
  CHECK(contains(pages[0].roff, ".SH NAME\ntool \\- a sample tool\n"));
  const std::string& g = pages[1].roff;
  CHECK(contains(g, "One of: \\(oq\\fB,\\fR\\(cq, \\(oq\\fB;\\fR\\(cq, \\fBtab\\fR.\n"));
  CHECK(contains(g, "\\fB\\-\\-follow\\-through\\fR\n"));
  CHECK(contains(g, "Not with \\fB\\-\\-no\\-follow\\-through\\fR.\n"));
  CHECK(contains(g, "Credit; see \\-\\-no\\-follow\\-through.\n"));  // in prose too
}
