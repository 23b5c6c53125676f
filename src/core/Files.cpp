#include "gridcar/core/Files.h"

#include "gridcar/core/Errors.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace gridcar
{
void requireReadableFile(const std::string &path, const std::string &what)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec)
        throw MapLoadError(path, "cannot open the " + what + " (" +
                                     (ec == std::errc::no_such_file_or_directory ? std::string("no such file") : ec.message()) + ")");
    if (fs::is_directory(st)) throw MapLoadError(path, "is a directory, not a " + what);
    if (!fs::is_regular_file(st)) throw MapLoadError(path, "is not a regular file, not a " + what);
    std::ifstream f(path, std::ios::binary);
    if (!f) throw MapLoadError(path, "cannot open the " + what + " (" + std::strerror(errno) + ")");
}

}  // namespace gridcar
