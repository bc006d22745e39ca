// `epure preview KIND`: one exercise's question and key diagrams as PNG, drawn by the cairo
// backend, for a quick look at a kind (or at a change to one) without generating a set.
#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "exercises/exercise.h"
#include "exercises/spec.h"
#include "exercises/worksheet.h"
#include "output/atomic_file.h"
#include "render/pdf_document.h"

namespace epure::cli {

namespace {

struct PreviewOptions {
  std::string kind;
  std::uint64_t seed = 1;
  std::string language;
  std::string difficulty;
  std::string branch;
  std::string out = "out/preview";
  double dpi = 150;
  double width = 360;  // points: about the width a figure takes on the page
};

// The Figures of a section, in order.
std::vector<const render::Scene*> figures(const render::Section& section) {
  std::vector<const render::Scene*> scenes;
  for (const auto& block : section.blocks)
    if (const auto* f = std::get_if<render::Figure>(&block)) scenes.push_back(&f->scene);
  return scenes;
}

int run_preview(const PreviewOptions& o) {
  const ExerciseKind* kind = find_kind(o.kind);
  if (kind == nullptr) {
    std::string names;
    for (const ExerciseKind* k : all_kinds()) names += (names.empty() ? "" : ", ") + std::string(k->name());
    fmt::print(stderr, "epure preview: unknown kind '{}' (kinds: {})\n", o.kind, names);
    return 2;
  }
  // The course's own settings for this kind when it has them (points, constraints), else the kind's.
  // (the built-in spec that has the kind: the course, or the course in space)
  WorksheetSpec spec = builtin_spec();
  ExerciseSpec exercise{};
  exercise.kind = o.kind;
  for (const auto& candidate : builtin_specs()) {
    bool found = false;
    for (const auto& e : candidate.exercises)
      if (e.kind == o.kind) exercise = e, found = true;
    if (found) {
      spec = candidate;
      break;
    }
  }
  if (!o.branch.empty()) {
    bool known = false;
    std::string names;
    for (const auto& [name, weight] : kind->default_branches()) {
      known = known || name == o.branch;
      names += (names.empty() ? "" : ", ") + name;
    }
    if (!known) {
      fmt::print(stderr, "epure preview: kind '{}' has no branch '{}' (branches: {})\n", o.kind, o.branch, names);
      return 2;
    }
    exercise.branches = {{o.branch, 1.0}};
  }
  spec.exercises = {exercise};
  SetOptions options;
  if (!o.language.empty()) options.language = o.language;
  if (!o.difficulty.empty()) options.difficulty = parse_difficulty(o.difficulty);
  WorksheetSet set(std::move(spec), o.seed, options);
  const Sheet sheet = set.next();
  const ExerciseInstance& instance = sheet.exercises.at(0);

  std::filesystem::create_directories(o.out);
  std::vector<std::string> written;
  const auto write = [&](const std::vector<const render::Scene*>& scenes, const char* part) {
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const std::string name =
          scenes.size() == 1 ? fmt::format("{}-{}.png", o.kind, part) : fmt::format("{}-{}-{}.png", o.kind, part, i + 1);
      output::write_file_atomically(std::filesystem::path(o.out) / name,
                                    render::scene_to_png(*scenes[i], o.width, o.dpi));
      written.push_back(name);
    }
  };
  write(figures(instance.sheet), "question");
  write(figures(instance.key), "key");
  fmt::print("epure preview: {} ({}, sheet {}) into {}/: {}\n", o.kind, instance.branch, sheet.id.str(), o.out,
             fmt::join(written, ", "));
  return 0;
}

}  // namespace

void add_preview_command(CLI::App& app, int& status) {
  auto o = std::make_shared<PreviewOptions>();
  CLI::App* cmd = app.add_subcommand("preview", "Draw one exercise's question and key diagrams as PNG");
  cmd->add_option("kind", o->kind, "Exercise kind (as 'epure kinds' lists them)")->required()->check(kind_name_check());
  cmd->add_option("--seed,-s", o->seed, "Seed")->capture_default_str();
  cmd->add_option("--lang", o->language, "Language of the labels")->check(CLI::IsMember({"en", "fr"}));
  cmd->add_option("--difficulty", o->difficulty, "Difficulty")->check(CLI::IsMember({"easy", "standard", "hard"}));
  cmd->add_option("--branch", o->branch, "The case to draw (between, miss, …); default: as a set would");
  cmd->add_option("--out,-o", o->out, "Output directory")->capture_default_str();
  cmd->add_option("--dpi", o->dpi, "Resolution")->check(CLI::Range(20.0, 1200.0))->capture_default_str();
  cmd->callback([o, &status] { status = run_reporting("epure preview", [&] { return run_preview(*o); }); });
}

}  // namespace epure::cli
