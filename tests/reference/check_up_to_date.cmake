# Regenerates the reference into OUTPUT and compares it with the committed
# file byte for byte. Run by CTest (test reference_data_up_to_date):
#   cmake -DPYTHON=... -DSCRIPT=.../make_reference.py -DCOMMITTED=.../article_reference.json
#         -DOUTPUT=<file in the build dir> [-DOPTIONS=--scenes] -P check_up_to_date.cmake
# (OPTIONS: arguments put before OUTPUT, e.g. --scenes for scenes_reference.json;
# test reference_scenes_data_up_to_date). Test reference_effects_data_up_to_date
# runs it with SCRIPT=.../make_effects_reference.py and COMMITTED=.../effects_reference.json;
# reference_hard_cases_data_up_to_date and hard_cases_catalogue_up_to_date with
# SCRIPT=.../make_hard_cases.py (the second with OPTIONS=--catalogue).
foreach(var PYTHON SCRIPT COMMITTED OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_up_to_date.cmake: ${var} is not set")
  endif()
endforeach()

get_filename_component(output_dir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${output_dir}")
file(REMOVE "${OUTPUT}")
execute_process(
  COMMAND "${PYTHON}" "${SCRIPT}" ${OPTIONS} "${OUTPUT}"
  RESULT_VARIABLE result
  ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} failed (${result}):\n${errors}")
endif()

execute_process(
  COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUTPUT}" "${COMMITTED}"
  RESULT_VARIABLE different)
if(NOT different EQUAL 0)
  message(FATAL_ERROR "${COMMITTED} is not what ${SCRIPT} makes now (see ${OUTPUT}); "
                      "regenerate it with: ${PYTHON} ${SCRIPT} ${OPTIONS} ${COMMITTED}")
endif()
message(STATUS "reference data up to date: ${COMMITTED}")
