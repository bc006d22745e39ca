#pragma once
// What the sandbox cannot do on this machine (no seccomp, no Landlock, a failed step): epure
// check then refuses to run students' code at all rather than run it unconfined.
#include <stdexcept>

namespace epure::check {

class SandboxError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace epure::check
