// `epure solve [FILE]`: JSON Lines in, one result per line out, in order.
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.h"
#include "solve/solve.h"

namespace epure::cli {

namespace {

struct SolveOptions {
  std::string file;  // empty or "-": standard input
};

// Lines of a stream, read in large blocks and handed out as views into the block: no copy and
// no allocation per line (a million-line file is read in a hundred reads).
class LineReader {
 public:
  explicit LineReader(std::FILE* in) : in_(in), buffer_(1 << 20) {}

  // The next line without its '\n' (valid until the next call), or nothing at the end of the
  // input or on a read error (then failed()).
  std::optional<std::string_view> next() {
    for (;;) {
      const char* begin = buffer_.data() + pos_;
      if (auto* nl = static_cast<const char*>(std::memchr(begin, '\n', size_ - pos_))) {
        pos_ = static_cast<std::size_t>(nl - buffer_.data()) + 1;
        return std::string_view(begin, static_cast<std::size_t>(nl - begin));
      }
      if (size_ - pos_ > solve::kMaxLineBytes) return too_long();
      if (done_) {
        if (pos_ == size_) return std::nullopt;
        pos_ = size_;  // a last line without its '\n'
        return std::string_view(begin, static_cast<std::size_t>(buffer_.data() + size_ - begin));
      }
      refill();
    }
  }
  bool failed() const { return std::ferror(in_) != 0; }

 private:
  // Keeps the unfinished line, at the front, and reads after it; a line longer than the buffer
  // doubles it.
  void refill() {
    std::memmove(buffer_.data(), buffer_.data() + pos_, size_ - pos_);
    size_ -= pos_;
    pos_ = 0;
    if (size_ == buffer_.size()) buffer_.resize(2 * buffer_.size());
    const std::size_t got = std::fread(buffer_.data() + size_, 1, buffer_.size() - size_, in_);
    size_ += got;
    if (got == 0) done_ = true;
  }

  // A line longer than solve::kMaxLineBytes: its first kMaxLineBytes + 1 bytes (solve_line
  // refuses them, and the line still gives one output line), the rest read past up to its '\n'
  // without being kept, so that a line of gigabytes takes no more memory than one of 2 MiB.
  std::string_view too_long() {
    std::memmove(buffer_.data(), buffer_.data() + pos_, size_ - pos_);
    size_ -= pos_;
    pos_ = 0;
    const std::size_t keep = solve::kMaxLineBytes + 1;
    if (buffer_.size() < 2 * keep) buffer_.resize(2 * keep);
    for (;;) {
      if (auto* nl = static_cast<const char*>(std::memchr(buffer_.data() + keep, '\n', size_ - keep))) {
        const std::size_t after = static_cast<std::size_t>(nl - buffer_.data()) + 1;
        std::memmove(buffer_.data() + keep, buffer_.data() + after, size_ - after);
        size_ = keep + (size_ - after);
        break;
      }
      size_ = keep;
      if (done_) break;
      const std::size_t got = std::fread(buffer_.data() + size_, 1, buffer_.size() - size_, in_);
      size_ += got;
      if (got == 0) {
        done_ = true;
        break;
      }
    }
    pos_ = keep;
    return std::string_view(buffer_.data(), keep);
  }

  std::FILE* in_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, size_ = 0;
  bool done_ = false;
};

// Reads lines from `in`, writes results to stdout; bad lines are reported on stderr with their
// line number and the rest is still solved. Returns the exit status: 1 if any line failed.
int run_solve(std::FILE* in, const std::string& name) {
  LineReader lines(in);
  fmt::memory_buffer out;
  long line_number = 0;
  int failed = 0;
  while (auto next = lines.next()) {
    std::string_view line = *next;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF files
    if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
    std::string error = solve::solve_line(line, out);  // README
    out.push_back('\n');
    if (!error.empty()) {
      ++failed;
      fmt::print(stderr, "epure solve: {}:{}: {}\n", name, line_number, error);
    }
    if (out.size() > (1 << 16)) {
      std::fwrite(out.data(), 1, out.size(), stdout);
      out.clear();
    }
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  if (lines.failed()) {
    fmt::print(stderr, "epure solve: {}: read error after line {}\n", name, line_number);
    return 1;
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace

void add_solve_command(CLI::App& app, int& status) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "solve", "Solve figures given as JSON Lines (one object per line); one JSON result per line");
  cmd->add_option("file", options->file, "Input file (default: standard input)");
  cmd->footer(fmt::format("Kinds: {}. A bad line yields {{\"error\": ...}} and the rest is still\n"
                          "solved; the exit status is 1 if any line failed.",
                          fmt::join(solve::contract_kinds(), ", ")));
  cmd->callback([options, &status] {
    if (options->file.empty() || options->file == "-") {
      status = run_solve(stdin, "<stdin>");
      return;
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(options->file.c_str(), "rb"),
                                                       &std::fclose);
    if (!in) {
      fmt::print(stderr, "epure solve: cannot open '{}'\n", options->file);
      status = 2;
      return;
    }
    status = run_solve(in.get(), options->file);
  });
}

}  // namespace epure::cli
