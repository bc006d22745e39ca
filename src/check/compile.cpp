#include "check/compile.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/landlock.h"
#include "check/sandbox_error.h"
#include "embed/embedded.h"

namespace epure::check {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kCompileTime = std::chrono::seconds(30);
constexpr std::size_t kMaxCompilerOutput = 1 << 20;

// The starter's headers, as the harness and every submission are compiled with them (the
// English copy: the French one has the same code, tests/check/starter_test.cpp checks it).
constexpr const char* kHeaders[] = {"raytracer.h", "g2x.h", "g3x.h"};

std::string template_text(const std::string& name) {
  const auto text = embedded_file(name);
  if (!text) throw std::runtime_error(fmt::format("epure was built without templates/{}", name));
  return std::string(*text);
}

void write_file(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
}

std::string find_program(const char* name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return std::filesystem::canonical(candidate).string();
  }
  return {};
}

std::string line_of(std::string_view source, int line) {
  int at = 1;
  std::size_t from = 0;
  while (at < line) {
    const std::size_t nl = source.find('\n', from);
    if (nl == std::string_view::npos) return {};
    from = nl + 1;
    ++at;
  }
  const std::size_t to = source.find('\n', from);
  std::string text(source.substr(from, to == std::string_view::npos ? std::string_view::npos : to - from));
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

// The name of a file gcc talks about, as a message may show it: the submission's own name,
// a starter header by name, a system header as <name>.
std::string shown_file(const std::string& file, std::string_view display_name) {
  if (file == "submission.c") return std::string(display_name);
  const std::string base = std::filesystem::path(file).filename().string();
  for (const char* h : kHeaders)
    if (base == h) return base;
  return "<" + base + ">";
}

void add_diagnostic(const nlohmann::json& d, std::string_view source, std::string_view display_name,
                    std::vector<CompileMessage>& out) {
  if (!d.is_object() || out.size() >= kMaxMessages) return;
  CompileMessage m;
  m.severity = d.value("kind", "error");
  m.text = d.value("message", "");
  std::string file;
  if (d.contains("locations") && d["locations"].is_array() && !d["locations"].empty()) {
    const auto& caret = d["locations"][0].value("caret", nlohmann::json::object());
    file = caret.value("file", "");
    m.line = caret.value("line", 0);
    m.column = caret.value("display-column", caret.value("column", 0));
  }
  const bool ours = file == "submission.c";
  if (!ours) {
    m.line = 0;
    m.column = 0;
  }
  const std::string where = file.empty() ? std::string(display_name)
                            : ours       ? fmt::format("{}:{}:{}", display_name, d["locations"][0]["caret"].value("line", 0), m.column)
                                         : shown_file(file, display_name);
  m.rendered = fmt::format("{}: {}: {}", where, m.severity, m.text);
  if (ours && m.line > 0) {
    const std::string text = line_of(source, m.line);
    m.rendered += fmt::format("\n  {:>4} | {}\n       | {}^", m.line, text, std::string(m.column > 1 ? m.column - 1 : 0, ' '));
  }
  out.push_back(std::move(m));
  if (d.contains("children") && d["children"].is_array())
    for (const auto& child : d["children"]) add_diagnostic(child, source, display_name, out);
}

// The linker's and assembler's lines (plain text): only what they say, never a path nor text
// quoted from a file.
void add_tool_lines(std::string_view text, std::vector<CompileMessage>& out) {
  std::size_t from = 0;
  while (from < text.size() && out.size() < kMaxMessages) {
    const std::size_t nl = text.find('\n', from);
    const std::string line(text.substr(from, nl == std::string_view::npos ? std::string_view::npos : nl - from));
    from = nl == std::string_view::npos ? text.size() : nl + 1;
    CompileMessage m;
    m.severity = "error";
    if (const auto u = line.find("undefined reference to `"); u != std::string::npos) {
      const auto end = line.find('\'', u);
      const std::string name = line.substr(u + 24, end == std::string::npos ? std::string::npos : end - u - 24);
      m.text = fmt::format("link: {} is used but defined nowhere (a typo? a function of g2x this header does not have?)", name);
    } else if (const auto d = line.find("multiple definition of `"); d != std::string::npos) {
      const auto end = line.find('\'', d);
      const std::string name = line.substr(d + 24, end == std::string::npos ? std::string::npos : end - d - 24);
      m.text = fmt::format("link: {} is defined twice (the header or the checker defines it already)", name);
    } else if (const auto e = line.find("Error: "); e != std::string::npos) {
      m.text = "assembler: " + line.substr(e + 7, 200);
    } else {
      continue;
    }
    bool seen = false;
    for (const auto& o : out) seen = seen || o.text == m.text;
    if (seen) continue;
    m.rendered = m.text;
    out.push_back(std::move(m));
  }
}

}  // namespace

std::vector<CompileMessage> read_diagnostics(std::string_view json_text, std::string_view source,
                                             std::string_view display_name) {
  std::vector<CompileMessage> out;
  const nlohmann::json j = nlohmann::json::parse(json_text, nullptr, false);
  if (!j.is_array()) return out;
  for (const auto& d : j) add_diagnostic(d, source, display_name, out);
  return out;
}

Toolchain::Toolchain(std::filesystem::path work, std::optional<SandboxUser> user)
    : work_(std::move(work)), harness_dir_(work_ / "harness"), user_(user) {
  gcc_ = find_program("gcc");
  if (gcc_.empty()) throw SandboxError("gcc is not installed (apt-get install gcc)");
  std::filesystem::create_directories(harness_dir_);
  for (const char* h : kHeaders) write_file(harness_dir_ / h, template_text(std::string("check/starter/en/") + h));
  write_file(harness_dir_ / "harness.c", template_text("check/harness.c"));
  chmod(harness_dir_.c_str(), 0755);
  if (user_ && chown(harness_dir_.c_str(), user_->uid, user_->gid) != 0)
    throw SandboxError(fmt::format("{}: cannot give it to the sandbox user: {}", harness_dir_.string(), std::strerror(errno)));
  const Run r = run_gcc(harness_dir_, {"-std=c11", "-O1", "-Wall", "-Wextra", "-DEPURE_CHECK", "-I.", "-c", "harness.c",
                                       "-o", "harness.o"});
  if (!r.ok) throw std::runtime_error("the harness does not compile: " + r.err.substr(0, 2000));
}

Toolchain::Run Toolchain::run_gcc(const std::filesystem::path& dir, std::vector<std::string> args) const {
  LandlockRules rules;
  for (const char* tree : {"/usr", "/bin", "/lib", "/lib64", "/lib32", "/libx32"})
    if (std::filesystem::exists(tree)) rules.allow(tree, landlock_access::read_tree);
  if (std::filesystem::exists("/etc/ld.so.cache")) rules.allow("/etc/ld.so.cache", landlock_access::read_file);
  if (std::filesystem::is_character_file("/dev/null"))
    rules.allow("/dev/null", landlock_access::read_file | landlock_access::write_file);
  rules.allow(harness_dir_, landlock_access::read_tree);
  rules.allow(dir, rules.everything());

  int err[2], in[2];
  if (pipe2(err, O_CLOEXEC) != 0 || pipe2(in, O_CLOEXEC) != 0)
    throw SandboxError(fmt::format("pipe: {}", std::strerror(errno)));
  // gcc's standard input: an empty pipe (not /dev/null, which a machine may keep from others)
  close(in[1]);
  const int null = in[0];
  SpawnSpec spec;
  spec.program = gcc_;
  spec.argv = {"gcc"};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", "LANG=C", "TMPDIR=" + dir.string(), "HOME=" + dir.string()};
  spec.directory = dir.string();
  spec.descriptors = {{0, null}, {1, err[1]}, {2, err[1]}};
  spec.limits.cpu_seconds = 30;
  spec.limits.address_space = 2ULL << 30;
  spec.limits.file_size = 64ULL << 20;
  spec.limits.open_files = 256;
  spec.limits.stack = 64ULL << 20;
  if (user_) spec.limits.processes = 256;  // the sandbox user's processes: gcc's passes
  spec.user = user_;
  spec.landlock_ruleset = rules.fd();
  pid_t pid;
  try {
    pid = spawn_confined(spec);
  } catch (...) {
    close(err[0]), close(err[1]), close(null);
    throw;
  }
  close(err[1]);
  close(null);
  Run run;
  const auto deadline = Clock::now() + kCompileTime;
  char buffer[8192];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      run.timed_out = true;
      break;
    }
    pollfd p{err[0], POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    const ssize_t n = read(err[0], buffer, sizeof buffer);
    if (n <= 0) break;
    if (run.err.size() < kMaxCompilerOutput) run.err.append(buffer, static_cast<std::size_t>(n));
  }
  close(err[0]);
  if (run.timed_out) {
    kill_group(pid);
    wait_child(pid);
    return run;
  }
  const ChildExit exit = wait_child(pid);
  kill_group(pid);
  run.ok = exit.exited && exit.status == 0;
  if (exit.signal == SIGXCPU || exit.signal == SIGKILL) run.timed_out = true;
  return run;
}

CompileResult Toolchain::build(const std::filesystem::path& dir, std::string_view source,
                               std::string_view display_name) const {
  std::filesystem::create_directories(dir);
  write_file(dir / "submission.c", source);
  for (const char* h : kHeaders) std::filesystem::copy_file(harness_dir_ / h, dir / h, std::filesystem::copy_options::overwrite_existing);
  if (user_) {
    if (chown(dir.c_str(), user_->uid, user_->gid) != 0)
      throw SandboxError(fmt::format("{}: cannot give it to the sandbox user: {}", dir.string(), std::strerror(errno)));
  }
  chmod(dir.c_str(), 0755);

  CompileResult result;
  const Run compiled = run_gcc(dir, {"-std=c11", "-O1", "-Wall", "-Wextra", "-fdiagnostics-format=json",
                                     "-fmax-errors=40", "-DEPURE_CHECK", "-Dmain=epure_student_main",
                                     "-include", "raytracer.h", "-I.", "-c", "submission.c", "-o", "submission.o"});
  // gcc writes the JSON array on one line; the assembler's lines, if any, are plain text
  std::string plain;
  std::size_t from = 0;
  while (from < compiled.err.size()) {
    const std::size_t nl = compiled.err.find('\n', from);
    const std::string_view line = std::string_view(compiled.err).substr(from, nl == std::string::npos ? std::string::npos : nl - from);
    from = nl == std::string::npos ? compiled.err.size() : nl + 1;
    if (!line.empty() && line.front() == '[') {
      for (auto& m : read_diagnostics(line, source, display_name))
        if (result.messages.size() < kMaxMessages) result.messages.push_back(std::move(m));
    } else {
      plain.append(line).push_back('\n');
    }
  }
  add_tool_lines(plain, result.messages);
  if (compiled.timed_out) {
    result.timed_out = true;
    result.messages.push_back({"error", 0, 0, "the compiler ran past its time or memory limit", "the compiler ran past its time or memory limit"});
    return result;
  }
  if (!compiled.ok) {
    if (result.messages.empty())
      result.messages.push_back({"error", 0, 0, "the compiler failed without a message", "the compiler failed without a message"});
    return result;
  }
  const Run linked = run_gcc(dir, {"-static", "-o", "program", (harness_dir_ / "harness.o").string(), "submission.o", "-lm"});
  if (!linked.ok) {
    const std::size_t before = result.messages.size();
    add_tool_lines(linked.err, result.messages);
    if (result.messages.size() == before)
      result.messages.push_back({"error", 0, 0, "the link failed", "the link failed"});
    result.timed_out = linked.timed_out;
    return result;
  }
  result.ok = true;
  result.program = dir / "program";
  return result;
}

}  // namespace epure::check
