# The scene format as it grew (planes, materials, colours, shadows): a bad
# scene is refused with exit 3 and the pointer of its fault; a legal but
# surprising one is accepted with a warning; scene check names the stages.
# Included from tests/CMakeLists.txt, after commands.cmake (${scenes}).

# Each bad fixture: exit 3, the file, the JSON pointer and the key words.
promyk_cli_test(scene_zero_normal ARGS scene check ${scenes}/zero_normal.json EXIT 3
                STDERR "zero_normal.json: /planes/0/n: n \\(the plane's normal\\) must not be the zero vector")
promyk_cli_test(scene_missing_material ARGS scene check ${scenes}/missing_material.json EXIT 3
                STDERR "/spheres/0/material: material 2 does not exist: the scene has 2 materials \\(0 and 1\\)")
promyk_cli_test(scene_fractional_exponent ARGS scene check ${scenes}/fractional_exponent.json EXIT 3
                STDERR "/materials/0/exponent: .*whole number from 1 to 10000, got 2.5")
promyk_cli_test(scene_background_out_of_range ARGS scene check ${scenes}/background_out_of_range.json EXIT 3
                STDERR "/background/0: background\\[0\\] \\(red\\) must be between 0 and 1, got 2")
promyk_cli_test(scene_light_colour_two ARGS scene check ${scenes}/light_colour_two.json EXIT 3
                STDERR "/lights/0/colour: colour must be an array of 3 numbers \\[r, g, b\\].*got 2 elements")
promyk_cli_test(scene_shadows_yes ARGS scene check ${scenes}/shadows_yes.json EXIT 3
                STDERR "/shadows: shadows must be true or false, got a string")
promyk_cli_test(scene_no_objects ARGS scene check ${scenes}/no_objects.json EXIT 3
                STDERR "/spheres: the scene has no objects")
promyk_cli_test(scene_negative_diffuse ARGS scene check ${scenes}/negative_diffuse.json EXIT 3
                STDERR "/materials/0/diffuse: diffuse .* must be >= 0, got -0.5")
promyk_cli_test(scene_shininess ARGS scene check ${scenes}/shininess.json EXIT 3
                STDERR "/materials/0/shininess: unknown key 'shininess'; did you mean 'exponent'\\?")
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
                STDOUT "3 spheres, 1 plane, 2 lights, 4 materials; shadows on\n.*plane 0: Q = \\(0, -1.1, 0\\), n = \\(0, 1, 0\\), material 3\n.*the engine runs.*  - nearest: .*every object is tested; the nearest hit wins\n.*  - shadows: .*  - phong: .*  - colour: ")
promyk_cli_test(scene_check_floor ARGS scene check ${PROJECT_SOURCE_DIR}/lessons/scenes/floor.json EXIT 0
                STDOUT "  - plane: t = .*and skips:\n  - ambient: .*  - shadows: no shadow ray: the scene does not ask for shadows\n  - phong: .*  - colour: one channel")
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
