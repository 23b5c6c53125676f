#pragma once
/// @file Format.h
/// @brief Number formatting and small statistics of the experiment tables.

#include <string>
#include <vector>

namespace gridcar::bench
{
/// @p v with @p prec decimals.
std::string fixed(double v, int prec);
/// "median % (min .. max)" of percentages, "-" for none.
std::string percentSummary(std::vector<double> v);
/// Throws InputError unless @p seconds is a positive number of seconds, at most a day.
void checkTimeLimit(double seconds);

}  // namespace gridcar::bench
