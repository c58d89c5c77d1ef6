# isa.symbols_in_own_namespace: every symbol the AVX2 and AVX-512 translation
# units define for the linker is in their own namespace
# (promyk::lanes::avx2::..., ...::avx512::...). A shared inline function or
# template compiled there (a Vec3 operator, pane_x, trace_ray) would be
# emitted as a weak symbol, and the linker could keep that copy for the
# baseline path too: AVX-512 code on a processor without it.
# Run with -DNM=... -DOBJECTS=a.o|b.o
cmake_minimum_required(VERSION 3.25)
string(REPLACE "|" ";" OBJECTS "${OBJECTS}")
if(NOT OBJECTS)
  message(FATAL_ERROR "no objects given")
endif()
foreach(object ${OBJECTS})
  get_filename_component(name "${object}" NAME)
  if(NOT name MATCHES "_(avx2|avx512)\\.cpp\\.o")
    message(FATAL_ERROR "${name}: not an instruction set's file")
  endif()
  set(isa ${CMAKE_MATCH_1})
  execute_process(COMMAND "${NM}" -C --defined-only "${object}" OUTPUT_VARIABLE symbols RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "nm ${object} failed")
  endif()
  string(REPLACE "\n" ";" lines "${symbols}")
  set(own 0)
  foreach(line ${lines})
    # Local symbols (lower-case kinds) stay in the file.
    if(NOT line MATCHES "^[0-9a-f]* [A-Zuvw] (.*)$")
      continue()
    endif()
    set(symbol "${CMAKE_MATCH_1}")
    if(NOT symbol MATCHES "^promyk::lanes::${isa}::")
      message(FATAL_ERROR "${name} defines ${symbol}, outside promyk::lanes::${isa}::")
    endif()
    math(EXPR own "${own} + 1")
  endforeach()
  if(own EQUAL 0)
    message(FATAL_ERROR "${name} defines nothing in promyk::lanes::${isa}::")
  endif()
  message(STATUS "${name}: ${own} symbols, all in promyk::lanes::${isa}::")
endforeach()
