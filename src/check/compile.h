#pragma once
// Compiling a submission with gcc, contained: in its own empty directory (the submission and the
// starter's headers copied in, nothing else), as the sandbox user when root, with limits (CPU,
// memory, file size), and under Landlock: gcc and its passes read /usr (and /lib, /etc's
// ld.so.cache) and write that directory only. The student's file is compiled once, all its
// functions together, C11 with warnings on, the course's prototypes forced in
// (-include raytracer.h: a function of the wrong type is a compile error, not a crash), its own
// main() renamed away; then linked statically with the harness, compiled once per run.
//
// Messages: gcc's are read as JSON (-fdiagnostics-format=json) and written again, each with its
// line of the submission; a message about another file (a header) names it and quotes nothing.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "check/sandbox.h"

namespace epure::check {

struct CompileMessage {
  std::string severity;  // "error", "warning", "note"
  int line = 0;          // in the submission; 0 when about another file or the link
  int column = 0;
  std::string text;      // the message alone
  std::string rendered;  // "file.c:12:5: error: …" with the source line and a caret
};

struct CompileResult {
  bool ok = false;
  bool timed_out = false;
  std::filesystem::path program;          // the linked program, when ok
  std::vector<CompileMessage> messages;   // errors and warnings, at most kMaxMessages
};

inline constexpr std::size_t kMaxMessages = 50;

class Toolchain {
 public:
  // Finds gcc, writes the harness and the headers into `work`/harness and compiles the harness
  // there. Throws SandboxError when gcc is missing or cannot be confined, std::runtime_error when
  // the harness does not compile (a broken installation).
  Toolchain(std::filesystem::path work, std::optional<SandboxUser> user);

  // Compiles `source` (shown as `display_name` in messages) in the empty directory `dir`
  // (created; owned by the sandbox user when there is one) and links it with the harness.
  CompileResult build(const std::filesystem::path& dir, std::string_view source, std::string_view display_name) const;

  const std::string& compiler() const { return gcc_; }

 private:
  struct Run {
    bool ok = false;
    bool timed_out = false;
    std::string err;
  };
  Run run_gcc(const std::filesystem::path& dir, std::vector<std::string> args) const;

  std::filesystem::path work_;
  std::filesystem::path harness_dir_;
  std::optional<SandboxUser> user_;
  std::string gcc_;
};

// gcc's JSON diagnostics turned into messages (tests). `source` is the submission's text.
std::vector<CompileMessage> read_diagnostics(std::string_view json_text, std::string_view source,
                                             std::string_view display_name);

}  // namespace epure::check
