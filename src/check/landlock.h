#pragma once
// Landlock (Linux ≥ 5.13): a process restricts what it, and everything it executes, may do with
// the file system (and, from ABI 4, TCP; from ABI 6, signals to processes outside). epure check
// confines the compiler with it (gcc reads /usr and writes its work directory, nothing else:
// an `.incbin "/etc/passwd"` finds no such file), and the harness on top of seccomp (it may
// execute its own binary and touch nothing else).
//
// glibc 2.36 has no wrappers: the three system calls are made directly. A ruleset is built in
// the parent (it is only a file descriptor), and the child enforces it between fork and exec
// with one system call, after PR_SET_NO_NEW_PRIVS.
#include <cstdint>
#include <filesystem>

namespace epure::check {

// The Landlock ABI version the kernel offers; 0 when it has none (not built in, or not in the
// kernel's `lsm=` list).
int landlock_abi();

// Access rights, as the kernel names them (linux/landlock.h).
namespace landlock_access {
inline constexpr std::uint64_t execute = 1ULL << 0;
inline constexpr std::uint64_t write_file = 1ULL << 1;
inline constexpr std::uint64_t read_file = 1ULL << 2;
inline constexpr std::uint64_t read_dir = 1ULL << 3;
// What a directory's reader needs: list it, read and execute its files.
inline constexpr std::uint64_t read_tree = execute | read_file | read_dir;
}  // namespace landlock_access

class LandlockRules {
 public:
  // Handles every file-system right the kernel knows (what no rule allows is denied) and, where
  // the ABI has them, TCP bind/connect and signals or abstract sockets beyond the domain.
  // Throws SandboxError when the kernel has no Landlock.
  LandlockRules();
  ~LandlockRules();
  LandlockRules(const LandlockRules&) = delete;
  LandlockRules& operator=(const LandlockRules&) = delete;

  // Allows `access` beneath `path` (a directory: its whole tree; a file: that file, whose rights
  // are then limited to the file ones). Throws SandboxError naming the path.
  void allow(const std::filesystem::path& path, std::uint64_t access);
  // Every right the ruleset handles, for a work directory.
  std::uint64_t everything() const { return handled_fs_; }

  int fd() const { return fd_; }

 private:
  int fd_ = -1;
  std::uint64_t handled_fs_ = 0;
};

// In the child, between fork and exec: enforces the ruleset. Async-signal-safe (one system call);
// returns false (errno set) on failure.
bool landlock_enforce(int ruleset_fd);

}  // namespace epure::check
