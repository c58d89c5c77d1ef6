# The scene format as it grew (planes, materials, colours, shadows): a bad
# scene is refused with exit 3 and the pointer of its fault; a legal but
# surprising one is accepted with a warning; scene check names the stages.
# Included from tests/CMakeLists.txt, after commands.cmake (${scenes}).

# Each bad fixture: exit 3, then "FILE: POINTER: message" on stderr.
function(promyk_bad_scene fixture expected)
  promyk_cli_test(scene_${fixture} ARGS scene check ${scenes}/${fixture}.json EXIT 3
                  STDERR "${fixture}.json: ${expected}")
endfunction()
promyk_bad_scene(zero_normal "/planes/0/n: n \\(the plane's normal\\) must not be the zero vector")
promyk_bad_scene(missing_material
                 "/spheres/0/material: material 2 does not exist: the scene has 2 materials \\(0 and 1\\)")
promyk_bad_scene(fractional_exponent "/materials/0/exponent: .*whole number from 1 to 10000, got 2.5")
promyk_bad_scene(background_out_of_range "/background/0: background\\[0\\] \\(red\\) must be between 0 and 1, got 2")
promyk_bad_scene(light_colour_two "/lights/0/colour: colour must be an array of 3 numbers \\[r, g, b\\].*got 2 elements")
promyk_bad_scene(shadows_yes "/shadows: shadows must be true or false, got a string")
promyk_bad_scene(no_objects "/spheres: the scene has no objects")
promyk_bad_scene(negative_diffuse "/materials/0/diffuse: diffuse .* must be >= 0, got -0.5")
promyk_bad_scene(shininess "/materials/0/shininess: unknown key 'shininess'; did you mean 'exponent'\\?")
# The loader refuses a scene before any command uses it.
promyk_cli_test(render_zero_normal ARGS render --scene ${scenes}/zero_normal.json --w 8 EXIT 3
                STDERR "/planes/0/n" EMPTY)

# Legal, but surprising: accepted (exit 0) with a warning.
promyk_cli_test(scene_check_eye_inside ARGS scene check ${scenes}/eye_inside.json EXIT 0
                STDOUT "warnings.*the eye is inside sphere 0 \\(\\|S\\|² − r² < 0\\): it sees the sphere's inside")
promyk_cli_test(scene_check_eye_in_plane ARGS scene check ${scenes}/eye_in_plane.json EXIT 0
                STDOUT "the eye lies in plane 0 \\(n̂·Q = 0\\): the plane is seen edge-on")
promyk_cli_test(scene_check_plane_behind ARGS scene check ${scenes}/plane_behind.json EXIT 0
                STDOUT "plane 0 is outside the pane's view")
promyk_cli_test(scene_check_hidden ARGS scene check ${scenes}/hidden_sphere.json EXIT 0
                STDOUT "no pixel of a 64 × 64 pane sees sphere 1: .*hidden behind another object.*no visible surface faces light 1")

# The stages: what runs, what is skipped and why.
promyk_cli_test(scene_check_everything ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/everything.json EXIT 0
                STDOUT "3 spheres, 1 plane, 2 lights, 4 materials. shadows on\n.*plane 0: Q = \\(0, −1.1, 0\\), n = \\(0, 1, 0\\), material 3\n.*the engine runs.*  - nearest: .*every object is tested; the nearest hit wins .*  - shadows: .*  - phong: .*  - colour: ")
# In Polish, every word and number of the report is Polish: decimal commas,
# ';' between a point's coordinates (CMake splits a regex at ';': '.' stands for it).
promyk_cli_test(scene_check_everything_polish ARGS --lang pl scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/everything.json EXIT 0
                STDOUT "3 kule, 1 płaszczyzna, 2 światła, 4 materiały. cienie włączone\n  - kula 0: S = \\(−0,6. −0,3. 3,4\\). r = 0,8. materiał 0\n.*  - materiał 0: otoczenie 0,1. rozproszenie 0,8. odblask 0,4. wykładnik 30. *\n? *barwa .*\\(najmniejsze t > 0. przy remisie wygrywa wcześniejszy obiekt\\)"
                NOSTDOUT "sphere [0-9]|material [0-9]|background|shadows on|for each|a miss|[0-9]\\.[0-9]")
promyk_cli_test(scene_check_floor ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/floor.json EXIT 0
                STDOUT "  - plane: the ray is intersected with every plane \\(t = .*and skips:\n  - ambient: .*  - shadows: no shadow ray: the scene does not ask for shadows\n  - phong: .*  - colour: one channel")
foreach(name floor everything colour phong shadows two_lights two_spheres)
  promyk_cli_test(scene_check_${name}_no_warning ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/${name}.json EXIT 0)
  set_tests_properties(cli.scene_check_${name}_no_warning PROPERTIES FAIL_REGULAR_EXPRESSION "warnings")
endforeach()

# scene dump --all: every knob, with its default.
promyk_cli_test(scene_dump_all ARGS scene dump --all EXIT 0
                STDOUT "^\\{\n  \"name\": \"article\",\n  \"z_E\": 2,\n  \"background\": 0.5,\n  \"shadows\": false,\n  \"spheres\": \\[\n    \\{\"S\": \\[0, 0, 3.2\\], \"r\": 1.1\\}\n  \\],\n  \"planes\": \\[\\],\n  \"lights\": \\[\n    \\{\"L\": \\[1.5, 1, 1\\], \"I\": 1, \"colour\": \\[1, 1, 1\\]\\}\n  \\],\n  \"materials\": \\[\\]\n\\}\n$")
promyk_cli_test(scene_dump_help ARGS scene dump --help EXIT 0 STDOUT "--all.*\"shadows\": false")
# A scene file written in the canonical form is dumped back byte for byte.
add_test(NAME cli.scene_dump_everything
         COMMAND sh -c "\"$0\" scene dump --scene \"$1\" | \"$0\" scene dump --scene /dev/stdin | cmp - \"$2\""
                 $<TARGET_FILE:promyk> ${PROJECT_SOURCE_DIR}/lessons/scenes/everything.json
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/everything_canonical.json)
