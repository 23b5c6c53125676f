#pragma once
/// @file Errors.h
/// @brief The error types of gridcar. Misuse (bad sizes, NaN, unknown names) throws
/// std::invalid_argument; these two are for bad files and bad user input.

#include <stdexcept>
#include <string>

namespace gridcar
{
/// @p text for an error message: control and non-ASCII bytes as \xNN, at most @p max
/// characters (a hostile file must not write raw bytes to a terminal).
inline std::string printable(const std::string &text, std::size_t max = 80)
{
    static const char *hex = "0123456789abcdef";
    std::string out;
    for (unsigned char c : text)
    {
        if (out.size() >= max)
        {
            out += "...";
            break;
        }
        if (c >= 0x20 && c < 0x7f)
            out += char(c);
        else
            out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
    return out;
}

/// Longest message of gridcar's error types (a message is one printable line).
constexpr std::size_t kMaxErrorMessage = 2000;

/// Thrown for any file that cannot be read as what it claims to be. what() is
/// "<file>: <reason>", one printable line (control and non-ASCII bytes as \xNN, whatever a
/// library's message about a hostile file echoes).
class MapLoadError : public std::runtime_error
{
public:
    MapLoadError(const std::string &file, const std::string &reason)
      : std::runtime_error(printable(file + ": " + reason, kMaxErrorMessage)), file_(file), reason_(reason)
    {
    }
    const std::string &file() const { return file_; }
    const std::string &reason() const { return reason_; }

private:
    std::string file_, reason_;
};

/// Bad input from a user of a program (an argument, a problem file's value): reported on one
/// printable line; the gridcar program exits with status 2.
class InputError : public std::runtime_error
{
public:
    explicit InputError(const std::string &message) : std::runtime_error(printable(message, kMaxErrorMessage)) {}
};

}  // namespace gridcar
