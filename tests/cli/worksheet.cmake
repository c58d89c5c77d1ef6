# promyk lesson --worksheet [--key] and --answers FILE, as a teacher and a
# student meet them. Included from tests/CMakeLists.txt.

promyk_cli_test(lesson_worksheet ARGS lesson sphere --worksheet --lang en EXIT 0
                STDOUT "^Lesson: .*Worksheet: .*--answers ANSWERS.txt.*\\(3, 4\\): \\.\\.\\.\\.\\.\\.\\.\\.\\.\\.\\(6\\)")
promyk_cli_test(lesson_worksheet_form ARGS lesson sphere --worksheet --lang en EXIT 0
                STDOUT "── The file ANSWERS.txt ──.*\\[3,4\\]\n +E = +# \\(3\\)\n +EE = +# \\(6\\) \\|E\\|²\n +SS = +# \\(12\\) \\|S\\|²\n +C = +# \\(9\\) E·S\n +delta = +# \\(15\\) Δ/4\n +Delta = +# \\(18\\) Δ\n")
promyk_cli_test(lesson_worksheet_key ARGS lesson sphere --worksheet --key --lang pl --format markdown EXIT 0
                STDOUT "## Klucz odpowiedzi \\(dla nauczyciela\\)\n\n- \\(1\\) piksel \\(0, 0\\): E = \\(−0,875; 0,875; 2\\)   \\[E\\]\n")
promyk_cli_test(lesson_key_alone ARGS lesson sphere --key EXIT 2 STDERR "--key needs --worksheet")
promyk_cli_test(lesson_answers_and_worksheet ARGS lesson sphere --worksheet --answers a.txt EXIT 2 STDERR "--worksheet cannot be used together with --answers")
promyk_cli_test(lesson_answers_missing ARGS lesson sphere --answers missing.txt EXIT 3 STDERR "missing.txt: cannot read")

# Files a student writes: right, wrong, malformed, JSON.
add_test(NAME cli.worksheet_answers COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/worksheet_test.sh $<TARGET_FILE:promyk>
                                            ${CMAKE_CURRENT_BINARY_DIR}/cli/worksheet_answers)

# A bad line is one unreadable answer (exit 1, the rest checked); a file with no readable answer is refused (exit 3).
promyk_cli_test(lesson_answers_unreadable ARGS lesson sphere --lang en
                --answers ${CMAKE_CURRENT_SOURCE_DIR}/cli/lesson/answers_mixed.txt EXIT 1
                STDOUT "✓ E·S \\(C\\) = 6,4: right.*✗ line 4: detla = 4,5578: unreadable: unknown key 'detla';.*'delta'\\?.*Unreadable: 3\\.")
promyk_cli_test(lesson_answers_nothing_readable ARGS lesson sphere --lang pl
                --answers ${CMAKE_CURRENT_SOURCE_DIR}/cli/lesson/answers_typos.txt EXIT 3
                STDERR "answers_typos.txt: linia 2: nieznany klucz „detla”; czy chodziło o „delta”\\?.*w pliku nie ma żadnej czytelnej odpowiedzi")
