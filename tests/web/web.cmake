# The web page in a real browser (tests/web/page_test.mjs; included from
# tests/CMakeLists.txt). The release pass only: it runs Debian's chromium
# headless on pages the release promyk exports, and the sanitizers' promyk
# would export the same bytes, slowly. Registered whenever the page is built;
# CI builds with PROMYK_REQUIRE_WEB=ON, so there it is never missing.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.page
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/page_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/page")
  set_tests_properties(web.page PROPERTIES TIMEOUT 600)
endif()

# promyk export's command line (tests/cli/export_test.sh): with the page, its
# data and refusals; without it, the exit 4 that says what to install.
if(PROMYK_WEB_PAGE_BUILT)
  add_test(NAME cli.export COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/cli/export_test.sh" $<TARGET_FILE:promyk>
                                   "${CMAKE_CURRENT_BINARY_DIR}/cli/export")
else()
  add_test(NAME cli.export_without_web
           COMMAND ${CMAKE_COMMAND} -DPROMYK=$<TARGET_FILE:promyk> "-DARGS=export" -DEXIT=4
                   "-DSTDERR=built without the web page \\(missing at build time: .*\\); install them" -DEMPTY=ON
                   -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/cli/export_without_web
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
endif()

# The scene panel (tests/web/edit_test.mjs, issue 17): edits re-render the
# page's image as `promyk render` of the copied scene, bit for bit; the
# loader's messages by their fields; the URL reopens an edited scene.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.edit
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/edit_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/edit")
  set_tests_properties(web.edit PROPERTIES TIMEOUT 600)
endif()

# The lessons section (tests/web/lessons_test.mjs, issue 17): a lesson with
# a chosen pixel shows `promyk lesson --format markdown`'s numbers; a hostile
# scene name stays text; step mode, reveals, the print stylesheet.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.lessons
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/lessons_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/lessons")
  set_tests_properties(web.lessons PROPERTIES TIMEOUT 600)
endif()

# Touch (tests/web/touch_test.mjs, issue 17): at 1024 × 768 with touch, a
# tap selects a pixel, steps the derivation and a lesson, edits a field; one
# finger turns the 3D view and two pinch it; a phone still shows the image
# and the derivation.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.touch
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/touch_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/touch")
  set_tests_properties(web.touch PROPERTIES TIMEOUT 600)
endif()

# A browser without WebGL (tests/web/no_webgl_test.mjs): the page opens
# without the 3D view, says why, and lists what it would draw in words.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.no_webgl
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/no_webgl_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/no_webgl")
  set_tests_properties(web.no_webgl PROPERTIES TIMEOUT 300)
endif()

# The keyboard (tests/web/keyboard_test.mjs, issue 17): Tab reaches every
# control a reader can see, each with a visible focus ring; Enter, Space and
# the arrows work them.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.keyboard
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/keyboard_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/keyboard")
  set_tests_properties(web.keyboard PROPERTIES TIMEOUT 600)
endif()

# The worksheet in the page (tests/web/worksheet_test.mjs, issue 17): marks
# equal `promyk lesson --answers` on the saved file; the URL reopens the
# lesson at its pixel, step and mode; axe-core; a keyboard-only walk.
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.worksheet
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/worksheet_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/worksheet")
  set_tests_properties(web.worksheet PROPERTIES TIMEOUT 600)
endif()

# The precision lab (issue 17): export --bench embeds and checks a bench file
# (tests/cli/export_bench_test.sh); in the browser (tests/web/precision_test.mjs)
# the bench plot, the error and digits-lost overlays against `render --map`,
# the fixed range, the far sphere's type and formula, axe-core.
if(PROMYK_WEB_PAGE_BUILT)
  add_test(NAME cli.export_bench COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/cli/export_bench_test.sh" $<TARGET_FILE:promyk>
                                         "${CMAKE_CURRENT_BINARY_DIR}/cli/export_bench"
                                         "${CMAKE_CURRENT_SOURCE_DIR}/web/data/accuracy_w8.json")
  # A number beyond double's range (fuzz_accuracy's finding: exit 70 before).
  promyk_cli_test(export_bench_number_overflow ARGS export --bench ${CMAKE_CURRENT_SOURCE_DIR}/data/bench_number_overflow.json
                  -o p.html EXIT 3 EMPTY
                  STDERR "bench_number_overflow.json: the number 1e999 is too large for a double; promyk bench accuracy")
  promyk_cli_test(export_bench_number_overflow_pl ARGS export --lang pl --bench ${CMAKE_CURRENT_SOURCE_DIR}/data/bench_number_overflow.json
                  -o p.html EXIT 3 EMPTY STDERR "liczba 1e999 jest za duża dla typu double")
endif()
if(NOT PROMYK_SANITIZE AND PROMYK_WEB_PAGE_BUILT)
  add_test(NAME web.precision
           COMMAND "${PROMYK_NODE}" "${CMAKE_CURRENT_SOURCE_DIR}/web/precision_test.mjs" $<TARGET_FILE:promyk>
                   "${PROMYK_NPM_MODULES}" "${PROJECT_SOURCE_DIR}/lessons" "${CMAKE_CURRENT_BINARY_DIR}/web/precision"
                   "${CMAKE_CURRENT_SOURCE_DIR}/web/data/accuracy_w8.json")
  set_tests_properties(web.precision PROPERTIES TIMEOUT 600)
endif()
