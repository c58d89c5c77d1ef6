# The documents' tests (included from tests/CMakeLists.txt).

# A reference script refuses an output path that begins with "-" (an option
# misread as the output once left a file named '--help' in the repository).
add_test(NAME reference_script_refuses_dash_output
         COMMAND ${CMAKE_COMMAND} -DPROMYK=${PROMYK_PYTHON}
                 "-DARGS=${CMAKE_CURRENT_SOURCE_DIR}/reference/make_reference.py|--help" -DEXIT=2
                 "-DSTDERR=the output path must not begin with '-': --help" -DEMPTY=ON
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/docs/dash_output
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)

# The release pass only: the sanitizers' build would give the same bytes and
# outputs, many times slower.
if(NOT PROMYK_SANITIZE)
  # docs/*.png are what docs/make_pictures.sh makes today.
  add_test(NAME docs.pictures_up_to_date
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs/pictures_up_to_date.sh $<TARGET_FILE:promyk>
                   ${CMAKE_CURRENT_BINARY_DIR}/docs/pictures)
  # Every command shown in README.md and docs/*.md prints what is shown.
  add_test(NAME docs.commands
           COMMAND ${PROMYK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/docs/doc_commands.py $<TARGET_FILE:promyk>)
  set_tests_properties(docs.commands PROPERTIES TIMEOUT 300)
endif()
