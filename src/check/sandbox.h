#pragma once
// Confined child processes: the compiler and the students' programs. A child is started by
// fork, given its limits and its confinement with raw system calls only (the parent has worker
// threads), and then executes its program:
//
//   its own process group (so that killing the group leaves nothing behind), its descriptors
//   (the pipes, nothing else), every signal back to its default, rlimits (CPU, address space,
//   file size, open files, stack, no core), an unprivileged user when epure runs as root
//   (setgroups, setgid, setuid: then no processes at all for a student's program, RLIMIT_NPROC
//   0), PR_SET_NO_NEW_PRIVS, death with its parent, Landlock, and for a student's program the
//   seccomp filter; then execve.
//
// A step that fails is reported through a close-on-exec pipe before the child exits; the parent
// turns it into a SandboxError, and epure check stops rather than run anything unconfined.
#include <sys/resource.h>
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace epure::check {

class SeccompProgram;

struct Limits {
  double cpu_seconds = 10;                      // RLIMIT_CPU (SIGXCPU, then SIGKILL one second later)
  rlim_t address_space = 512ULL << 20;          // RLIMIT_AS
  rlim_t file_size = 0;                         // RLIMIT_FSIZE
  rlim_t open_files = 16;                       // RLIMIT_NOFILE
  rlim_t stack = 16ULL << 20;                   // RLIMIT_STACK
  // RLIMIT_NPROC once the user is dropped (it counts the processes of that user): unset leaves
  // the limit as it is (a compiler forks its passes).
  std::optional<rlim_t> processes;
};

// Who the children run as when epure runs as root: "nobody" (65534 where it has no entry).
struct SandboxUser {
  uid_t uid = 65534;
  gid_t gid = 65534;
  static SandboxUser nobody();
};

struct SpawnSpec {
  std::string program;             // an absolute path
  std::vector<std::string> argv;   // argv[0] included
  std::vector<std::string> env;    // the whole environment ("NAME=value")
  std::string directory = "/";     // the working directory
  // (child descriptor, parent descriptor): dup2'ed in order; every other descriptor is closed
  std::vector<std::pair<int, int>> descriptors;
  Limits limits;
  std::optional<SandboxUser> user;   // set: drop to it (only when running as root)
  int landlock_ruleset = -1;         // LandlockRules::fd(), or -1 for none
  const SeccompProgram* seccomp = nullptr;
};

// Starts the confined child; its process group id is its pid. Throws SandboxError when a step
// of the confinement failed (the child has then exited).
pid_t spawn_confined(const SpawnSpec& spec);

// SIGKILL to the child's whole process group (whatever it started under it dies too).
void kill_group(pid_t pid);

struct ChildExit {
  bool exited = false;  // a normal exit, with `status`
  int status = 0;
  int signal = 0;       // the signal that ended it
  rusage usage{};
};
// Waits for the child (and reaps it). With a deadline: nothing when it is still running then.
ChildExit wait_child(pid_t pid);
std::optional<ChildExit> wait_child_until(pid_t pid, std::chrono::steady_clock::time_point deadline);

// What the sandbox relies on, as found on this machine.
struct SandboxReport {
  bool root = false;
  SandboxUser user;  // the user children run as (when root)
  bool seccomp = false;
  int landlock_abi = 0;
  // Empty when everything is there; otherwise why epure check refuses to run.
  std::string refusal;
};
SandboxReport probe_sandbox();
// Why epure check refuses to run with what was found (empty: it runs).
std::string sandbox_refusal(bool seccomp, int landlock_abi, bool root, uid_t user);

}  // namespace epure::check
