#include "gridcar/bench/Format.h"

#include "gridcar/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridcar::bench
{
std::string fixed(double v, int prec)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}

std::string percentSummary(std::vector<double> v)
{
    if (v.empty()) return "-";
    std::sort(v.begin(), v.end());
    const double med = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    return fixed(med, 1) + " % (" + fixed(v.front(), 1) + " .. " + fixed(v.back(), 1) + ")";
}

void checkTimeLimit(double seconds)
{
    if (!(seconds > 0.0) || !std::isfinite(seconds) || seconds > 86400)
        throw InputError("--time-limit must be a positive number of seconds (at most a day)");
}

}  // namespace gridcar::bench
