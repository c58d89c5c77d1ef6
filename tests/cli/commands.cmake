# Command names, command-line values, the trace's text layout and the
# non-finite branch, as a user meets them. Included from tests/CMakeLists.txt.

# promyk help, and commands typed wrong
promyk_cli_test(help_command ARGS help EXIT 0 STDOUT "render.*trace.*bench.*Exit codes")
promyk_cli_test(help_command_render ARGS help render EXIT 0 STDOUT "Usage: promyk render")
promyk_cli_test(command_case ARGS Render EXIT 2 STDERR "^promyk: unknown command 'Render'; did you mean 'render'\\?")
promyk_cli_test(command_typo ARGS trcae EXIT 2 STDERR "did you mean 'trace'\\?")
promyk_cli_test(parse_error_prefix ARGS trace --bogus EXIT 2 STDERR "^promyk: .*--bogus.*Run 'promyk trace --help'")

# Numbers are plain decimal; each refusal names the option and the plain form.
promyk_cli_test(w_octal ARGS trace --w 010 EXIT 2 STDERR "^promyk: --w: .*plain decimal, got '010'; write 10\n")
promyk_cli_test(w_hex ARGS trace --w 0x10 EXIT 2 STDERR "got '0x10'; write 16\n")
promyk_cli_test(w_space ARGS trace --w " 16" EXIT 2 STDERR "got ' 16'; write 16\n")
promyk_cli_test(w_exponent ARGS render --w 1e3 EXIT 2 STDERR "from 1 to 32768 .*got '1e3'; write 1000" EMPTY)
promyk_cli_test(w_plus ARGS trace --w +8 EXIT 2 STDERR "got '\\+8'; write 8")
promyk_cli_test(threads_hex ARGS render --threads 0x2 EXIT 2 STDERR "--threads: .*got '0x2'; write 2" EMPTY)
promyk_cli_test(repetitions_zero ARGS bench speed --repetitions 0 EXIT 2 STDERR "--repetitions: .*from 1 to 1000, got 0")
promyk_cli_test(pixel_as_printed ARGS trace --pixel "3, 4" EXIT 0 STDOUT "^pixel \\(i, j\\) = \\(3, 4\\)")
promyk_cli_test(pixel_in_parentheses ARGS trace --pixel "(5, 1)" EXIT 0 STDOUT "branch: dark")
promyk_cli_test(pixel_octal ARGS trace --pixel 03,4 EXIT 2 STDERR "plain decimal\\), got '03,4'")
promyk_cli_test(pixel_three ARGS trace --pixel 1,2,3 EXIT 2 STDERR "--pixel expects I,J")

# The text layout fits 80 columns; --wide keeps one row a step.
promyk_cli_test(trace_wide ARGS trace --wide EXIT 0
                STDOUT "step +key +symbol +formula +value\n.*\n +5 +delta +Δ/4 +C² − \\|E\\|²·\\(\\|S\\|² − r²\\) +4.557812500000004\n")
promyk_cli_test(trace_grey_miss ARGS trace --pixel 0,0 EXIT 0 STDOUT "grey level: 128 of 255 = round\\(255 · I_P\\)")
promyk_cli_test(trace_a_7 ARGS trace --w 7 --pixel 3,3 EXIT 0 STDOUT "of a 7 × 7 pane")
promyk_cli_test(trace_an_11 ARGS trace --w 11 --pixel 3,3 EXIT 0 STDOUT "of an 11 × 11 pane")

# Overflow: accepted, traced to the first non-finite step, never a branch by NaN.
promyk_cli_test(trace_far_pane ARGS trace --scene ${scenes}/far_pane.json EXIT 0
                STDOUT "branch: non-finite.*first non-finite value: step 2, \\|E\\|² = inf")
promyk_cli_test(trace_far_centre ARGS trace --scene ${scenes}/far_centre.json --format json EXIT 0
                STDOUT "\"first_non_finite\":\\{\"index\":4,\"key\":\"delta\"\\},\"branch\":\"non-finite\",\"result\":null,\"result_text\":\"nan\"")

# Empty values are errors, not "none" (CMake lists cannot carry an empty argument).
add_test(NAME cli.empty_values COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/empty_values_test.sh $<TARGET_FILE:promyk>
                                       ${CMAKE_CURRENT_BINARY_DIR}/cli/empty_values)

# Input-derived text in messages is escaped (no raw control characters).
add_test(NAME cli.escapes COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/escapes_test.sh $<TARGET_FILE:promyk>
                                  ${CMAKE_CURRENT_BINARY_DIR}/cli/escapes)
promyk_cli_test(scene_nul ARGS trace --scene ${scenes}/nul_after_scene.json EXIT 3 STDERR "nul_after_scene.json: line")
promyk_cli_test(scene_two_boms ARGS trace --scene ${scenes}/two_byte_order_marks.json EXIT 3
                STDERR "two_byte_order_marks.json: line 1")

# The trace speaks the lesson's languages.
promyk_cli_test(trace_polish ARGS trace --lang pl EXIT 0
                STDOUT "^piksel \\(i, j\\) = \\(3, 4\\) szyby 8 × 8; scena „article” \\(wbudowana\\).*dane: z_E = 2; S = \\(0; 0; 3,2\\).*= 4,557812500000004\n.*gałąź: strona oświetlona — .*poziom szarości: 177 z 255")
promyk_cli_test(trace_explain ARGS trace --explain --lang en --pixel 0,0 EXIT 0
                STDOUT "delta +Δ/4 = C² − \\|E\\|²·\\(\\|S\\|² − r²\\)\n +the quadratic's discriminant divided by 4")
promyk_cli_test(trace_bad_lang ARGS trace --lang de EXIT 2 STDERR "--lang")

# Lessons
promyk_cli_test(lesson_list ARGS lesson --lang en EXIT 0 STDOUT "^Lessons \\(promyk lesson NAME\\):\n +vectors .*pane .*sphere .*lambert .*program ")
promyk_cli_test(lesson_list_polish ARGS lesson --list --lang pl EXIT 0 STDOUT "^Lekcje \\(promyk lesson NAZWA\\):")
promyk_cli_test(lesson_check ARGS lesson --check --lang en EXIT 0 STDOUT "lessons checked: 22; all is well")
promyk_cli_test(lesson_unknown ARGS lesson nosuch EXIT 2 STDERR "no lesson 'nosuch'. The lessons: vectors, pane, sphere, lambert, program, spheres, lights, planes, shadows, phong, precision")
promyk_cli_test(lesson_sphere ARGS lesson sphere --lang en --pixel 3,4 --pixel 0,0 EXIT 0
                STDOUT "^Lesson: .*pixels: \\(3, 4\\), \\(0, 0\\).*Step 1 of 7: .*Step 7 of 7")
promyk_cli_test(lesson_markdown ARGS lesson program --lang pl --format markdown EXIT 0
                STDOUT "^# Lekcja: .*\\| \\| piksel \\(0, 0\\) \\| piksel \\(5, 1\\) \\| piksel \\(3, 4\\) \\|.*<details><summary>Odpowiedź</summary>")
promyk_cli_test(lesson_pixel_outside ARGS lesson pane --pixel 8,0 EXIT 2 STDERR "outside the 8 × 8 pane")
promyk_cli_test(lesson_small_w ARGS lesson pane --w 4 EXIT 2 STDERR "the lesson's pixel \\(5, 1\\) is outside the 4 × 4 pane")
add_test(NAME cli.lesson_files COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/lesson_files_test.sh $<TARGET_FILE:promyk>
                                       ${CMAKE_CURRENT_BINARY_DIR}/cli/lesson_files)

# render finishes an overflowing scene, exits 0, and says how many pixels and which first.
promyk_cli_test(render_non_finite ARGS render --scene ${scenes}/far_pane.json --w 16 -o far.png EXIT 0 FILES far.png
                STDERR "warning: 256 of 256 pixels are non-finite.*the first is \\(0, 0\\): see promyk trace --pixel 0,0 --w 16 --scene")
promyk_cli_test(render_stats ARGS render --w 64 -o a.png --stats EXIT 0
                STDERR "stages: lambert\n  rays cast: 4096 primary \\(one a pixel\\), 0 shadow\n  intersection tests: 1972 ray-sphere, 0 ray-plane\n  background pixels skipped without a test \\(outside the sphere's outline in\n    their row, proven misses\\): 2124\n  pixels: 2380 miss, 342 dark, 1374 lit, 0 shadowed, 0 non-finite")

# promyk scene check and dump (more in scenes.cmake)
promyk_cli_test(scene_check_article ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/article.json EXIT 0
                STDOUT "article.json: a valid scene\ncontains:\n  - name \"article\", pane at z_E = 2, background 0.5\n  - 1 sphere, 0 planes, 1 light, 0 materials; shadows off\n  - sphere 0: S = \\(0, 0, 3.2\\), r = 1.1\n.*the engine runs.*  - article: the article's program and nothing else.*and skips:\n.*  - shadows: no shadow ray: the scene does not ask for shadows\n")
promyk_cli_test(scene_check_no_warning ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/article.json EXIT 0)
set_tests_properties(cli.scene_check_no_warning PROPERTIES FAIL_REGULAR_EXPRESSION "warnings")
promyk_cli_test(scene_check_light_inside ARGS scene check ${scenes}/light_inside.json EXIT 0 STDOUT "warnings.*light 0 is inside sphere 0")
promyk_cli_test(scene_check_off_view ARGS scene check ${scenes}/off_view.json EXIT 0 STDOUT "no pixel of a 64 × 64 pane sees sphere 0")
promyk_cli_test(scene_check_behind ARGS scene check ${scenes}/behind_eye.json EXIT 0 STDOUT "sphere 0 lies wholly behind the eye \\(z_S \\+ r <= 0\\) and is not drawn")
promyk_cli_test(scene_check_light_behind ARGS scene check ${scenes}/light_behind.json EXIT 0 STDOUT "no visible surface faces light 0")
promyk_cli_test(scene_check_far ARGS scene check ${scenes}/far_pane.json EXIT 0 STDOUT "4096 of 4096 pixels of a 64 × 64 pane are non-finite")
promyk_cli_test(scene_check_bad ARGS scene check ${scenes}/negative_radius.json EXIT 3 STDERR "negative_radius.json: /spheres/0/r")
promyk_cli_test(scene_check_missing ARGS scene check EXIT 2 STDERR "promyk scene check needs FILE")
promyk_cli_test(scene_no_kind ARGS scene EXIT 2)
# The dump is the committed article.json byte for byte (an independent text).
add_test(NAME cli.scene_dump
         COMMAND sh -c "\"$0\" scene dump | cmp - \"$1\"" $<TARGET_FILE:promyk> ${PROJECT_SOURCE_DIR}/lessons/scenes/article.json)

# The scene schema and the loader agree on every example and test scene.
file(GLOB promyk_scene_files ${PROJECT_SOURCE_DIR}/lessons/scenes/*.json ${PROJECT_SOURCE_DIR}/tests/reference/scenes/*.json
     ${scenes}/*.json)
list(FILTER promyk_scene_files EXCLUDE REGEX "scene\\.schema\\.json$")
# A sweep over every scene file (a promyk start per file, two minutes under
# AddressSanitizer): the release pass only, as the sweeps are.
if(NOT PROMYK_SANITIZE)
  add_test(NAME cli.scene_schema
           COMMAND ${PROMYK_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/cli/scene_schema_test.py $<TARGET_FILE:promyk>
                   ${PROJECT_SOURCE_DIR}/lessons/scenes/scene.schema.json ${promyk_scene_files})
endif()
promyk_cli_test(lesson_html ARGS lesson program --lang pl --format html EXIT 0
                STDOUT "^<header class=.lesson-head.>.<h1>Lekcja: .*<section class=.lesson-step. data-step=.1. .*<th scope=.col.>piksel \\(0, 0\\)</th>.*<details class=.answer. data-step=.[0-9]+.><summary>Odpowiedź</summary>")
# A worksheet in HTML: a labelled field a blank, the answers left out, the answer file's form at the end.
promyk_cli_test(lesson_html_worksheet ARGS lesson sphere --worksheet --format html --lang en EXIT 0
                STDOUT "^<header class=\"lesson-head\">.*<section class=\"worksheet-intro\">.*--answers ANSWERS.txt.*<input type=\"text\" id=\"blank-6\" [^>]*data-key=\"EE\" data-i=\"3\" data-j=\"4\"[^>]*><label for=\"blank-6\"><span aria-hidden=\"true\">\\(6\\)</span><span class=\"sr-only\">blank 6: \\|E\\|², pixel \\(3, 4\\)</span></label>.*<section class=\"worksheet-form\">.*\\[3,4\\]\nE = +# \\(3\\)"
                NOSTDOUT "<details|\\.\\.\\.\\.\\.\\.\\.\\.\\.\\.\\(6\\)</td>")
promyk_cli_test(lesson_html_worksheet_key ARGS lesson sphere --worksheet --key --format html --lang pl EXIT 0
                STDOUT "<label for=\"blank-1\"><span aria-hidden=\"true\">\\(1\\)</span><span class=\"sr-only\">miejsce 1: E, piksel \\(0, 0\\)</span>.*<section class=\"worksheet-key\">\n<h2>Klucz odpowiedzi \\(dla nauczyciela\\)</h2>\n<ul>\n<li>\\(1\\) piksel \\(0, 0\\): E = \\(−0,875; 0,875; 2\\)   \\[E\\]</li>")
