/// @file PlainLog.cpp
/// @brief usePlainLog(): OMPL's output handler without source locations.
#include "gridcar/query/PlainLog.h"

#include <ompl/util/Console.h>

#include <cstdio>
#include <string>

namespace gridcar
{
namespace
{
struct PlainLog : ompl::msg::OutputHandler
{
    void log(const std::string &text, ompl::msg::LogLevel level, const char *, int) override
    {
        const char *tag = level >= ompl::msg::LOG_ERROR  ? "Error: "
                          : level >= ompl::msg::LOG_WARN ? "Warning: "
                          : level >= ompl::msg::LOG_INFO ? "Info: "
                                                         : "Debug: ";
        std::fprintf(stderr, "%s%s\n", tag, text.c_str());
    }
};
}  // namespace

void usePlainLog()
{
    static PlainLog handler;
    ompl::msg::useOutputHandler(&handler);
}

}  // namespace gridcar
