# Hostile input on promyk lesson's files: a teacher's folder, a student's
# answers, --dump. Included from tests/CMakeLists.txt.
add_test(NAME cli.hostile_lessons COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_lessons_test.sh $<TARGET_FILE:promyk>
                                          ${CMAKE_CURRENT_BINARY_DIR}/cli/hostile_lessons)
