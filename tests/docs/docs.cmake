# The documents' tests (included from tests/CMakeLists.txt).

# A reference script refuses an output path that begins with "-" (an option
# misread as the output once left a file named '--help' in the repository).
add_test(NAME reference_script_refuses_dash_output
         COMMAND ${CMAKE_COMMAND} -DPROMYK=${PROMYK_PYTHON}
                 "-DARGS=${CMAKE_CURRENT_SOURCE_DIR}/reference/make_reference.py|--help" -DEXIT=2
                 "-DSTDERR=the output path must not begin with '-': --help" -DEMPTY=ON
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/docs/dash_output
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)

