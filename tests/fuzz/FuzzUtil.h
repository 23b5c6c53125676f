#pragma once
// Shared by the libFuzzer targets of tests/fuzz: the input written to a file (every reader takes
// a path, as the gridcar program does), and the rule every target checks: a reader either
// succeeds or throws one of gridcar's documented errors (MapLoadError, InputError,
// std::invalid_argument: what the program reports with exit 2) with a printable one-line
// message. Anything else (another exception, a crash, undefined behaviour, a leak, an
// allocation beyond libFuzzer's -malloc_limit_mb) is a finding.
#include "gridcar/core/Errors.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <unistd.h>

namespace gridcar::fuzz
{
/// A folder of this process's own under the temporary directory (made once).
inline const std::string &workDir()
{
    static const std::string dir = [] {
        const auto d = std::filesystem::temp_directory_path() / ("gridcar-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d.string();
    }();
    return dir;
}

/// Writes @p size bytes to @p name inside workDir(); returns its path.
inline std::string writeFile(const std::string &name, const std::uint8_t *data, std::size_t size)
{
    const std::string path = workDir() + "/" + name;
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char *>(data), std::streamsize(size));
    return path;
}

[[noreturn]] inline void finding(const char *what, const std::string &detail)
{
    std::fprintf(stderr, "FUZZ FINDING: %s: %s\n", what, detail.c_str());
    std::abort();
}

/// A documented error's message must be one printable line.
inline void checkMessage(const std::exception &e)
{
    const std::string m = e.what();
    if (m.empty()) finding("empty error message", typeid(e).name());
    for (unsigned char c : m)
        if (c < 0x20 || c == 0x7f) finding("unprintable byte in an error message", printable(m, 400));
}

/// Runs @p read; documented errors pass (their message checked), anything else is a finding.
template <class F>
void expectCleanly(F &&read)
{
    try
    {
        read();
    }
    catch (const MapLoadError &e)
    {
        checkMessage(e);
    }
    catch (const InputError &e)
    {
        checkMessage(e);
    }
    catch (const std::invalid_argument &e)
    {
        checkMessage(e);
    }
    catch (const std::exception &e)
    {
        finding((std::string("undocumented exception ") + typeid(e).name()).c_str(), printable(e.what(), 400));
    }
}

/// Splits @p data at the first occurrence of @p sep (the second part empty when absent).
inline void split(const std::uint8_t *data, std::size_t size, const std::string &sep, std::string &a, std::string &b)
{
    const std::string all(reinterpret_cast<const char *>(data), size);
    const auto at = all.find(sep);
    a = all.substr(0, at);
    b = at == std::string::npos ? std::string() : all.substr(at + sep.size());
}

}  // namespace gridcar::fuzz
