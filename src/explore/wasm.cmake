# The page of `epure explore`: the geometry core, the kinds (methods, scenes, texts), the SVG
# writer and explorer.cpp compiled to WebAssembly with em++ (Debian's emscripten), inlined into
# one HTML file (-s SINGLE_FILE=1) around page.html, then embedded into the epure binary
# (src/embed/embed_page.cmake). Without em++ the binary embeds nothing, and `epure explore` says
# how to get the page. Included from src/CMakeLists.txt; sets EPURE_EXPLORE_PAGE (the built
# HTML file, or empty).
#
# Only the sources the page needs, one em++ call per source (parallel, incremental, with depfiles),
# at -O2. fmt and toml++ are used header-only (Debian's libraries are native); their headers and
# nlohmann's are reached through a directory of links, so that em++ sees no other native header.
option(EPURE_EXPLORE "Build the WebAssembly page of `epure explore` when em++ is found" ON)
# CMakePresets.json's "wasm": the page or an error, never a program without it by surprise
option(EPURE_EXPLORE_REQUIRED "Fail when the page cannot be built (em++ or node missing)" OFF)
set(EPURE_EXPLORE_PAGE "")
if(NOT EPURE_EXPLORE)
  return()
endif()
find_program(EPURE_EMXX em++)
find_program(EPURE_NODE node)
if(NOT EPURE_EMXX OR NOT EPURE_NODE)
  if(EPURE_EXPLORE_REQUIRED)
    message(FATAL_ERROR "epure explore: em++ or node not found, and the page is required (apt-get install emscripten)")
  endif()
  message(STATUS "epure explore: em++ or node not found; the page is not built (install emscripten)")
  return()
endif()
message(STATUS "epure explore: building the page with ${EPURE_EMXX}")

set(wasm_dir ${CMAKE_BINARY_DIR}/explore-wasm)
set(wasm_include ${wasm_dir}/include)
file(MAKE_DIRECTORY ${wasm_include})
foreach(lib fmt nlohmann toml++)
  if(NOT EXISTS ${wasm_include}/${lib})
    file(CREATE_LINK /usr/include/${lib} ${wasm_include}/${lib} SYMBOLIC)
  endif()
endforeach()

file(GLOB wasm_sources CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/geometry/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/exercises/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/exercises/kinds/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/solve/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/explore/*.cpp)
list(APPEND wasm_sources
  ${CMAKE_CURRENT_SOURCE_DIR}/render/font_metrics.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/text.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/svg_writer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/markup_escape.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/label_placer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/scene_painter.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/svg_path_data.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/render/svg_scene.cpp
  ${CMAKE_CURRENT_BINARY_DIR}/embedded_templates.cpp)
list(SORT wasm_sources)

# The same floating-point rule as the native build (no fma contraction): the same bits.
# WebAssembly's own exceptions (try/catch in the module, Chromium 95 and later): with emscripten's
# default JavaScript-based ones, every call that may throw inside a try goes out through a
# JavaScript trampoline (invoke_*), and the core is full of them.
set(wasm_eh -fwasm-exceptions)
# _LIBCPP_DISABLE_EXTERN_TEMPLATE: emscripten's libc++ declares std::string's members extern
# templates, so every push_back or append was a call into its prebuilt archive (whose small
# members, __is_long and size, are calls again): with the members instantiated here they inline.
set(wasm_flags -std=c++20 -O3 ${wasm_eh} -ffp-contract=off -D_LIBCPP_DISABLE_EXTERN_TEMPLATE -DFMT_HEADER_ONLY -DTOML_HEADER_ONLY=1
  -I${CMAKE_CURRENT_SOURCE_DIR} -isystem ${wasm_include} -Wno-deprecated-declarations)
set(wasm_env ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
set(wasm_objects "")
foreach(src ${wasm_sources})
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${src})
  if(rel MATCHES "^\\.\\.")
    file(RELATIVE_PATH rel ${CMAKE_BINARY_DIR} ${src})
  endif()
  string(REPLACE "/" "_" obj ${rel})
  set(obj ${wasm_dir}/${obj}.o)
  add_custom_command(
    OUTPUT ${obj}
    COMMAND ${wasm_env} ${EPURE_EMXX} ${wasm_flags} -MD -MF ${obj}.d -c ${src} -o ${obj}
    DEPENDS ${src}
    DEPFILE ${obj}.d
    COMMENT "em++ ${rel}"
    VERBATIM)
  list(APPEND wasm_objects ${obj})
endforeach()

set(EPURE_EXPLORE_PAGE ${wasm_dir}/explore.html)
add_custom_command(
  OUTPUT ${EPURE_EXPLORE_PAGE}
  COMMAND ${wasm_env} ${EPURE_EMXX} -O2 ${wasm_eh} --bind -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1
          -sENVIRONMENT=web -sMINIFY_HTML=0 -sINCOMING_MODULE_JS_API=[onRuntimeInitialized,print,printErr]
          --shell-file ${CMAKE_CURRENT_SOURCE_DIR}/explore/page.html
          ${wasm_objects} -o ${EPURE_EXPLORE_PAGE}
  DEPENDS ${wasm_objects} ${CMAKE_CURRENT_SOURCE_DIR}/explore/page.html
  COMMENT "Linking the explorer page (WebAssembly, one HTML file)"
  VERBATIM)
add_custom_target(epure_explore_page DEPENDS ${EPURE_EXPLORE_PAGE})
