#include "check/sandbox.h"

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <thread>

#include <fmt/format.h>

#include "check/landlock.h"
#include "check/sandbox_error.h"
#include "check/seccomp_filter.h"

namespace epure::check {

namespace {

// The steps of the child's set-up, as reported when one fails.
enum Step : int {
  step_group = 1,
  step_descriptors,
  step_signals,
  step_directory,
  step_limits,
  step_user,
  step_no_new_privs,
  step_landlock,
  step_seccomp,
  step_exec,
};

const char* step_name(int step) {
  switch (step) {
    case step_group: return "a process group of its own";
    case step_descriptors: return "its descriptors";
    case step_signals: return "its signals";
    case step_directory: return "its working directory";
    case step_limits: return "its resource limits";
    case step_user: return "the unprivileged user";
    case step_no_new_privs: return "PR_SET_NO_NEW_PRIVS";
    case step_landlock: return "Landlock";
    case step_seccomp: return "the seccomp filter";
    case step_exec: return "executing the program";
  }
  return "?";
}

struct Failure {
  int step;
  int error;
};

// Only raw system calls from here to execve: the parent has other threads, whose locks a forked
// child must not need.
[[noreturn]] void fail(int report_fd, int step) {
  const Failure f{step, errno};
  (void)!write(report_fd, &f, sizeof f);
  _exit(127);
}

bool set_limit(int resource, rlim_t value) {
  const rlimit r{value, value};
  return setrlimit(resource, &r) == 0;
}

[[noreturn]] void child(const SpawnSpec& spec, char* const* argv, char* const* envp, int report_fd) {
  if (setpgid(0, 0) != 0) fail(report_fd, step_group);
  // descriptors: the wanted ones first out of the way of their targets, then in place
  int top = 64;
  for (const auto& [target, source] : spec.descriptors) {
    (void)target;
    if (source == report_fd) fail(report_fd, step_descriptors);
    top = std::max(top, source + 1);
  }
  int sources[16];
  const std::size_t n = std::min<std::size_t>(spec.descriptors.size(), 16);
  for (std::size_t i = 0; i < n; ++i) {
    sources[i] = fcntl(spec.descriptors[i].second, F_DUPFD, top);
    if (sources[i] < 0) fail(report_fd, step_descriptors);
  }
  const int report = fcntl(report_fd, F_DUPFD_CLOEXEC, top + 16);
  if (report < 0) fail(report_fd, step_descriptors);
  report_fd = report;
  // the Landlock ruleset above it (the rest is closed around the two)
  int ruleset = -1;
  if (spec.landlock_ruleset >= 0) {
    ruleset = fcntl(spec.landlock_ruleset, F_DUPFD_CLOEXEC, report_fd + 1);
    if (ruleset < 0) fail(report_fd, step_descriptors);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (dup2(sources[i], spec.descriptors[i].first) < 0) fail(report_fd, step_descriptors);
  int first_free = 0;
  for (std::size_t i = 0; i < n; ++i) first_free = std::max(first_free, spec.descriptors[i].first + 1);
  // close everything past the wanted descriptors but the report pipe and the ruleset
  if (syscall(SYS_close_range, first_free, report_fd - 1, 0) != 0) fail(report_fd, step_descriptors);
  if (ruleset > report_fd + 1 && syscall(SYS_close_range, report_fd + 1, ruleset - 1, 0) != 0)
    fail(report_fd, step_descriptors);
  if (syscall(SYS_close_range, std::max(report_fd, ruleset) + 1, ~0U, 0) != 0) fail(report_fd, step_descriptors);

  // every signal to its default, none blocked (the parent ignores SIGPIPE, its threads block some)
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int s = 1; s < NSIG; ++s)
    if (s != SIGKILL && s != SIGSTOP) sigaction(s, &dfl, nullptr);
  sigset_t none;
  sigemptyset(&none);
  if (sigprocmask(SIG_SETMASK, &none, nullptr) != 0) fail(report_fd, step_signals);

  if (chdir(spec.directory.c_str()) != 0) fail(report_fd, step_directory);

  const Limits& l = spec.limits;
  const auto cpu = static_cast<rlim_t>(l.cpu_seconds + 0.999);
  const rlimit cpu_limit{cpu, cpu + 1};
  if (setrlimit(RLIMIT_CPU, &cpu_limit) != 0 || !set_limit(RLIMIT_AS, l.address_space) ||
      !set_limit(RLIMIT_FSIZE, l.file_size) || !set_limit(RLIMIT_NOFILE, l.open_files) ||
      !set_limit(RLIMIT_STACK, l.stack) || !set_limit(RLIMIT_CORE, 0) || !set_limit(RLIMIT_MEMLOCK, 0) ||
      !set_limit(RLIMIT_MSGQUEUE, 0))
    fail(report_fd, step_limits);

  if (spec.user) {
    if (setgroups(0, nullptr) != 0 || setgid(spec.user->gid) != 0 || setuid(spec.user->uid) != 0)
      fail(report_fd, step_user);
    // back to root must be impossible
    if (setuid(0) == 0) fail(report_fd, step_user);
  }
  // after the user change: RLIMIT_NPROC counts that user's processes (0: fork fails, whatever
  // the count), and the change of credentials would have cleared the parent-death signal
  if (l.processes && !set_limit(RLIMIT_NPROC, *l.processes)) fail(report_fd, step_limits);
  if (prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0) != 0) fail(report_fd, step_signals);
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) fail(report_fd, step_no_new_privs);
  if (ruleset >= 0) {
    if (!landlock_enforce(ruleset)) fail(report_fd, step_landlock);
    close(ruleset);
  }
  if (spec.seccomp && !spec.seccomp->install()) fail(report_fd, step_seccomp);
  execve(spec.program.c_str(), argv, envp);
  fail(report_fd, step_exec);
}

std::vector<char*> c_strings(const std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (const auto& s : strings) out.push_back(const_cast<char*>(s.c_str()));
  out.push_back(nullptr);
  return out;
}

}  // namespace

SandboxUser SandboxUser::nobody() {
  SandboxUser user;
  passwd pw{};
  passwd* found = nullptr;
  char buffer[4096];
  if (getpwnam_r("nobody", &pw, buffer, sizeof buffer, &found) == 0 && found) {
    user.uid = found->pw_uid;
    user.gid = found->pw_gid;
  }
  return user;
}

pid_t spawn_confined(const SpawnSpec& spec) {
  if (spec.descriptors.size() > 16) throw SandboxError("spawn: more than 16 descriptors");
  const std::vector<char*> argv = c_strings(spec.argv), envp = c_strings(spec.env);
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) throw SandboxError(fmt::format("spawn: pipe: {}", std::strerror(errno)));
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    close(report[0]);
    close(report[1]);
    throw SandboxError(fmt::format("spawn: fork: {}", std::strerror(error)));
  }
  if (pid == 0) {
    close(report[0]);
    child(spec, argv.data(), envp.data(), report[1]);
  }
  close(report[1]);
  setpgid(pid, pid);  // also here: no race with a kill_group before the child's own call
  Failure f{};
  ssize_t got;
  while ((got = read(report[0], &f, sizeof f)) < 0 && errno == EINTR) {
  }
  close(report[0]);
  if (got == static_cast<ssize_t>(sizeof f)) {
    wait_child(pid);
    throw SandboxError(
        fmt::format("could not confine {}: {}: {}", spec.program, step_name(f.step), std::strerror(f.error)));
  }
  return pid;
}

void kill_group(pid_t pid) {
  if (pid > 0) kill(-pid, SIGKILL);
}

ChildExit wait_child(pid_t pid) {
  ChildExit out;
  int status = 0;
  while (wait4(pid, &status, 0, &out.usage) < 0)
    if (errno != EINTR) return out;
  out.exited = WIFEXITED(status);
  out.status = out.exited ? WEXITSTATUS(status) : 0;
  out.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return out;
}

std::optional<ChildExit> wait_child_until(pid_t pid, std::chrono::steady_clock::time_point deadline) {
  for (auto pause = std::chrono::microseconds(50);; pause = std::min(pause * 2, std::chrono::microseconds(5000))) {
    ChildExit out;
    int status = 0;
    const pid_t r = wait4(pid, &status, WNOHANG, &out.usage);
    if (r == pid) {
      out.exited = WIFEXITED(status);
      out.status = out.exited ? WEXITSTATUS(status) : 0;
      out.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      return out;
    }
    if (r < 0 && errno != EINTR) return ChildExit{};
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(pause);
  }
}

std::string sandbox_refusal(bool seccomp, int landlock, bool root, uid_t user) {
  std::vector<std::string> missing;
  if (!seccomp) missing.push_back("seccomp filters (CONFIG_SECCOMP_FILTER)");
  if (landlock < 1) missing.push_back("Landlock (Linux 5.13 or later, with landlock in the kernel's lsm= list)");
  if (root && user == 0) missing.push_back("an unprivileged user to run as (nobody is uid 0?)");
  if (missing.empty()) return {};
  std::string refusal = "refusing to run students' code unconfined: this machine lacks ";
  for (std::size_t i = 0; i < missing.size(); ++i) refusal += (i ? " and " : "") + missing[i];
  return refusal;
}

SandboxReport probe_sandbox() {
  SandboxReport r;
  r.root = geteuid() == 0;
  r.user = SandboxUser::nobody();
  r.seccomp = seccomp_available();
  r.landlock_abi = landlock_abi();
  r.refusal = sandbox_refusal(r.seccomp, r.landlock_abi, r.root, r.user.uid);
  return r;
}

}  // namespace epure::check
