#pragma once
// Runs a student's compiled program on its cases: one confined child (sandbox.h) for all the
// cases of all the functions the file defines, fed in batches through its pipes; a function
// that crashes, hangs, prints without end or tries what the sandbox forbids ends that child
// (its whole process group is killed, and reaped), and a fresh one takes the next function. So
// every function gets its own verdict, and nothing the student's code started outlives the run.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "check/functions.h"
#include "check/sandbox.h"
#include "exercises/texts.h"

namespace epure::check {

class SeccompProgram;

struct RunConfig {
  std::optional<SandboxUser> user;        // when root: who the child runs as
  const SeccompProgram* seccomp = nullptr;  // required
  Limits limits;                          // the child's rlimits (processes set to 0 here)
  // Wall-clock time for one function's cases (and for the start-up before them).
  std::chrono::milliseconds function_time{2000};
  std::size_t output_cap = 1 << 20;       // bytes of the student's own output before it is stopped
  std::size_t output_kept = 2048;         // bytes of it kept for the report
};

// How a function's run ended.
enum class RunEnd {
  completed,    // every case answered
  not_written,  // its body is still TO_WRITE(...)
  crashed,      // a fatal signal, abort(), exit(), or the process ending on its own
  timeout,      // past its time (wall clock), or past the CPU limit
  refused,      // a system call the sandbox forbids, output without end, bytes on the results' pipe
};

struct FunctionRun {
  Fn fn;
  std::vector<std::optional<Outcome>> outcomes;  // per case; nothing for a case not answered
  RunEnd end = RunEnd::completed;
  // why it ended, for crashed / timeout / refused: a short code ("SIGSEGV", "stack_overflow",
  // "abort", "exit", "openat", "output", …) and the sentence's key (check.reason.<key> in the
  // texts) with its values
  std::string reason_code;
  std::string reason_key;
  TextVars reason_vars;
  std::optional<std::size_t> stopped_at;  // the case being run when it ended
  std::string output;        // the first bytes it printed
  std::size_t output_bytes = 0;
};

struct FileRun {
  std::uint32_t defined = 0;  // bit i: function i is defined (from the harness's hello)
  // When the program did not even start (a constructor that crashed, looped, or tried a
  // forbidden call): why, and no function ran.
  std::optional<FunctionRun> startup;
  std::vector<FunctionRun> functions;
};

// Runs `program` on cases[fn] for every function it defines (cases indexed by Fn). Throws
// SandboxError when the child cannot be confined.
FileRun run_program(const std::filesystem::path& program, const std::vector<std::vector<Case>>& cases,
                    const RunConfig& config);

}  // namespace epure::check
