# cli.isa_paths: `promyk render` under every PROMYK_ISA value writes the same
# bytes, on the article's scene at several w (whole vectors of 2, 4, 8 doubles
# and not), on every example scene and on every hard case's scene at its own
# pane or three times it (the same pixel centres and more), whichever is
# small. A path this processor lacks (by /proc/cpuinfo)
# must be refused with exit 2 and say so; a value that names no path too.
# Run with -DPROMYK=... -DSOURCE=... -DWORK=... [-DSANITIZED=ON]
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

set(cpuinfo "")
if(EXISTS /proc/cpuinfo)
  file(READ /proc/cpuinfo cpuinfo)
endif()
set(paths baseline)
foreach(path avx2 avx512)
  set(flags ${path})
  if(path STREQUAL "avx512")
    set(flags avx512f avx512dq avx512vl avx512bw)  # every one the path is compiled for
  endif()
  set(has_all TRUE)
  foreach(flag ${flags})
    if(NOT cpuinfo MATCHES "[ \t]${flag}[ \n]")
      set(has_all FALSE)
    endif()
  endforeach()
  if(has_all)
    list(APPEND paths ${path})
  else()
    execute_process(COMMAND ${CMAKE_COMMAND} -E env PROMYK_ISA=${path} LC_ALL=C "${PROMYK}" render --w 8 -o "${WORK}/x.png"
                    RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT err MATCHES "cannot run that path")
      message(FATAL_ERROR "PROMYK_ISA=${path} on a processor without ${flags}: exit ${code}, ${err}")
    endif()
  endif()
endforeach()
message(STATUS "paths on this processor: ${paths}")

set(runs 0)
# Renders under every path; each image must equal the baseline's, byte for
# byte (and with DEFAULT, the run without PROMYK_ISA too). Only the article's
# kernel (--stats: "stages: lambert") has paths: other scenes stop after the
# baseline.
function(same_on_every_path name)
  set(runs_here ${paths})
  if(ARGV1 STREQUAL "DEFAULT")
    list(APPEND runs_here default)
    list(REMOVE_AT ARGN 0)
  endif()
  foreach(path ${runs_here})
    set(isa PROMYK_ISA=${path})
    if(path STREQUAL "default")
      set(isa --unset=PROMYK_ISA)
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E env ${isa} LC_ALL=C "${PROMYK}" render ${ARGN} --stats
                            -o "${WORK}/${name}.${path}.png" RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "${name}: PROMYK_ISA=${path} failed (${code}): ${err}")
    endif()
    if(path STREQUAL "baseline" AND NOT err MATCHES "\n *stages: lambert\n")
      return()  # another kernel
    endif()
    file(SHA256 "${WORK}/${name}.baseline.png" expected)
    file(SHA256 "${WORK}/${name}.${path}.png" got)
    if(NOT got STREQUAL expected)
      message(FATAL_ERROR "${name} (render ${ARGN}): ${isa} drew other bytes than PROMYK_ISA=baseline")
    endif()
    math(EXPR n "${runs} + 1")
    set(runs ${n} PARENT_SCOPE)
  endforeach()
endfunction()

foreach(w 61 64 67 301)
  same_on_every_path(article_${w} --w ${w})
endforeach()
same_on_every_path(article_1024 DEFAULT --w 1024)
file(GLOB scenes "${SOURCE}/lessons/scenes/*.json")
foreach(scene ${scenes})
  get_filename_component(name "${scene}" NAME_WE)
  if(name STREQUAL "scene")  # scene.schema.json
    continue()
  endif()
  same_on_every_path(${name}_67 --scene "${scene}" --w 67)
endforeach()
file(READ "${SOURCE}/tests/reference/hard_cases_reference.json" reference)
string(JSON count LENGTH "${reference}" cases)
math(EXPR last "${count} - 1")
foreach(k RANGE ${last})
  string(JSON id GET "${reference}" cases ${k} id)
  string(JSON scene GET "${reference}" cases ${k} scene)
  string(JSON w GET "${reference}" cases ${k} pixel w)
  file(WRITE "${WORK}/${id}.json" "${scene}")
  if(w LESS 100)
    math(EXPR w "3 * ${w}")
  endif()
  same_on_every_path(${id}_${w} --scene "${WORK}/${id}.json" --w ${w})
endforeach()

# Under valgrind, a processor without AVX-512 (valgrind cannot run it): the
# default takes a narrower path and draws the same bytes (AVX-512 code on
# that path would stop it with an illegal instruction), and forcing avx512
# is refused.
# (Not in the sanitizer build: valgrind cannot run AddressSanitizer's code.)
find_program(VALGRIND valgrind)
if(VALGRIND AND NOT SANITIZED)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PROMYK_ISA ${VALGRIND} -q --tool=none "${PROMYK}" render
                          --w 67 -o "${WORK}/valgrind.png" RESULT_VARIABLE code ERROR_VARIABLE err)
  file(SHA256 "${WORK}/article_67.baseline.png" expected)
  if(EXISTS "${WORK}/valgrind.png")
    file(SHA256 "${WORK}/valgrind.png" got)
  endif()
  if(NOT code EQUAL 0 OR NOT got STREQUAL expected)
    message(FATAL_ERROR "under valgrind: exit ${code}, ${err}, or other bytes than the baseline's")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PROMYK_ISA=avx512 LC_ALL=C ${VALGRIND} -q --tool=none "${PROMYK}"
                          render --w 8 -o "${WORK}/valgrind8.png" RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 2 OR NOT err MATCHES "PROMYK_ISA=avx512: this processor \\(or this build of promyk\\) cannot run[ \n]+that path")
    message(FATAL_ERROR "PROMYK_ISA=avx512 under valgrind: exit ${code}, ${err}")
  endif()
  message(STATUS "under valgrind: the default path drew the same bytes; avx512 refused")
endif()

# A value that names no path: exit 2, in the run's language.
execute_process(COMMAND ${CMAKE_COMMAND} -E env PROMYK_ISA=sse2 "${PROMYK}" --lang pl render --w 8 -o "${WORK}/x.png"
                RESULT_VARIABLE code ERROR_VARIABLE err)
# (every path named, then those this processor runs)
list(JOIN paths ",[ \n]+" runs)
if(NOT code EQUAL 2 OR NOT err MATCHES "PROMYK_ISA=sse2: nie ma takiej ścieżki;[ \n]+dozwolone:[ \n]+baseline,[ \n]+avx2,[ \n]+avx512[ \n]+\\(ten[ \n]+procesor[ \n]+wykona:[ \n]+${runs}\\)")
  message(FATAL_ERROR "PROMYK_ISA=sse2: exit ${code}, ${err}")
endif()
if(EXISTS "${WORK}/x.png")
  message(FATAL_ERROR "PROMYK_ISA=sse2: an image was written")
endif()
message(STATUS "${runs} renders, each equal to the baseline's")
