#include "check/landlock.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "check/sandbox_error.h"

namespace epure::check {

namespace {

// The system call numbers are the same on every architecture (added after the table was unified).
#ifndef SYS_landlock_create_ruleset
constexpr long SYS_landlock_create_ruleset = 444;
constexpr long SYS_landlock_add_rule = 445;
constexpr long SYS_landlock_restrict_self = 446;
#endif
constexpr std::uint32_t kCreateRulesetVersion = 1U << 0;
constexpr int kRulePathBeneath = 1;

// struct landlock_ruleset_attr as the newest ABI has it; the size passed says which fields the
// kernel reads (Debian 12's header has only the first).
struct RulesetAttr {
  std::uint64_t handled_access_fs;
  std::uint64_t handled_access_net;
  std::uint64_t scoped;
};
struct __attribute__((packed)) PathBeneathAttr {
  std::uint64_t allowed_access;
  std::int32_t parent_fd;
};

// The file-system rights of each ABI: 13 in v1, then REFER (v2), TRUNCATE (v3), IOCTL_DEV (v5).
std::uint64_t fs_rights(int abi) {
  std::uint64_t rights = (1ULL << 13) - 1;
  if (abi >= 2) rights |= 1ULL << 13;
  if (abi >= 3) rights |= 1ULL << 14;
  if (abi >= 5) rights |= 1ULL << 15;
  return rights;
}
// What a rule on a regular file may allow: execute, write, read, truncate, ioctl on devices.
std::uint64_t file_rights(int abi) {
  std::uint64_t rights = landlock_access::execute | landlock_access::write_file | landlock_access::read_file;
  if (abi >= 3) rights |= 1ULL << 14;
  if (abi >= 5) rights |= 1ULL << 15;
  return rights;
}

}  // namespace

int landlock_abi() {
  const long abi = syscall(SYS_landlock_create_ruleset, nullptr, 0, kCreateRulesetVersion);
  return abi < 0 ? 0 : static_cast<int>(abi);
}

LandlockRules::LandlockRules() {
  const int abi = landlock_abi();
  if (abi < 1) throw SandboxError("the kernel has no Landlock (Linux 5.13 or later, with landlock in its lsm= list)");
  handled_fs_ = fs_rights(abi);
  RulesetAttr attr{handled_fs_, 0, 0};
  std::size_t size = sizeof(std::uint64_t);
  if (abi >= 4) {
    attr.handled_access_net = (1ULL << 0) | (1ULL << 1);  // bind and connect TCP
    size = 2 * sizeof(std::uint64_t);
  }
  if (abi >= 6) {
    attr.scoped = (1ULL << 0) | (1ULL << 1);  // abstract unix sockets, signals
    size = sizeof attr;
  }
  const long fd = syscall(SYS_landlock_create_ruleset, &attr, size, 0);
  if (fd < 0) throw SandboxError(fmt::format("Landlock: cannot create a ruleset: {}", std::strerror(errno)));
  fd_ = static_cast<int>(fd);
  fcntl(fd_, F_SETFD, FD_CLOEXEC);
}

LandlockRules::~LandlockRules() {
  if (fd_ >= 0) close(fd_);
}

void LandlockRules::allow(const std::filesystem::path& path, std::uint64_t access) {
  const int target = open(path.c_str(), O_PATH | O_CLOEXEC);
  if (target < 0) throw SandboxError(fmt::format("Landlock: {}: {}", path.string(), std::strerror(errno)));
  struct stat st {};
  const bool directory = fstat(target, &st) == 0 && S_ISDIR(st.st_mode);
  PathBeneathAttr rule{access & (directory ? handled_fs_ : file_rights(landlock_abi())), target};
  const long r = syscall(SYS_landlock_add_rule, fd_, kRulePathBeneath, &rule, 0);
  const int error = errno;
  close(target);
  if (r < 0) throw SandboxError(fmt::format("Landlock: a rule for {}: {}", path.string(), std::strerror(error)));
}

bool landlock_enforce(int ruleset_fd) { return syscall(SYS_landlock_restrict_self, ruleset_fd, 0) == 0; }

}  // namespace epure::check
