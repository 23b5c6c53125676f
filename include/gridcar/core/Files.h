#pragma once
/// @file Files.h
/// @brief Checks before a reader opens a file, so that a directory, a missing file or an
/// over-long name is reported as bad input (MapLoadError naming the file), never as an
/// internal error from a stream library.

#include <string>

namespace gridcar
{
/// Throws MapLoadError(@p path, reason) unless @p path names a regular file that can be opened
/// for reading; @p what says what the file should be ("map file", "vehicle file", ...).
void requireReadableFile(const std::string &path, const std::string &what);

}  // namespace gridcar
