#include "util/system_error_text.hpp"

#include <cerrno>
#include <utility>

#include "trace/messages.hpp"

namespace promyk {

std::string system_error_text(int err) {
    static const std::pair<int, const char*> known[] = {
        {ENOENT, "ENOENT"}, {EACCES, "EACCES"},   {EPERM, "EPERM"},   {EISDIR, "EISDIR"},
        {ENOTDIR, "ENOTDIR"}, {ENOSPC, "ENOSPC"}, {EROFS, "EROFS"},   {ELOOP, "ELOOP"},
        {EEXIST, "EEXIST"}, {EIO, "EIO"},         {ENAMETOOLONG, "ENAMETOOLONG"},
        {EDQUOT, "EDQUOT"}, {EFBIG, "EFBIG"},     {EMFILE, "EMFILE"}, {ENOTEMPTY, "ENOTEMPTY"},
        {EBUSY, "EBUSY"},   {ENXIO, "ENXIO"},     {EINVAL, "EINVAL"},
    };
    for (const auto& [number, name] : known)
        if (number == err) return ui_message(std::string("system_error_") + name);
    return ui_message("system_error_other",
                      {{"text", std::generic_category().message(err)}, {"code", std::to_string(err)}});
}

int errno_or_eio() { return errno != 0 ? errno : EIO; }

std::string system_error_text(const std::error_code& error) {
    // std::filesystem reports errno values (generic or system category on POSIX).
    if (error.category() == std::generic_category() || error.category() == std::system_category())
        return system_error_text(error.value());
    return error.message();
}

}  // namespace promyk
