# promyk's core sources in one list, read by both builds of the tracer:
# src/CMakeLists.txt (the native library promyk_core) and
# web_export/wasm/CMakeLists.txt (the web page's tracer, emscripten). A file
# added to the core goes here once; a list kept by hand in each build once
# missed a file in the wasm.
#
# Paths are relative to src/. promyk_core_sources(OUT SRC_DIR [NATIVE])
# sets OUT to the absolute paths: the portable core (scene reader, kernels'
# non-generated parts, trace writer and reader, number formatter, messages,
# vocabulary, the lesson runner the page shows lessons with), and with NATIVE
# also what only the command line needs (`promyk diff`, image files,
# output files, the x87 long double, benchmarks are
# listed by src/CMakeLists.txt itself).
include_guard(GLOBAL)

# Compiled into both the command line and the wasm.
set(PROMYK_PORTABLE_SOURCES
  math/real.cpp
  math/decimal.cpp
  scene/article_scene.cpp
  scene/scene_hash.cpp
  scene/scene_json.cpp
  scene/scene_parse.cpp
  scene/scene_validate.cpp
  scene/scene_hints.cpp
  scene/scene_write.cpp
  render/article_world.cpp
  render/samples.cpp
  render/stages.cpp
  render/kernel.cpp
  render/trace_pixel.cpp
  render/renderer.cpp
  render/article_row.cpp
  render/float_row.cpp
  render/general_row.cpp
  render/pane_columns.cpp
  render/sample_hashes.cpp
  render/isa.cpp
  render/skipping.cpp
  render/maps.cpp
  image/map_colours.cpp
  # The page's error and digits-lost overlays and their legends (issue 17).
  image/map_legend.cpp
  render/map_overlay.cpp
  trace/json_text.cpp
  trace/trace_json.cpp
  trace/trace_lines.cpp
  trace/trace_read.cpp
  trace/trace_text.cpp
  trace/type_example.cpp
  trace/trace_compare.cpp
  trace/vocabulary.cpp
  trace/number_text.cpp
  trace/digits_alarm.cpp
  trace/intensity_formula.cpp
  trace/formula_numbers.cpp
  trace/messages.cpp
  trace/byte_size_text.cpp
  util/interrupt.cpp
  util/held_signals.cpp
  util/read_input.cpp
  util/printable.cpp
  # The lesson runner: the page shows lessons through it (web_export/wasm).
  lesson/lesson_parse.cpp
  lesson/lesson_check.cpp
  lesson/lesson_library.cpp
  lesson/lesson_render.cpp
  lesson/lesson_run.cpp
  lesson/lesson_html.cpp
  # Worksheets and the answer checker: the page's worksheet checks with them.
  lesson/worksheet.cpp
  lesson/answers_read.cpp
  lesson/answers_judge.cpp
  lesson/answers_run.cpp
  util/system_error_text.cpp
  util/atomic_file.cpp
)

# The command line's core only (not needed by the page's C API).
set(PROMYK_NATIVE_CORE_SOURCES
  render/pixel_selection.cpp
  render/scene_report.cpp
  render/trace_size.cpp
  lesson/trace_diff.cpp
  util/output_file.cpp
  util/standard_output.cpp
  image/image_writer.cpp
  image/png_writer.cpp
  image/netpbm_writer.cpp
  image/scaled_writer.cpp
  image/canvas.cpp
  image/bitmap_font.cpp
  image/framed_writer.cpp
  image/pane_labels.cpp
  image/legend.cpp
)

function(promyk_core_sources out src_dir)
  set(relative ${PROMYK_PORTABLE_SOURCES})
  if("NATIVE" IN_LIST ARGN)
    list(APPEND relative ${PROMYK_NATIVE_CORE_SOURCES})
  endif()
  set(paths "")
  foreach(file IN LISTS relative)
    list(APPEND paths "${src_dir}/${file}")
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()

# The embedded data (the vocabulary, lessons, messages, example scenes) as
# two generated sources in GENERATED_DIR, made the same way for both builds.
function(promyk_embedded_sources out root generated_dir)
  set(vocabulary "${root}/lessons/vocabulary.json")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${vocabulary}")
  file(READ "${vocabulary}" PROMYK_EMBEDDED_TEXT)
  set(PROMYK_EMBEDDED_NAME embedded_vocabulary_json)
  configure_file("${root}/cmake/embedded_text.cpp.in" "${generated_dir}/embedded_vocabulary.cpp" @ONLY)
  include("${root}/cmake/embed_files.cmake")
  file(GLOB lesson_files CONFIGURE_DEPENDS
       "${root}/lessons/*/*.md"
       "${root}/lessons/messages*.json"
       "${root}/lessons/scenes/*.json")
  list(SORT lesson_files)
  promyk_embed_files("${generated_dir}/embedded_lessons.cpp" lesson_files "${root}/lessons" ${lesson_files})
  set(${out} "${generated_dir}/embedded_vocabulary.cpp" "${generated_dir}/embedded_lessons.cpp" PARENT_SCOPE)
endfunction()

# The kernels: one translation unit per real type and formula, from
# render/kernel_instance.cpp.in. REAL_PAIRS are "id:C++ type" ("quad:quad").
function(promyk_kernel_sources out src_dir generated_dir)
  set(files "")
  foreach(real_pair IN LISTS ARGN)
    string(REPLACE ":" ";" real_pair "${real_pair}")
    list(GET real_pair 0 real_id)
    list(GET real_pair 1 PROMYK_KERNEL_REAL)
    foreach(PROMYK_KERNEL_FORMULA article stable fma geometric)
      set(kernel_file "${generated_dir}/kernel_${real_id}_${PROMYK_KERNEL_FORMULA}.cpp")
      configure_file("${src_dir}/render/kernel_instance.cpp.in" "${kernel_file}" @ONLY)
      list(APPEND files "${kernel_file}")
    endforeach()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()
