#pragma once
// The seccomp filter a student's program runs under: an allow-list of the system calls the
// harness and a C function computing geometry need (read the cases on fd 0, write on fds 1–3,
// memory for malloc, signals for its own handlers, a static binary's start-up, exit). Anything
// else raises SIGSYS (SECCOMP_RET_TRAP), which the harness turns into a record naming the call;
// a call from a foreign architecture's table kills the process.
//
// Built once with libseccomp (Debian's libseccomp-dev: the syscall tables per architecture, the
// argument comparisons and the architecture check written and tested by others), exported as
// BPF, and installed in each child between fork and exec with one system call: the filter then
// holds from the harness's first instruction, before any code of the student's runs.
#include <linux/filter.h>

#include <vector>

namespace epure::check {

class SeccompProgram {
 public:
  // Throws SandboxError when libseccomp cannot build it.
  static SeccompProgram harness();

  // The system call's name for a number of this architecture, for messages ("openat").
  static const char* name_of(long syscall_number);

  // In the child, between fork and exec, after PR_SET_NO_NEW_PRIVS: installs the filter.
  // Async-signal-safe; returns false (errno set) on failure.
  bool install() const;

  std::size_t instructions() const { return code_.size(); }

 private:
  std::vector<sock_filter> code_;
  sock_fprog program_{};
};

// Whether this kernel applies seccomp filters (a probe child installs one).
bool seccomp_available();

}  // namespace epure::check
