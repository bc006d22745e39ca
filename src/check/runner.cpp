#include "check/runner.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "check/landlock.h"
#include "check/protocol.h"
#include "check/sandbox_error.h"
#include "check/seccomp_filter.h"

namespace epure::check {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kBatch = 256;  // cases written at once: 22.5 KB, within a pipe's 64 KB

struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw SandboxError(fmt::format("pipe: {}", std::strerror(errno)));
    read = fds[0], write = fds[1];
  }
  ~Pipe() {
    if (read >= 0) close(read);
    if (write >= 0) close(write);
  }
  void close_read() {
    if (read >= 0) close(read);
    read = -1;
  }
  void close_write() {
    if (write >= 0) close(write);
    write = -1;
  }
};

// What kind of thing a forbidden system call does (check.call.<kind> in the texts).
std::string call_kind(const std::string& name) {
  static const std::pair<const char*, const char*> kinds[] = {
      {"open", "file"},        {"openat", "file"},        {"openat2", "file"},     {"creat", "file"},
      {"unlink", "file"},      {"unlinkat", "file"},      {"rename", "file"},      {"mkdir", "file"},
      {"mkdirat", "file"},     {"chdir", "file"},         {"socket", "network"},   {"connect", "network"},
      {"bind", "network"},     {"sendto", "network"},     {"clone", "process"},    {"clone3", "process"},
      {"fork", "process"},     {"vfork", "process"},      {"kill", "signal"},      {"tgkill", "signal"},
      {"tkill", "signal"},     {"nanosleep", "sleep"},    {"clock_nanosleep", "sleep"}, {"ptrace", "trace"},
      {"prlimit64", "limits"}, {"setrlimit", "limits"},   {"pipe", "pipe"},        {"pipe2", "pipe"},
  };
  for (const auto& [call, kind] : kinds)
    if (name == call) return kind;
  return "other";
}

std::string signal_name(int s) {
  switch (s) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    case SIGTRAP: return "SIGTRAP";
    case SIGKILL: return "SIGKILL";
    case SIGXCPU: return "SIGXCPU";
    case SIGSYS: return "SIGSYS";
    case SIGTERM: return "SIGTERM";
  }
  return fmt::format("signal {}", s);
}

// A confined child running the harness, with its three pipes.
class Child {
 public:
  Child(const std::filesystem::path& program, const RunConfig& config) {
    LandlockRules rules;
    rules.allow(program, landlock_access::execute | landlock_access::read_file);
    SpawnSpec spec;
    spec.program = program.string();
    spec.argv = {"epure-harness"};
    spec.env = {};
    spec.directory = "/";
    spec.descriptors = {{0, in_.read}, {1, out_.write}, {2, out_.write}, {3, results_.write}};
    spec.limits = config.limits;
    spec.limits.processes = 0;
    spec.user = config.user;
    spec.landlock_ruleset = rules.fd();
    spec.seccomp = config.seccomp;
    pid_ = spawn_confined(spec);
    in_.close_read();
    out_.close_write();
    results_.close_write();
    fcntl(out_.read, F_SETFL, O_NONBLOCK);
    fcntl(results_.read, F_SETFL, O_NONBLOCK);
  }
  ~Child() { stop(); }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // Kills the whole group and reaps the child (idempotent).
  ChildExit stop() {
    if (pid_ > 0) {
      kill_group(pid_);
      exit_ = wait_child(pid_);
      pid_ = -1;
    }
    return exit_;
  }
  // The child has ended on its own: reap it (and anything left in its group).
  ChildExit reap() {
    if (pid_ > 0) {
      exit_ = wait_child(pid_);
      kill_group(pid_);
      pid_ = -1;
    }
    return exit_;
  }

  bool send(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = write(in_.write, bytes.data(), bytes.size());
      if (n < 0) {
        if (errno == EINTR) continue;
        return false;  // EPIPE: it is gone (SIGPIPE is ignored)
      }
      bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  enum class Event { records, ended, deadline, output_flood };

  // Waits for records, the end, or the deadline; collects output meanwhile into `output`.
  Event wait(Clock::time_point deadline, std::vector<Record>& records, FunctionRun& sink, const RunConfig& config) {
    for (;;) {
      pollfd fds[2] = {{results_.read, POLLIN, 0}, {out_.read, POLLIN, 0}};
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return Event::deadline;
      const int ready = poll(fds, out_.read >= 0 ? 2 : 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (ready < 0 && errno != EINTR) return Event::ended;
      if (fds[1].revents != 0 && drain_output(sink, config)) return Event::output_flood;
      if (fds[0].revents != 0) {
        char buffer[4096];
        const ssize_t n = read(results_.read, buffer, sizeof buffer);
        if (n > 0) {
          records = reader_.feed({buffer, static_cast<std::size_t>(n)});
          if (!records.empty() || reader_.broken()) return Event::records;
          continue;
        }
        if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
          drain_output(sink, config);
          return Event::ended;
        }
      }
    }
  }

  const ResultReader& reader() const { return reader_; }

 private:
  // Reads what is there; true when the student's output passed the cap.
  bool drain_output(FunctionRun& sink, const RunConfig& config) {
    char buffer[8192];
    for (;;) {
      if (out_.read < 0) return false;
      const ssize_t n = read(out_.read, buffer, sizeof buffer);
      if (n <= 0) {
        if (n == 0) out_.close_read();  // closed: poll no more
        return false;
      }
      const std::size_t room = config.output_kept > sink.output.size() ? config.output_kept - sink.output.size() : 0;
      sink.output.append(buffer, std::min(room, static_cast<std::size_t>(n)));
      sink.output_bytes += static_cast<std::size_t>(n);
      if (sink.output_bytes > config.output_cap) {
        // how far past the cap the pipe got before the kill depends on scheduling: the report
        // says only "over the cap" (cap + 1), so that two runs write the same report.json
        sink.output_bytes = config.output_cap + 1;
        return true;
      }
    }
  }

  Pipe in_, out_, results_;
  pid_t pid_ = -1;
  ChildExit exit_;
  ResultReader reader_;
};

void end_with(FunctionRun& run, RunEnd end, std::string code, std::string key, TextVars vars = {}) {
  run.end = end;
  run.reason_code = std::move(code);
  run.reason_key = std::move(key);
  run.reason_vars = std::move(vars);
}

// Why the child ended, from the last record it sent and its exit.
void explain_end(FunctionRun& run, const std::optional<Record>& last, const ChildExit& exit) {
  if (last) {
    if (const auto* f = std::get_if<record::Forbidden>(&*last)) {
      const std::string name = SeccompProgram::name_of(f->syscall_number);
      end_with(run, RunEnd::refused, name, "syscall", {{"call", name}, {"kind", call_kind(name)}});
      return;
    }
    if (const auto* r = std::get_if<record::Raised>(&*last)) {
      if (r->signal == SIGABRT) end_with(run, RunEnd::crashed, "abort", "abort");
      else end_with(run, RunEnd::crashed, signal_name(r->signal), "raised", {{"signal", signal_name(r->signal)}});
      return;
    }
    if (const auto* f = std::get_if<record::Fatal>(&*last)) {
      const TextVars where{{"signal", signal_name(f->signal)}, {"address", fmt::format("{:#x}", f->address)}};
      if (f->stack_overflow) end_with(run, RunEnd::crashed, "stack_overflow", "stack_overflow");
      else if ((f->signal == SIGSEGV || f->signal == SIGBUS) && f->address < 4096)
        end_with(run, RunEnd::crashed, signal_name(f->signal), "null_pointer", where);
      // a wild address is not said: under ASLR it differs between runs, and report.json must not
      else if (f->signal == SIGSEGV || f->signal == SIGBUS) end_with(run, RunEnd::crashed, signal_name(f->signal), "memory", {{"signal", signal_name(f->signal)}});
      else if (f->signal == SIGFPE) end_with(run, RunEnd::crashed, "SIGFPE", "fpe");
      else end_with(run, RunEnd::crashed, signal_name(f->signal), "fatal", where);
      return;
    }
    if (const auto* n = std::get_if<record::NotWritten>(&*last); n && !n->fn) {
      end_with(run, RunEnd::crashed, "todo_outside", "todo_outside");
      return;
    }
  }
  if (exit.signal == SIGSYS) {
    // the filter's signal while it was blocked (a thread's creation blocks them all): the kernel
    // then ends the process without the harness's word on which call it was
    end_with(run, RunEnd::refused, "syscall", "syscall_blocked");
  } else if (exit.signal == SIGXCPU || (exit.signal == SIGKILL && exit.usage.ru_utime.tv_sec + exit.usage.ru_stime.tv_sec > 0)) {
    end_with(run, RunEnd::timeout, "cpu", "cpu");
  } else if (exit.signal != 0) {
    end_with(run, RunEnd::crashed, signal_name(exit.signal), "signal", {{"signal", signal_name(exit.signal)}});
  } else {
    end_with(run, RunEnd::crashed, "exit", "exit", {{"status", std::to_string(exit.status)}});
  }
}

// Starts a child and reads its hello: nothing in `startup` on success.
std::unique_ptr<Child> start(const std::filesystem::path& program, const RunConfig& config, std::uint32_t& defined,
                             std::optional<FunctionRun>& startup) {
  auto child = std::make_unique<Child>(program, config);
  FunctionRun probe;
  const auto deadline = Clock::now() + config.function_time;
  std::optional<Record> last;
  for (;;) {
    std::vector<Record> records;
    const auto event = child->wait(deadline, records, probe, config);
    if (event == Child::Event::records) {
      if (child->reader().broken()) {
        child->stop();
        end_with(probe, RunEnd::refused, "protocol", "protocol", {{"error", child->reader().error()}});
        startup = std::move(probe);
        return nullptr;
      }
      for (auto& r : records) {
        if (const auto* h = std::get_if<record::Hello>(&r)) {
          defined = h->defined;
          return child;
        }
        last = std::move(r);
      }
      continue;
    }
    if (event == Child::Event::deadline) {
      child->stop();
      end_with(probe, RunEnd::timeout, "startup", "startup");
    } else if (event == Child::Event::output_flood) {
      child->stop();
      end_with(probe, RunEnd::refused, "output", "output", {{"bytes", std::to_string(config.output_cap)}});
    } else {
      explain_end(probe, last, child->reap());
    }
    startup = std::move(probe);
    return nullptr;
  }
}

}  // namespace

FileRun run_program(const std::filesystem::path& program, const std::vector<std::vector<Case>>& cases,
                    const RunConfig& config) {
  if (!config.seccomp) throw SandboxError("no seccomp filter: refusing to run a student's program unconfined");
  signal(SIGPIPE, SIG_IGN);
  FileRun file;
  std::unique_ptr<Child> child = start(program, config, file.defined, file.startup);
  if (!child) return file;
  std::uint32_t seq = 0;
  for (int f = 0; f < kFunctionCount; ++f) {
    if (!(file.defined & (1u << f)) || static_cast<std::size_t>(f) >= cases.size() || cases[static_cast<std::size_t>(f)].empty())
      continue;
    const Fn fn = static_cast<Fn>(f);
    const std::vector<Case>& todo = cases[static_cast<std::size_t>(f)];
    FunctionRun run;
    run.fn = fn;
    run.outcomes.assign(todo.size(), std::nullopt);
    if (!child) {
      std::uint32_t again = 0;
      std::optional<FunctionRun> failed;
      child = start(program, config, again, failed);
      if (!child) {  // it started once and not now: the same verdict as its start-up
        run.end = failed->end, run.reason_code = failed->reason_code;
        run.reason_key = failed->reason_key, run.reason_vars = failed->reason_vars;
        run.stopped_at = 0;
        file.functions.push_back(std::move(run));
        continue;
      }
    }
    const auto deadline = Clock::now() + config.function_time;
    const std::uint32_t base = seq;  // case i of this function is number base + i
    seq += static_cast<std::uint32_t>(todo.size());
    std::size_t answered = 0;
    std::optional<Record> last;
    bool ended = false;
    while (answered < todo.size() && !ended) {
      // the next batch
      const std::size_t end = std::min(todo.size(), answered + kBatch);
      std::string batch;
      batch.reserve((end - answered) * kCaseRecordSize);
      for (std::size_t i = answered; i < end; ++i) {
        const auto record = encode_case(fn, base + static_cast<std::uint32_t>(i), todo[i].in);
        batch.append(record.data(), record.size());
      }
      child->send(batch);
      while (answered < end && !ended) {
        std::vector<Record> records;
        const auto event = child->wait(deadline, records, run, config);
        if (event == Child::Event::deadline) {
          child->stop();
          end_with(run, RunEnd::timeout, "time", "time", {{"ms", std::to_string(config.function_time.count())}});
          ended = true;
          break;
        }
        if (event == Child::Event::output_flood) {
          child->stop();
          end_with(run, RunEnd::refused, "output", "output", {{"bytes", std::to_string(config.output_cap)}});
          ended = true;
          break;
        }
        if (event == Child::Event::ended) {
          explain_end(run, last, child->reap());
          ended = true;
          break;
        }
        if (child->reader().broken()) {
          child->stop();
          end_with(run, RunEnd::refused, "protocol", "protocol", {{"error", child->reader().error()}});
          ended = true;
          break;
        }
        for (auto& r : records) {
          if (const auto* res = std::get_if<record::Result>(&r)) {
            const std::uint32_t want = base + static_cast<std::uint32_t>(answered);
            if (res->fn != fn || res->seq != want) {
              child->stop();
              end_with(run, RunEnd::refused, "protocol", "protocol", {{"error", "a result out of order"}});
              ended = true;
              break;
            }
            run.outcomes[answered++] = res->outcome;
            continue;
          }
          if (const auto* n = std::get_if<record::NotWritten>(&r); n && n->fn == fn) {
            child->stop();
            run.end = RunEnd::not_written;
            ended = true;
            break;
          }
          last = std::move(r);
        }
      }
    }
    if (ended && run.end != RunEnd::completed && run.end != RunEnd::not_written) run.stopped_at = answered;
    if (ended) child.reset();
    file.functions.push_back(std::move(run));
  }
  if (child) {
    const char quit[kCaseRecordSize] = {'Q'};
    child->send({quit, sizeof quit});
    child->reap();
  }
  return file;
}

}  // namespace epure::check
