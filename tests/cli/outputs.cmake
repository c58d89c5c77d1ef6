# Outputs of `promyk render`: same-file refusals, standard output, plain PGM,
# --scale, the trace size guard. Included from tests/CMakeLists.txt, which
# defines promyk_cli_test. Cases that need files, links, devices or FIFOs set
# up beforehand are in outputs_test.sh.

# Two outputs that are one file: refused before anything is computed or created.
promyk_cli_test(render_same_file_dot ARGS render --w 8 -o x.png --traces ./x.png
                EXIT 2 STDERR "-o and --traces name the same file \\(x.png and ./x.png\\)" EMPTY)
promyk_cli_test(render_same_file_default ARGS render --w 8 --traces promyk.png
                EXIT 2 STDERR "same file" EMPTY)
promyk_cli_test(render_same_stdout ARGS render --w 8 -o - --traces -
                EXIT 2 STDERR "same file \\(standard output\\)" EMPTY)

# A directory as an output: exit 4 before computing, and the image is not committed.
promyk_cli_test(render_traces_directory ARGS render --w 8 -o x.png --traces .
                EXIT 4 STDERR "cannot write \\.: Is a directory" EMPTY)
promyk_cli_test(render_image_directory ARGS render --w 8 -o ./ --traces t.jsonl
                EXIT 4 STDERR "Is a directory" EMPTY)

# Traces to standard output: stdout carries the JSON Lines only, status goes to stderr.
promyk_cli_test(render_traces_stdout ARGS render --w 8 -o a.png --traces - --trace-pixel 3,4 --trace-pixel 0,0
                EXIT 0 FILES a.png STDOUT "^\\{\"schema\":1,[^\n]*\n\\{\"schema\":1,[^\n]*\n$"
                STDERR "wrote a.png \\(8 × 8 pixels, scene \"article\"\\)\nwrote traces to standard output \\(2 traces, [0-9.]+ kB\\)")
promyk_cli_test(render_png_stdout ARGS render --w 8 -o - EXIT 0 STDOUT "^.PNG" STDERR "wrote PNG to standard output" EMPTY)

# Plain PGM is P2; .pgm alone is binary P5; --plain needs .pgm.
promyk_cli_test(render_plain_pgm ARGS render --w 4 -o - --plain EXIT 2 STDERR "--plain" EMPTY)
promyk_cli_test(render_plain_with_png ARGS render --w 4 -o a.png --plain EXIT 2 STDERR "\\.pgm" EMPTY)
promyk_cli_test(render_help_pgm_forms ARGS render --help EXIT 0 STDOUT "binary PGM \\(P5.*plain PGM \\(P2")

# --scale and --grid: validated before anything is created.
promyk_cli_test(render_scale_zero ARGS render --w 8 --scale 0 EXIT 2 STDERR "--scale: expects a whole number from 1 to 32768, got 0" EMPTY)
promyk_cli_test(render_scale_too_big ARGS render --w 8 --scale 4097 EXIT 2 STDERR "between 1 and 4096 at --w 8" EMPTY)
promyk_cli_test(render_scale_grid_too_big ARGS render --w 8 --scale 4096 --grid
                EXIT 2 STDERR "between 1 and 4095 at --w 8 with --grid" EMPTY)
promyk_cli_test(render_grid_too_wide ARGS render --w 20000 --grid EXIT 2 STDERR "--grid at --w 20000" EMPTY)
promyk_cli_test(render_scale ARGS render --w 8 --scale 16 --grid -o s.png EXIT 0 FILES s.png
                STDERR "wrote s.png \\(135 × 135 pixels: the 8 × 8 pane at scale 16 with a grid, scene \"article\"\\)")

# A trace file above the trace limit (250 MB) needs --force or --max-trace-size; the estimate is in the message.
promyk_cli_test(render_traces_too_big ARGS render --w 2048 --traces t.jsonl
                EXIT 2 STDERR "--traces t.jsonl would take about [0-9.]+ GB \\(4194304 traces of about [0-9.]+ (B|kB) each\\), and the limit is 250 MB. add --max-trace-size [0-9]+ or --force" EMPTY)

# Everything that needs set-up: links, devices, FIFOs, /dev/full. No test here
# writes to a real device: as root, a promyk with the bugs these tests catch
# would replace /dev/null with a regular file.
add_test(NAME cli.outputs COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/outputs_test.sh $<TARGET_FILE:promyk>
                                  ${CMAKE_CURRENT_BINARY_DIR}/cli/outputs)
