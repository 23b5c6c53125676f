/// @file Settings.cpp
/// @brief The parsers of the settings tables (Settings.h).
#include "gridcar/planners/Settings.h"

#include "gridcar/core/Errors.h"

#include <ompl/util/String.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gridcar::settings
{
namespace
{
[[noreturn]] void refuse(const std::string &name, const std::string &value, const std::string &what)
{
    throw std::invalid_argument(name + " must be " + what + ", got '" + printable(value) + "'");
}

/// True if a number read from @p value ended at @p end with nothing but blanks after it.
bool readWhole(const std::string &value, const char *end)
{
    const char *s = value.c_str();
    return end != s && std::all_of(end, s + value.size(), [](char c) { return std::isspace((unsigned char)c) != 0; });
}
}  // namespace

double real(const std::string &name, const std::string &value, double lo, double hi, const std::string &what)
{
    const char *s = value.c_str();
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(s, &end);
    if (!readWhole(value, end) || errno == ERANGE || !std::isfinite(v) || v < lo || v > hi) refuse(name, value, what);
    return v;
}

int integer(const std::string &name, const std::string &value, std::initializer_list<int> allowed, const std::string &what)
{
    const char *s = value.c_str();
    char *end = nullptr;
    errno = 0;
    const long v = std::strtol(s, &end, 10);
    if (!readWhole(value, end) || errno == ERANGE || std::find(allowed.begin(), allowed.end(), v) == allowed.end())
        refuse(name, value, what);
    return int(v);
}

std::string switchWord(const std::string &value)
{
    std::string v = value;
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (v == "1" || v == "true" || v == "on") return "on";
    if (v == "0" || v == "false" || v == "off") return "off";
    return v;
}

bool onOff(const std::string &name, const std::string &value)
{
    const std::string w = switchWord(value);
    if (w != "on" && w != "off") refuse(name, value, "on (1, true) or off (0, false)");
    return w == "on";
}

int oneOf(const std::string &name, const std::string &value, const std::vector<std::string> &words, const std::string &what)
{
    const std::string w = switchWord(value);
    const auto it = std::find(words.begin(), words.end(), w);
    if (it == words.end()) refuse(name, value, what);
    return int(it - words.begin());
}

std::string print(double v) { return ompl::toString(v); }

}  // namespace gridcar::settings
