# render --labels, --legend and --range (tests/image_frame_test.cpp checks the pixels).
# Each test fixes the language through LC_ALL: the messages are the run's language's.
function(promyk_cli_test_in language name)
  # Forwarded through PARSE_ARGV so that a ';' inside a regex survives (see promyk_cli_test).
  cmake_parse_arguments(PARSE_ARGV 2 W "" "" "")
  promyk_cli_test(${name} ${W_UNPARSED_ARGUMENTS})
  set(locale C)
  if(language STREQUAL "pl")
    set(locale pl_PL.UTF-8)
  endif()
  set_tests_properties(cli.${name} PROPERTIES ENVIRONMENT "LC_ALL=${locale}")
endfunction()

# --labels: the image grows by the margins (left: the widest row number; top: a line of digits).
promyk_cli_test_in(en render_labels ARGS render --w 8 --scale 40 --grid --labels -o l.png EXIT 0 FILES l.png
                   STDERR "wrote l.png \\(345 × 349 pixels: the 8 × 8 pane at scale 40 with a grid")
promyk_cli_test_in(en render_labels_unscaled ARGS render --w 64 --labels -o l.png EXIT 0 FILES l.png
                   STDERR "wrote l.png \\(79 × 75 pixels: the 64 × 64 pane at scale 1")
promyk_cli_test_in(en render_labels_help ARGS render --help EXIT 0
                   STDOUT "--labels +Number the rows.*every k-th row and column is numbered")

# --legend: below the map, as wide as the image; a too narrow image is refused before anything is written.
promyk_cli_test_in(en render_legend_branch ARGS render --map branch --w 8 --scale 40 --labels --legend -o b.png
                   EXIT 0 FILES b.png STDERR "wrote b.png \\(branch map, 338 × 414 pixels")
promyk_cli_test_in(pl render_legend_error_polish ARGS render --map error --real float --w 32 --scale 8 --legend
                   -o e.png --stats EXIT 0 FILES e.png STDERR "zakres skali: 1e−[0-9]+ … 1e−[0-9]+ \\(własny zakres przebiegu, w pełnych dekadach\\)")
promyk_cli_test_in(en render_legend_without_map ARGS render --w 8 --legend EXIT 2 EMPTY
                   STDERR "--legend explains a map: it works with --map branch\\|error\\|digits-lost only")
promyk_cli_test_in(en render_legend_too_narrow ARGS render --map branch --w 64 --legend EXIT 2 EMPTY
                   STDERR "--legend: the image is 64 px wide and the legend needs 97 px \\(for[ \n]+\"behind the eye\"\\). use --scale 2 or more")
promyk_cli_test_in(pl render_legend_too_narrow_polish ARGS render --map branch --w 64 --legend EXIT 2 EMPTY
                   STDERR "--legend: obraz ma 64 px szerokości, a legenda potrzebuje 133 px[ \n]+\\(dla[ \n]+„wartość nieskończona”\\). użyj --scale 3 lub większego")
promyk_cli_test_in(en render_legend_too_narrow_deferred ARGS render --map error --w 16 --legend EXIT 2 EMPTY
                   STDERR "use --scale [0-9]+ or more")

# --range: fixes the error map's scale; validated before anything is created.
promyk_cli_test_in(en render_range_stats ARGS render --map error --real float --w 16 --range 1e-12,1e-4 --stats -o e.png
                   EXIT 0 FILES e.png STDERR "  1e[^ ]+10 to 1e[^ ]+09: .*  scale: 1e[^ ]+12 … 0.0001 \\(from --range\\)\n$")
foreach(bad "0,1" "1e-10,1e-12" "1e-10,1e-10" "-1,1" "nan,1" "1,inf" "1e-10" "1e-10,1e-5,1" "a,b" "1e-10, 1e-5")
  string(MAKE_C_IDENTIFIER "${bad}" id)
  promyk_cli_test_in(en render_range_bad_${id} ARGS render --map error --w 8 --range "${bad}" EXIT 2 EMPTY
                     STDERR "--range expects LO,HI, two finite numbers with 0 < LO < HI")
endforeach()
promyk_cli_test_in(pl render_range_bad_polish ARGS render --map error --w 8 --range 2,1 EXIT 2 EMPTY
                   STDERR "--range oczekuje LO,HI, dwóch skończonych liczb, gdzie 0 < LO < HI .*podano „2,1”")
promyk_cli_test_in(en render_range_without_error_map ARGS render --map branch --w 8 --range 1e-10,1e-5 EXIT 2 EMPTY
                   STDERR "--range sets the error map's scale: it works with --map error only")
promyk_cli_test_in(en render_range_needed ARGS render --map error --w 5000 EXIT 2 EMPTY
                   STDERR "--map error at --w 5000 needs --range LO,HI")
