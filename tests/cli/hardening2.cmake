# Issue 19's hostile suite, second round: outputs into a folder promyk may
# not write (as an unprivileged user when run as root), and deep and huge
# JSON under a memory and time cap. Included from tests/CMakeLists.txt.
# Hostile tests, so in the release pass only: prlimit's address-space cap
# breaks AddressSanitizer's shadow memory, and the timings are a release
# build's.
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.readonly_dir COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/readonly_dir_test.sh $<TARGET_FILE:promyk>
                                         ${CMAKE_CURRENT_BINARY_DIR}/cli/readonly_dir)
  # Root without setpriv, or a user who writes anywhere: skipped, not passed.
  set_tests_properties(cli.readonly_dir PROPERTIES SKIP_RETURN_CODE 77)
  add_test(NAME cli.hostile_json COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_json_test.sh $<TARGET_FILE:promyk>
                                         ${CMAKE_CURRENT_BINARY_DIR}/cli/hostile_json)
endif()
