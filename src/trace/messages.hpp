// The words promyk prints around lessons (headings, prompts, the checker's
// messages) in each language, from lessons/messages.json (embedded). Text is
// data: a translation is an edit of that file, not of the C++.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "trace/number_text.hpp"

namespace promyk {

using MessageArgs = std::vector<std::pair<std::string_view, std::string>>;

// The language of everything this run prints: errors, warnings, status
// lines and outputs (the global --lang; until it is set, LANG's choice).
// --help stays English.
Language ui_language();
void set_ui_language(Language language);

// message(ui_language(), id, args): the usual way to word an error or a
// status line.
std::string ui_message(std::string_view id, const MessageArgs& args = {});

// The message `id` in `language`, each {name} replaced by its argument.
// Throws std::logic_error for an id messages.json lacks (a bug, caught by tests).
std::string message(Language language, std::string_view id, const MessageArgs& args = {});

// The message `id` in `language` if messages.json has it (an optional
// override, e.g. a symbol in the lesson's language), else nothing.
std::optional<std::string> optional_message(Language language, std::string_view id);

// "3 traces", "3 ślady", "5 śladów": the message `id`_one, `id`_few or
// `id`_many of the run's language, chosen by Polish grammar (few: 2-4, 22-24,
// ... but not 12-14), with {n} the count. English's few is its many.
std::string counted(long long n, std::string_view id);

// A word a trace step holds (what an object's test found, the nearest
// object, a blocker) in `language`: "sphere 1" -> "kula 1", "far" -> the
// message word_far. A word messages.json does not know is returned as it is.
std::string word_text(Language language, std::string_view word);

// A group's title ("sphere 1", "light 0") in `language`.
std::string group_text(Language language, std::string_view kind, int index);

// Every message id, for tests: each must exist in every language.
std::vector<std::string> message_ids(Language language);

}  // namespace promyk
