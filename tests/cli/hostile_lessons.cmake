# Hostile input on promyk lesson's files: a teacher's folder, a student's
# answers, --dump. Included from tests/CMakeLists.txt.
# The 10^5-pixel cases take 2 to 3 s of CPU in a release build (and several
# times that in wall-clock time on a busy machine: the limit is 20 s). A
# hostile test, so in the release pass only (under AddressSanitizer it took
# two minutes of the sanitizer pass; the parsers it feeds are fuzzed there).
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.hostile_lessons COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_lessons_test.sh $<TARGET_FILE:promyk>
                                            ${CMAKE_CURRENT_BINARY_DIR}/cli/hostile_lessons)
endif()
