#pragma once
// Subcommands of the gridcar program. Each returns the process exit status and throws
// gridcar::InputError (exit 2) for bad input.
#include <stdexcept>
#include <string>

namespace gridcar::cli
{
/// Bad input from the user (file, argument): reported on one line, exit status 2.
class InputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

struct InfoOptions
{
    std::string map;
    bool json{false};
    bool unknownFree{false};
};
int runInfo(const InfoOptions &o);

struct GenmapOptions
{
    std::string out{"campus.yaml"};
    std::string format{"pgm"};
    std::string png;
    unsigned long long seed{1};
    int width{4846};
    int height{2816};
    double resolution{0.298};
};
int runGenmap(const GenmapOptions &o);

struct DemoOptions
{
    std::string map;  ///< empty: the embedded campus map
    std::string outDir{"gridcar-out"};
    std::string vehicle{"paper-i"};
};
int runDemo(const DemoOptions &o);

}  // namespace gridcar::cli
