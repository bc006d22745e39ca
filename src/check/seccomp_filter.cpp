#include "check/seccomp_filter.h"

#include <linux/seccomp.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>

#include <fmt/format.h>

#include "check/sandbox_error.h"

namespace epure::check {

namespace {

struct ContextDeleter {
  void operator()(void* ctx) const { seccomp_release(ctx); }
};

// Adds a rule for a system call this architecture has (a name it lacks, such as arch_prctl on
// arm64, is skipped: nothing can call it).
template <class... Args>
void add(scmp_filter_ctx ctx, std::uint32_t action, const char* name, unsigned count, Args... args) {
  const int nr = seccomp_syscall_resolve_name(name);
  if (nr == __NR_SCMP_ERROR) return;
  const int r = seccomp_rule_add(ctx, action, nr, count, args...);
  if (r < 0) throw SandboxError(fmt::format("seccomp: a rule for {}: {}", name, std::strerror(-r)));
}

}  // namespace

SeccompProgram SeccompProgram::harness() {
  std::unique_ptr<void, ContextDeleter> owner(seccomp_init(SCMP_ACT_TRAP));
  if (!owner) throw SandboxError("seccomp: libseccomp cannot start a filter");
  scmp_filter_ctx ctx = owner.get();
  // the child sets PR_SET_NO_NEW_PRIVS itself; a call of a foreign architecture's table is killed
  seccomp_attr_set(ctx, SCMP_FLTATR_CTL_NNP, 0);
  seccomp_attr_set(ctx, SCMP_FLTATR_ACT_BADARCH, SCMP_ACT_KILL_PROCESS);

  // the cases in, the results and the student's output out: those descriptors only
  add(ctx, SCMP_ACT_ALLOW, "read", 1, SCMP_A0(SCMP_CMP_EQ, 0));
  for (int fd : {1, 2, 3}) add(ctx, SCMP_ACT_ALLOW, "write", 1, SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(fd)));
  for (int fd : {1, 2}) add(ctx, SCMP_ACT_ALLOW, "writev", 1, SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(fd)));
  // the end, memory (malloc), the harness's own signal handlers, the clock, a static binary's
  // start-up (thread pointer, robust list, rseq, the stack's limit read, malloc's random key)
  for (const char* name :
       {"exit", "exit_group", "brk", "mmap", "munmap", "mremap", "mprotect", "madvise", "rt_sigaction",
        "rt_sigprocmask", "rt_sigreturn", "sigaltstack", "getpid", "getppid", "gettid", "clock_gettime", "clock_getres",
        "gettimeofday", "time", "futex", "getrandom", "arch_prctl", "set_tid_address", "set_robust_list", "rseq",
        // the filter is installed before the harness is executed: this execve is the sandbox's
        // own; a later one can only run files Landlock allows, which is the harness alone
        "execve"})
    add(ctx, SCMP_ACT_ALLOW, name, 0);
  add(ctx, SCMP_ACT_ALLOW, "prlimit64", 1, SCMP_A2(SCMP_CMP_EQ, 0));  // read a limit, never set one
  // What stdio and the C library's start-up ask about their files: refused quietly, so that a
  // printf left in a function still prints (glibc then buffers by default).
  for (const char* name : {"newfstatat", "fstat", "statx", "ioctl", "readlink", "readlinkat", "lseek"})
    add(ctx, SCMP_ACT_ERRNO(EPERM), name, 0);

  const int fd = memfd_create("epure-seccomp", MFD_CLOEXEC);
  if (fd < 0) throw SandboxError(fmt::format("seccomp: memfd_create: {}", std::strerror(errno)));
  const int r = seccomp_export_bpf(ctx, fd);
  SeccompProgram program;
  if (r == 0) {
    const off_t size = lseek(fd, 0, SEEK_END);
    program.code_.resize(static_cast<std::size_t>(size) / sizeof(sock_filter));
    if (pread(fd, program.code_.data(), program.code_.size() * sizeof(sock_filter), 0) != size) program.code_.clear();
  }
  close(fd);
  if (r < 0 || program.code_.empty()) throw SandboxError("seccomp: libseccomp cannot export the filter");
  program.program_.len = static_cast<unsigned short>(program.code_.size());
  program.program_.filter = program.code_.data();
  return program;
}

const char* SeccompProgram::name_of(long syscall_number) {
  // libseccomp allocates the name; keep one per number asked (few distinct ones per run)
  thread_local std::string name;
  char* n = seccomp_syscall_resolve_num_arch(SCMP_ARCH_NATIVE, static_cast<int>(syscall_number));
  name = n ? n : fmt::format("system call {}", syscall_number);
  std::free(n);
  return name.c_str();
}

bool SeccompProgram::install() const {
  return syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &program_) == 0;
}

bool seccomp_available() {
  if (prctl(PR_GET_SECCOMP, 0, 0, 0, 0) < 0) return false;
  // a filter that allows everything, installed in a child that then exits
  sock_filter allow = BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW);
  sock_fprog program{1, &allow};
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const bool ok = prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 &&
                    syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &program) == 0;
    _exit(ok ? 0 : 1);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace epure::check
