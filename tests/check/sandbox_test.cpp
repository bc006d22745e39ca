// The sandbox's primitives on this machine, and its refusal where one is missing (check/sandbox.h).
#include <doctest/doctest.h>

#include <unistd.h>

#include "check/landlock.h"
#include "check/sandbox.h"
#include "check/sandbox_error.h"
#include "check/seccomp_filter.h"

using namespace epure::check;

TEST_CASE("without seccomp, Landlock or an unprivileged user, epure check refuses, saying what is missing") {
  CHECK(sandbox_refusal(true, 3, false, 1000).empty());
  CHECK(sandbox_refusal(true, 1, true, 65534).empty());
  const std::string no_seccomp = sandbox_refusal(false, 3, false, 1000);
  CHECK(no_seccomp.find("refusing to run students' code unconfined") == 0);
  CHECK(no_seccomp.find("seccomp") != std::string::npos);
  const std::string no_landlock = sandbox_refusal(true, 0, false, 1000);
  CHECK(no_landlock.find("Landlock") != std::string::npos);
  CHECK(sandbox_refusal(true, 2, true, 0).find("unprivileged user") != std::string::npos);
  CHECK(sandbox_refusal(false, 0, true, 0).find(" and ") != std::string::npos);
}

TEST_CASE("the harness's filter is built, and names the system calls it reports") {
  const SandboxReport r = probe_sandbox();
  if (!r.refusal.empty()) {
    MESSAGE("no sandbox on this machine: " << r.refusal);
    return;
  }
  const SeccompProgram p = SeccompProgram::harness();
  CHECK(p.instructions() > 20);
  CHECK(std::string(SeccompProgram::name_of(41)).size() > 0);
}

TEST_CASE("a confined child runs with its limits and cannot reach outside") {
  const SandboxReport r = probe_sandbox();
  if (!r.refusal.empty()) return;
  // /bin/sh under Landlock allowed to execute only itself (and read its libraries): it cannot
  // read /etc/hostname, and its exit says so
  LandlockRules rules;
  for (const char* tree : {"/usr", "/lib", "/lib64", "/bin"})
    if (access(tree, F_OK) == 0) rules.allow(tree, landlock_access::read_tree);
  SpawnSpec spec;
  spec.program = "/bin/sh";
  spec.argv = {"sh", "-c", "cat /etc/hostname >/dev/null 2>&1 && exit 3; ulimit -v; exit 0"};
  spec.limits.address_space = 256ULL << 20;
  spec.limits.open_files = 16;
  spec.landlock_ruleset = rules.fd();
  if (r.root) spec.user = r.user;
  const pid_t pid = spawn_confined(spec);
  const ChildExit e = wait_child(pid);
  CHECK(e.exited);
  CHECK(e.status == 0);
}
