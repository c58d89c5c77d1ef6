// Why the system refused (an errno value) in the run's language: the C
// library words it in English only, so the common reasons are messages
// (lessons/messages_status.json, system_error_*); others keep the C
// library's English in English and give their number in Polish.
#pragma once

#include <string>
#include <system_error>

namespace promyk {

std::string system_error_text(int err);
std::string system_error_text(const std::error_code& error);

// errno after a stdio call that may fail without setting it (EIO then).
int errno_or_eio();

}  // namespace promyk
