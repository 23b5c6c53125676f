#pragma once
/// @file Errors.h
/// @brief The error types of gridcar. Misuse (bad sizes, NaN, unknown names) throws
/// std::invalid_argument; these two are for bad files and bad user input.

#include <stdexcept>
#include <string>

namespace gridcar
{
/// Thrown for any file that cannot be read as what it claims to be. what() is
/// "<file>: <reason>", one line.
class MapLoadError : public std::runtime_error
{
public:
    MapLoadError(const std::string &file, const std::string &reason)
      : std::runtime_error(file + ": " + reason), file_(file), reason_(reason)
    {
    }
    const std::string &file() const { return file_; }
    const std::string &reason() const { return reason_; }

private:
    std::string file_, reason_;
};

/// Bad input from a user of a program (an argument, a problem file's value): reported on one
/// line; the gridcar program exits with status 2.
class InputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

}  // namespace gridcar
