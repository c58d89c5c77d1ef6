# Issue 19 (hardening): standard output's write errors, outputs that are
# inputs, inputs above their limit. Included from tests/CMakeLists.txt.
# A hostile test (every printing command into /dev/full, a closed stdout, a
# reader gone): the release pass only, as the hostile tests are (the
# sanitizer pass spent about 90 s on it).
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.stdout_errors COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/stdout_errors_test.sh $<TARGET_FILE:promyk>
                                          ${CMAKE_CURRENT_BINARY_DIR}/cli/stdout_errors)
endif()

# Catch2 tests of issue 19, added to the test program here so that its list
# in tests/CMakeLists.txt stays as it is.
target_sources(promyk_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/unit_normal_test.cpp)

add_test(NAME cli.output_is_input COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/output_is_input_test.sh $<TARGET_FILE:promyk>
                                          ${CMAKE_CURRENT_BINARY_DIR}/cli/output_is_input)
target_sources(promyk_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/input_limit_test.cpp)

# Hostile inputs under a memory limit (ulimit -v), which AddressSanitizer's
# shadow memory cannot live with: the release pass only, as the hostile
# tests are.
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.input_limits COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/input_limits_test.sh $<TARGET_FILE:promyk>
                                         ${CMAKE_CURRENT_BINARY_DIR}/cli/input_limits)
endif()

# The bound on a trace's size, estimated from the scene before tracing, and
# what diff refuses in a trace (issue 19, second part).
target_sources(promyk_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/trace_bound_test.cpp)
# Timed refusals (under 2 s): the release pass only; AddressSanitizer took 2.1-2.5 s.
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.trace_limits COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/trace_limits_test.sh $<TARGET_FILE:promyk>
                                         ${CMAKE_CURRENT_BINARY_DIR}/cli/trace_limits)
endif()
