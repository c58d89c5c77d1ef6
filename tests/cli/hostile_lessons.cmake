# Hostile input on promyk lesson's files: a teacher's folder, a student's
# answers, --dump. Included from tests/CMakeLists.txt.
add_test(NAME cli.hostile_lessons COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_lessons_test.sh $<TARGET_FILE:promyk>
                                          ${CMAKE_CURRENT_BINARY_DIR}/cli/hostile_lessons)
# The 10^5-pixel cases take 2 to 3 s of CPU in a release build (and several
# times that in wall-clock time on a busy machine: the limit is 20 s);
# AddressSanitizer multiplies that by about ten, so its limit is larger
# (still far below what a quadratic cost would take: 10^10 steps).
if(PROMYK_SANITIZE)
  set_tests_properties(cli.hostile_lessons PROPERTIES ENVIRONMENT "PROMYK_TEST_SECONDS=120")
endif()
