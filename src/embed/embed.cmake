# Writes OUTPUT: a C++ source that holds each INPUT file (paths relative to BASE) as a string,
# looked up by epure::embedded_file("text/en.toml"). Run at build time, so an edited template is
# rebuilt into the binary.
set(content "// Generated from templates/ by src/embed/embed.cmake: do not edit.\n#include \"embed/embedded.h\"\n\nnamespace epure {\nnamespace {\nstruct Entry { std::string_view name, text; };\nconstexpr Entry kEntries[] = {\n")
string(REPLACE "|" ";" INPUTS "${INPUTS}")
foreach(file ${INPUTS})
  file(RELATIVE_PATH name ${BASE} ${file})
  file(READ ${file} text)
  string(APPEND content "  {\"${name}\", R\"epure_embed(${text})epure_embed\"},\n")
endforeach()
string(APPEND content "};\n}  // namespace\n\nstd::optional<std::string_view> embedded_file(std::string_view name) {\n  for (const auto& e : kEntries)\n    if (e.name == name) return e.text;\n  return std::nullopt;\n}\n\nstd::vector<std::string_view> embedded_files() {\n  std::vector<std::string_view> names;\n  for (const auto& e : kEntries) names.push_back(e.name);\n  return names;\n}\n\n}  // namespace epure\n")
file(WRITE ${OUTPUT}.tmp "${content}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
