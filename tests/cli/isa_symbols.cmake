# isa.symbols_in_own_namespace: every symbol the AVX2 and AVX-512 translation
# units define for the linker is in their own namespace
# (promyk::lanes::avx2::..., ...::avx512::...). A shared inline function or
# template compiled there (a Vec3 operator, pane_x, trace_ray) would be
# emitted as a weak symbol, and the linker could keep that copy for the
# baseline path too: AVX-512 code on a processor without it.
# Optimised builds only: unoptimised, inline functions of other namespaces
# are emitted too (clang -O0 emits std::numeric_limits<double>::max()), so
# the sanitizer build, which never leaves the machine it is built on, would
# fail it.
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
  # Mangled names (demangled ones of templates start with their return
  # type): the namespace is the prefix N6promyk5lanes<length><isa>, after
  # _Z, or _ZZ (a function's static) or _ZGV (its guard).
  string(LENGTH "${isa}" length)
  set(own_prefix "^_Z(Z|GV)?N6promyk5lanes${length}${isa}")
  execute_process(COMMAND "${NM}" --defined-only "${object}" OUTPUT_VARIABLE symbols RESULT_VARIABLE code)
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
    if(NOT symbol MATCHES "${own_prefix}")
      message(FATAL_ERROR "${name} defines ${symbol}, outside promyk::lanes::${isa}::")
    endif()
    math(EXPR own "${own} + 1")
  endforeach()
  if(own EQUAL 0)
    message(FATAL_ERROR "${name} defines nothing in promyk::lanes::${isa}::")
  endif()
  message(STATUS "${name}: ${own} symbols, all in promyk::lanes::${isa}::")
endforeach()
