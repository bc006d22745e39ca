// The scan a submission passes before gcc sees it (check/submission.h).
#include <doctest/doctest.h>

#include "check/submission.h"

using namespace epure::check;

namespace {
std::string refusal_code(std::string_view source) {
  const SubmissionScan s = scan_submission(source);
  return s.refusal ? s.refusal->code : "";
}
}  // namespace

TEST_CASE("the starter's headers and the C standard headers may be included, by name") {
  const SubmissionScan s = scan_submission(
      "#include \"raytracer.h\"\n#include <math.h>\n  #  include <stdio.h> /* why */\n%:include <stdbool.h>\n#include <g2x.h>\n");
  CHECK_FALSE(s.refusal);
  CHECK(s.includes == std::vector<std::string>{"raytracer.h", "math.h", "stdio.h", "stdbool.h", "g2x.h"});
  CHECK(allowed_header("threads.h"));
  CHECK_FALSE(allowed_header("unistd.h"));
  CHECK_FALSE(allowed_header("./g2x.h"));
}

TEST_CASE("an include of anything else is refused, however it is spelt") {
  CHECK(refusal_code("#include \"/etc/passwd\"\n") == "include");
  CHECK(refusal_code("#include <unistd.h>\n") == "include");
  CHECK(refusal_code("#include \"../g2x.h\"\n") == "include");
  CHECK(refusal_code("#define F \"/etc/passwd\"\n#include F\n") == "include");
  CHECK(refusal_code("??=include \"/etc/passwd\"\n") == "include");           // a trigraph for #
  CHECK(refusal_code("%:include </etc/passwd>\n") == "include");              // a digraph for #
  CHECK(refusal_code("#inc\\\nlude </etc/passwd>\n") == "include");           // a line splice
  CHECK(refusal_code("# /* a comment */ include </etc/passwd>\n") == "include");
  CHECK(refusal_code("#include \"unterminated\n") == "include");
  // conservative: a directive in a block the preprocessor would skip is refused all the same
  CHECK(refusal_code("#if 0\n#include <unistd.h>\n#endif\n") == "include");
  const SubmissionScan s = scan_submission("int a;\n\n#include <sys/socket.h>\n");
  REQUIRE(s.refusal);
  CHECK(s.refusal->line == 3);
  CHECK(s.refusal->detail == "sys/socket.h");
}

TEST_CASE("directives and operators that reach other files are refused") {
  CHECK(refusal_code("#include_next <stdio.h>\n") == "directive");
  CHECK(refusal_code("#import \"raytracer.h\"\n") == "directive");
  CHECK(refusal_code("#embed \"/etc/passwd\"\n") == "directive");
  CHECK(refusal_code("#line 1 \"/etc/passwd\"\n") == "directive");
  CHECK(refusal_code("# 1 \"/etc/passwd\"\n") == "directive");
  CHECK(refusal_code("#pragma GCC dependency \"/etc/passwd\"\n") == "pragma");
  CHECK(refusal_code("#pragma GCC poison x\n") == "pragma");
  CHECK(refusal_code("_Pragma(\"GCC dependency \\\"/etc/passwd\\\"\")\n") == "identifier");
  CHECK(refusal_code("#if __has_include(\"/etc/passwd\")\n#endif\n") == "identifier");
  CHECK(refusal_code("__asm__(\".incbin \\\"/etc/passwd\\\"\");\n") == "identifier");
  CHECK(refusal_code("void f(void) { asm(\"nop\"); }\n") == "identifier");
  // allowed: once, diagnostics, STDC; a # inside a line; words in comments and strings
  CHECK(refusal_code("#pragma once\n#pragma GCC diagnostic ignored \"-Wunused\"\n#pragma STDC FP_CONTRACT OFF\n") == "");
  CHECK(refusal_code("int x = 1; # define Y 2\n") == "");
  CHECK(refusal_code("/* #include </etc/passwd> */\n// __asm__\nconst char* s = \"#include <unistd.h> asm\";\n") == "");
  CHECK(refusal_code("#define STR(x) #x\n#define CAT(a, b) a##b\n#ifdef X\n#elif 1\n#else\n#endif\n#error stop\n") == "");
}

TEST_CASE("size, NUL bytes, and the course's functions a file mentions") {
  CHECK(refusal_code(std::string(kMaxSubmissionBytes + 1, ' ')) == "size");
  CHECK(refusal_code(std::string("int a;\n\0", 8)) == "nul");
  const SubmissionScan s = scan_submission(
      "#include <unistd.h>\nbool InterSegments(G2Xpoint A, G2Xpoint B, G2Xpoint C, G2Xpoint D, G2Xpoint* I);\n"
      "/* Projection in a comment does not count */\nG2Xpoint Projection(G2Xpoint A, G2Xpoint B, G2Xpoint C);\n");
  CHECK(s.refusal);  // refused, and still the functions it holds are known (for the report)
  CHECK(s.mentioned == std::vector<Fn>{Fn::segments, Fn::projection});
}

TEST_CASE("comments, after the translation phases, with their lines") {
  const auto comments = comments_of("int a; // one\n/* two\n   lines */\n// spliced \\\ncomment\n");
  REQUIRE(comments.size() == 3);
  CHECK(comments[0].line == 1);
  CHECK(comments[0].text == " one");
  CHECK(comments[1].line == 2);
  CHECK(comments[2].text == " spliced comment");
}
