# The command line's errors (issue 14): names only for enumerated options,
# "did you mean" for typos, CLI11's errors reworded with the right command
# path, --lang and --digits as options of every command, pixels' ranges, and
# a scene's faults all in one run. Included from tests/CMakeLists.txt.
# (A ';' in a pattern would split CMake's list: '.' stands for it.)

# Enumerated options take names only; a typo gets the name probably meant.
promyk_cli_test(real_number_refused ARGS trace --real 0 EXIT 2
                STDERR "promyk: unknown value '0' for --real. the values are float, double, long-double, quad\nRun 'promyk trace --help' for the options.\n$")
promyk_cli_test(real_typo ARGS trace --real flaot EXIT 2
                STDERR "unknown value 'flaot' for --real. did you mean 'float'\\? \\(float, double, long-double, quad\\)")
promyk_cli_test(formula_typo ARGS render --formula stabel EXIT 2 EMPTY
                STDERR "unknown value 'stabel' for --formula. did you mean 'stable'\\?")
promyk_cli_test(format_typo ARGS trace --format JSON EXIT 2 STDERR "unknown value 'JSON' for --format. did you mean 'json'\\?")
promyk_cli_test(diff_format_typo ARGS diff a b --format jsn EXIT 2 STDERR "did you mean 'json'\\?")
promyk_cli_test(lang_unknown ARGS trace --lang english EXIT 2 STDERR "unknown value 'english' for --lang. the values are pl, en")
promyk_cli_test(compare_typo ARGS trace --compare float,dobule EXIT 2 STDERR "unknown value 'dobule' for --compare. did you mean 'double'\\?")
# Help shows the names, not CLI11's internals.
promyk_cli_test(trace_help_names ARGS trace --help EXIT 0
                STDOUT "--real float\\|double\\|long-double\\|quad.*--formula article\\|stable\\|fma\\|geometric.*--format text\\|json.*--lang pl\\|en.*--digits N"
                NOSTDOUT "->|TYPE:|OR \\{")
promyk_cli_test(diff_help_no_repeat ARGS diff --help EXIT 0 STDOUT "--tol" NOSTDOUT "A A|B B|REQUIRED")
promyk_cli_test(scene_help_path ARGS scene --help EXIT 0 STDOUT "Run 'promyk scene COMMAND --help'"
                NOSTDOUT "promyk COMMAND")
promyk_cli_test(bench_help_path ARGS bench --help EXIT 0 STDOUT "Run 'promyk bench COMMAND --help'"
                NOSTDOUT "promyk COMMAND")
promyk_cli_test(top_help_lang ARGS --help EXIT 0 STDOUT "--lang pl\\|en.*--help is always in English")

# CLI11's errors in promyk's words, with the command they belong to.
promyk_cli_test(unknown_option_suggested ARGS trace --pixle 3,4 EXIT 2
                STDERR "^promyk: unknown option '--pixle' for promyk trace. did you mean '--pixel'\\?\nRun 'promyk trace --help' for the options.\n$")
promyk_cli_test(unknown_option ARGS render --zzzzzz EXIT 2 STDERR "unknown option '--zzzzzz' for promyk render\n")
promyk_cli_test(extra_argument ARGS trace extra EXIT 2 STDERR "unexpected argument 'extra' for promyk trace")
promyk_cli_test(missing_value ARGS trace --w EXIT 2 STDERR "^promyk: --w needs a value\n")
promyk_cli_test(scene_check_needs_file ARGS scene check EXIT 2
                STDERR "promyk scene check needs FILE\nRun 'promyk scene check --help' for the options.\n$")
promyk_cli_test(scene_needs_command ARGS scene EXIT 2
                STDERR "promyk scene needs a command: check, dump\nRun 'promyk scene --help' for the options.")
promyk_cli_test(scene_check_usage_path ARGS scene check a b EXIT 2 STDERR "Run 'promyk scene check --help' for the options.")
promyk_cli_test(diff_needs_a ARGS diff EXIT 2 STDERR "promyk diff needs A")
promyk_cli_test(excludes ARGS trace --compare float,quad --real quad EXIT 2
                STDERR "--compare cannot be used together with --real|--real cannot be used together with --compare")
promyk_cli_test(tol_not_a_number ARGS diff a b --tol abc EXIT 2 STDERR "--tol expects a number, got 'abc'")

# --lang and --digits: before or after the command's name; the errors of
# the command line and of a scene in the chosen language.
promyk_cli_test(lang_pl_before ARGS --lang pl trace --pixle 3,4 EXIT 2
                STDERR "nieznana opcja '--pixle' polecenia promyk trace. czy chodziło o '--pixel'\\?\nOpcje polecenia pokaże 'promyk trace --help'.")
promyk_cli_test(lang_pl_after ARGS trace --pixel 9,0 --lang=pl EXIT 2 STDERR "leży poza szybą 8 × 8")
promyk_cli_test(lang_pl_scene ARGS trace --lang pl --scene ${scenes}/zero_normal.json EXIT 3
                STDERR "zero_normal.json: /planes/0/n: n \\(wektor normalny płaszczyzny\\) nie może być wektorem zerowym")
promyk_cli_test(lang_pl_real ARGS render --real flaot --lang pl EXIT 2 EMPTY
                STDERR "nieznana wartość 'flaot' opcji --real. czy chodziło o 'float'\\?")
promyk_cli_test(lang_en_text ARGS trace --lang en EXIT 0 STDOUT "branch: lit")
promyk_cli_test(digits_zero ARGS trace --digits 0 EXIT 2 STDERR "--digits expects a whole number from 1 to 40, got 0")
promyk_cli_test(digits_missing ARGS trace --digits EXIT 2 STDERR "--digits needs a value")
promyk_cli_test(digits_accepted ARGS --digits 5 trace --digits=40 EXIT 0 STDOUT "branch")

# Pixels: beyond the largest pane is exit 2 with the range (not an internal
# error), everywhere a pixel is read; outside the pane names the --w it fits.
promyk_cli_test(pixel_2_31 ARGS trace --pixel 2147483648,0 EXIT 2
                STDERR "--pixel expects I,J .*: numbers from 0 to 32767 .*got '2147483648,0'")
promyk_cli_test(pixel_huge ARGS trace --pixel 0,99999999999999999999 EXIT 2 STDERR "numbers from 0 to 32767")
promyk_cli_test(pixel_negative_huge ARGS trace --pixel -99999999999,0 EXIT 2 STDERR "numbers from 0 to 32767")
promyk_cli_test(trace_pixel_2_31 ARGS render --w 8 --traces t.jsonl --trace-pixel 2147483648,0 EXIT 2 EMPTY
                STDERR "--trace-pixel expects .*numbers from 0 to 32767")
promyk_cli_test(trace_region_2_31 ARGS render --w 8 --traces t.jsonl --trace-region 0,0,2147483648,1 EXIT 2 EMPTY
                STDERR "--trace-region expects .*numbers from 0 to 32767")
promyk_cli_test(lesson_pixel_2_31 ARGS lesson sphere --pixel 2147483648,1 EXIT 2 STDERR "--pixel expects .*numbers from 0 to 32767")
promyk_cli_test(pixel_outside_names_w ARGS trace --pixel 200,300 EXIT 2
                STDERR "--pixel \\(200, 300\\) is outside the 8 × 8 pane. it is in a pane of w ≥ 301: add --w 512 \\(render's default\\) or --w 301")
promyk_cli_test(pixel_outside_large ARGS trace --pixel 600,3 EXIT 2
                STDERR "--pixel \\(600, 3\\) is outside the 8 × 8 pane. it is in a pane of w ≥ 601: add --w 601\n")
promyk_cli_test(pixel_outside_render ARGS render --w 512 --traces t.jsonl --trace-pixel 512,0 EXIT 2 EMPTY
                STDERR "--trace-pixel \\(512, 0\\) is outside the 512 × 512 pane. it is in a pane of w ≥ 513: add --w 513\n")
promyk_cli_test(pixel_outside_fits ARGS trace --pixel 200,300 --w 301 EXIT 0 STDOUT "branch")

# A scene's faults, all in one run, in document order; at most 20 and a count.
promyk_cli_test(scene_three_mistakes ARGS scene check ${scenes}/three_mistakes.json EXIT 3
                STDERR "^promyk: [^\n]*three_mistakes.json: /z_E: z_E [^\n]*> 0, got -1\npromyk: [^\n]*three_mistakes.json: /spheres/0/r: r [^\n]*> 0, got -1.1\npromyk: [^\n]*three_mistakes.json: /lights/0/I: I [^\n]*>= 0, got -1\n$")
promyk_cli_test(scene_twenty_five_mistakes ARGS scene check ${scenes}/twenty_five_mistakes.json EXIT 3
                STDERR "/spheres/0/r: .*/spheres/19/r: [^\n]*\npromyk: [^\n]*twenty_five_mistakes.json: and 5 more\n$")
set_tests_properties(cli.scene_twenty_five_mistakes PROPERTIES FAIL_REGULAR_EXPRESSION "/spheres/20/r")
promyk_cli_test(render_three_mistakes ARGS render --scene ${scenes}/three_mistakes.json --w 8 EXIT 3 EMPTY
                STDERR "/z_E: .*/spheres/0/r: .*/lights/0/I: ")
# A scene check's warnings are also render's, on stderr.
promyk_cli_test(render_light_inside_warns ARGS render --scene ${scenes}/light_inside.json --w 8 -o i.png EXIT 0
                FILES i.png STDOUT "^$" STDERR "promyk: warning: light 0 is inside sphere 0: no point of the sphere's outside faces it")
promyk_cli_test(render_light_inside_warns_pl ARGS render --lang pl --scene ${scenes}/light_inside.json --w 8 -o i.png EXIT 0
                STDOUT "^$" STDERR "promyk: ostrzeżenie: światło 0 jest wewnątrz kuli 0")
# A scene legal in double but too small for float's unit vectors: a float
# trace (or a comparison with float) says why beside it; a double one is quiet.
promyk_cli_test(trace_float_tiny_warns ARGS trace --scene ${scenes}/tiny_for_float.json --pixel 4,4 --real float EXIT 0
                STDOUT "numbers: float, formula: article" STDERR "^promyk: warning: the smallest number other than 0 in the scene is 1e-20 \\(/lights/0/L/1\\): in float")
promyk_cli_test(trace_float_tiny_compare_warns ARGS trace --scene ${scenes}/tiny_for_float.json --pixel 4,4 --compare float,quad
                EXIT 0 STDERR "in float \\(--real float\\) the squares of lengths this small")
promyk_cli_test(trace_float_tiny_pl ARGS trace --lang pl --scene ${scenes}/tiny_for_float.json --pixel 4,4 --real float EXIT 0
                STDERR "^promyk: ostrzeżenie: ")
promyk_cli_test(trace_double_tiny_quiet ARGS trace --scene ${scenes}/tiny_for_float.json --pixel 4,4 EXIT 0 STDERR "^$")
promyk_cli_test(render_no_warning ARGS render --scene ${PROJECT_SOURCE_DIR}/lessons/scenes/everything.json --w 8 -o i.png
                EXIT 0)
set_tests_properties(cli.render_no_warning PROPERTIES FAIL_REGULAR_EXPRESSION "warning")
