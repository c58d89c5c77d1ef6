# The web page's tracer: promyk's C++ compiled to WebAssembly by emscripten
# (web_export/wasm, a project of its own, configured with emcmake), driven
# from the native build. Included by web_export/CMakeLists.txt.
#
# Defines:
#   PROMYK_WEB          option: build the wasm (default ON when em++, emcmake
#                       and node are found)
#   PROMYK_REQUIRE_WEB  option: fail the configure when they are missing
#                       (CI: the web build must never be skipped silently)
#   promyk_wasm         custom target (in ALL) building the module
#   PROMYK_WASM_JS      the built single-file module (JavaScript, the wasm
#                       inside), absolute path; empty when PROMYK_WEB is OFF
#   PROMYK_WASM_GZ      the wasm alone, gzip-compressed, and
#   PROMYK_WASM_GLUE_JS the JavaScript without it (createPromyk({wasmBinary}))
# and, with tests on, the CTest test web.wasm_equals_native (release pass).
include_guard(GLOBAL)

option(PROMYK_REQUIRE_WEB "Fail the configure when emscripten or node (for the web page) is missing" OFF)
find_program(PROMYK_EMXX em++)
find_program(PROMYK_EMCMAKE emcmake)
find_program(PROMYK_NODE node)
if(PROMYK_EMXX AND PROMYK_EMCMAKE AND PROMYK_NODE)
  set(promyk_web_default ON)
else()
  set(promyk_web_default OFF)
endif()
option(PROMYK_WEB "Build the web page's tracer with emscripten" ${promyk_web_default})
if(PROMYK_REQUIRE_WEB AND NOT (PROMYK_EMXX AND PROMYK_EMCMAKE AND PROMYK_NODE))
  message(FATAL_ERROR "PROMYK_REQUIRE_WEB: the web page needs emscripten (em++, emcmake) and node; "
                      "install them with .ci/install-deps (Debian: apt-get install emscripten nodejs)")
endif()
if(PROMYK_REQUIRE_WEB AND NOT PROMYK_WEB)
  message(FATAL_ERROR "PROMYK_REQUIRE_WEB is ON but PROMYK_WEB is OFF")
endif()

set(PROMYK_WASM_JS "" CACHE INTERNAL "The wasm module (single-file JavaScript)")
set(PROMYK_WASM_GZ "" CACHE INTERNAL "The wasm alone, gzip-compressed")
set(PROMYK_WASM_GLUE_JS "" CACHE INTERNAL "The module's JavaScript without its inline wasm")
if(NOT PROMYK_WEB)
  message(STATUS "promyk: the web page's tracer (wasm) is not built (PROMYK_WEB is OFF; em++: ${PROMYK_EMXX}, node: ${PROMYK_NODE})")
  return()
endif()

set(PROMYK_WASM_BUILD_DIR "${PROJECT_BINARY_DIR}/web_export/wasm" CACHE PATH
    "Where the wasm project is built (its own emscripten build folder)")
set(promyk_wasm_dir "${PROMYK_WASM_BUILD_DIR}")
set(PROMYK_WASM_JS "${promyk_wasm_dir}/promyk.js" CACHE INTERNAL "The wasm module (single-file JavaScript)")
# The same module split for a small page (web_export/wasm/split_module.mjs):
# the wasm gzip-compressed (about 1.7 MB instead of 12 MB of base64), and the
# glue that takes it as createPromyk({wasmBinary}).
set(PROMYK_WASM_GZ "${promyk_wasm_dir}/promyk.wasm.gz" CACHE INTERNAL "The wasm alone, gzip-compressed")
set(PROMYK_WASM_GLUE_JS "${promyk_wasm_dir}/promyk_glue.js" CACHE INTERNAL "The module's JavaScript without its inline wasm")
# Everything the wasm build reads: a change reruns its (incremental) build.
file(GLOB_RECURSE promyk_wasm_inputs CONFIGURE_DEPENDS
     "${PROJECT_SOURCE_DIR}/src/*.cpp" "${PROJECT_SOURCE_DIR}/src/*.hpp" "${PROJECT_SOURCE_DIR}/src/*.in"
     "${PROJECT_SOURCE_DIR}/lessons/*.json" "${PROJECT_SOURCE_DIR}/lessons/*.md"
     "${CMAKE_CURRENT_LIST_DIR}/wasm/*.cpp" "${CMAKE_CURRENT_LIST_DIR}/wasm/*.hpp"
     "${CMAKE_CURRENT_LIST_DIR}/wasm/CMakeLists.txt")
list(APPEND promyk_wasm_inputs "${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake" "${PROJECT_SOURCE_DIR}/cmake/embedded_text.cpp.in"
     "${PROJECT_SOURCE_DIR}/cmake/core_sources.cmake")
# em++ 3.1.6 from Debian runs its tools with node and needs Debian's node
# modules; the native build's compiler launcher (ccache) is not em++'s.
set(promyk_wasm_env "${CMAKE_COMMAND}" -E env --unset=CMAKE_CXX_COMPILER_LAUNCHER NODE_PATH=/usr/share/nodejs)
# A compiler launcher the native build uses (ccache) serves em++ too; none by default.
set(promyk_wasm_launcher)
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(promyk_wasm_launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}")
endif()
# The native build's unity batches (docs/building.md) for em++ too: it
# compiles the same core files, fmt header-only in each.
if(CMAKE_UNITY_BUILD)
  set(promyk_wasm_unity -DCMAKE_UNITY_BUILD=ON)
else()
  set(promyk_wasm_unity -DCMAKE_UNITY_BUILD=OFF)
endif()
add_custom_command(
  OUTPUT "${PROMYK_WASM_JS}" "${PROMYK_WASM_GZ}" "${PROMYK_WASM_GLUE_JS}"
  COMMAND ${promyk_wasm_env} "${PROMYK_EMCMAKE}" "${CMAKE_COMMAND}" -S "${CMAKE_CURRENT_LIST_DIR}/wasm"
          -B "${promyk_wasm_dir}" -DCMAKE_BUILD_TYPE=Release "-DPROMYK_VERSION=${PROJECT_VERSION}" ${promyk_wasm_launcher}
          ${promyk_wasm_unity}
  # Two jobs at most: em++ is slow and the machine small.
  COMMAND ${promyk_wasm_env} "${CMAKE_COMMAND}" --build "${promyk_wasm_dir}" -j2
  COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_LIST_DIR}/wasm/split_module.mjs" "${PROMYK_WASM_JS}" "${PROMYK_WASM_GZ}"
          "${PROMYK_WASM_GLUE_JS}"
  DEPENDS ${promyk_wasm_inputs} "${CMAKE_CURRENT_LIST_DIR}/wasm/split_module.mjs"
  COMMENT "Building the web page's tracer (WebAssembly, emscripten)"
  VERBATIM)
add_custom_target(promyk_wasm ALL DEPENDS "${PROMYK_WASM_JS}")

# The wasm traces every pixel as the CLI does, byte for byte (node + the
# native promyk). In the release pass only: the sanitizer build's promyk is
# the same code, and the comparison runs a few hundred traces.
if(PROMYK_BUILD_TESTS AND NOT PROMYK_SANITIZE)
  add_test(NAME web.wasm_equals_native
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_LIST_DIR}/wasm/tests/wasm_equals_native.mjs"
                   --module "${PROMYK_WASM_JS}" --promyk "$<TARGET_FILE:promyk>"
                   --gz "${PROMYK_WASM_GZ}" --glue "${PROMYK_WASM_GLUE_JS}"
           WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}")
  set_tests_properties(web.wasm_equals_native PROPERTIES TIMEOUT 600)
endif()
