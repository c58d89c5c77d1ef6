# Lessons on any pixel and any scene (a step's needs, guarded blocks, step
# mode's keys, a misspelt placeholder). Included from tests/CMakeLists.txt.
add_test(NAME cli.lesson_guards COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/lesson_guards_test.sh $<TARGET_FILE:promyk>
                                        ${CMAKE_CURRENT_BINARY_DIR}/cli/lesson_guards)
promyk_cli_test(lesson_shadows_on_article ARGS lesson shadows --scene ${PROJECT_SOURCE_DIR}/lessons/scenes/article.json --lang en
                EXIT 0 STDOUT "The scene \"article\" has no shadows, which this lesson is about: see its example\nscene, shadows.json")
