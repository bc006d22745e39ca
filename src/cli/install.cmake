# epure installed like a tool, in the GNU install directories (`cmake --install build --prefix P`):
#   bin/epure                                   the program (templates and the explorer page are compiled in)
#   share/man/man1/epure.1.gz, epure-*.1.gz     a manual page per command
#   share/bash-completion/completions/epure     bash completion
#   share/zsh/vendor-completions/_epure         zsh completion (share/zsh/site-functions outside /usr)
#   share/doc/epure/README.md
# and as a Debian package (`cpack -G DEB`, CMakePresets.json's "deb"): epure_<version>_<arch>.deb,
# its Depends computed from the binary by dpkg-shlibdeps. Included from src/CMakeLists.txt.
include(GNUInstallDirs)

# The manual pages and the completion scripts, written by the program from the options it parses
# (`epure __docs`, cli/docs_command.cpp), so that they cannot drift from it; the pages gzipped as
# Debian's policy has them (-n: no name nor time inside, the same bytes every build). Leak checks
# off: under the sanitizers this is a build step, not a test.
set(EPURE_DOCS_DIR ${CMAKE_BINARY_DIR}/docs)
find_program(EPURE_GZIP gzip REQUIRED)
add_custom_command(
  OUTPUT ${EPURE_DOCS_DIR}/written
  COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0 $<TARGET_FILE:epure> __docs --out ${EPURE_DOCS_DIR}
  COMMAND sh -c "${EPURE_GZIP} -9nkf ${EPURE_DOCS_DIR}/man1/*.1"
  COMMAND ${CMAKE_COMMAND} -E touch ${EPURE_DOCS_DIR}/written
  DEPENDS epure
  COMMENT "Writing the manual pages and the shell completions (epure __docs)"
  VERBATIM)
add_custom_target(epure_docs ALL DEPENDS ${EPURE_DOCS_DIR}/written)

install(TARGETS epure RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${EPURE_DOCS_DIR}/man1/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 FILES_MATCHING PATTERN "*.1.gz")
install(FILES ${EPURE_DOCS_DIR}/bash-completion/epure DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# zsh reads completions from its $fpath: Debian's zsh has share/zsh/vendor-completions under /usr
# (where packages put them) and share/zsh/site-functions under /usr/local. The prefix is known
# only when installing (`--prefix`, or /usr for the package), hence the choice made then.
set(EPURE_ZSH_COMPLETION_DIR "" CACHE STRING
    "Where the zsh completion goes, relative to the prefix (default: share/zsh/vendor-completions under /usr, else share/zsh/site-functions)")
install(CODE "
  set(zsh_dir \"${EPURE_ZSH_COMPLETION_DIR}\")
  if(NOT zsh_dir)
    if(CMAKE_INSTALL_PREFIX STREQUAL \"/usr\")
      set(zsh_dir share/zsh/vendor-completions)
    else()
      set(zsh_dir share/zsh/site-functions)
    endif()
  endif()
  file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/\${zsh_dir}\" TYPE FILE FILES \"${EPURE_DOCS_DIR}/zsh/_epure\")
")

# The Debian package. The version is the project's (CMakeLists.txt: project(VERSION)), as
# `epure --version` says it; Depends is what dpkg-shlibdeps finds the binary linked with (libc,
# cairo, pango, libzip, qrencode, fmt, jemalloc, libseccomp, …) plus the font the PDFs
# embed, which pango loads at run time by name.
set(EPURE_PACKAGE_MAINTAINER "epure maintainers <epure@example.org>" CACHE STRING "The Debian package's Maintainer field")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME epure)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${EPURE_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "randomised geometry worksheets, their answer keys and grading")
# (the extended description in lines of under 80 characters, as dpkg shows it)
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "epure turns the geometry of a ray tracer into randomised worksheets: each"
  "student gets their own instance of each exercise (dot and cross products,"
  "projections, segment intersections, ray/circle, ray/square, ellipse,"
  "rectangle, and their forms in space), solved by epure's geometry core and"
  "written with its answer key as SVG and print-ready PDF. It grades a class's"
  "answers from a spreadsheet export, with reports and feedback sheets, and"
  "exports sets to Moodle and QTI.")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
# `epure check` compiles students' C files with gcc and the static C library: recommended (apt
# installs them by default), not required by the rest of the program
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gcc, libc6-dev")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "bash-completion")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
