#pragma once
/// @file Settings.h
/// @brief A planner's settings as one plain struct, declared to OMPL from a table: each field
/// an OMPL string parameter, parsed once, in its setter, into the struct's enums and numbers.

#include <ompl/base/GenericParam.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
/**
 * @brief One setting of a settings struct @p S as OMPL sees it: its parameter name, its range
 * suggestion (for ompl::tools::Benchmark's sweeps), a line on what it does, and its parse and
 * print. `parse` throws std::invalid_argument naming the setting, the value and what is
 * accepted; the planner prefixes its own name.
 */
template <class S>
struct SettingField
{
    std::string name;
    std::string range;
    std::string help;
    std::function<void(S &, const std::string &)> parse;
    std::function<std::string(const S &)> print;
};

/// Declares every field of @p fields on @p params over @p settings: a setter parses into the
/// struct (an error is rethrown as std::invalid_argument prefixed "<planner>: "), then calls
/// @p changed with the name; the getter prints the field.
template <class S>
void declareSettings(ompl::base::ParamSet &params, const std::string &planner, const std::vector<SettingField<S>> &fields,
                     S &settings, const std::function<void(const std::string &)> &changed)
{
    for (const SettingField<S> &f : fields)
    {
        params.declareParam<std::string>(
            f.name,
            [&settings, &f, planner, changed](const std::string &value) {
                try
                {
                    f.parse(settings, value);
                }
                catch (const std::invalid_argument &e)
                {
                    throw std::invalid_argument(planner + ": " + e.what());
                }
                changed(f.name);
            },
            [&settings, &f] { return f.print(settings); });
        params.getParam(f.name)->setRangeSuggestion(f.range);
    }
}

/// The parsers the tables use. Each throws std::invalid_argument "NAME must be WHAT, got 'VALUE'".
namespace settings
{
/// A number in [lo, hi] (the whole of @p value: "1.5x" is refused).
double real(const std::string &name, const std::string &value, double lo, double hi, const std::string &what);
/// An integer among @p allowed.
int integer(const std::string &name, const std::string &value, std::initializer_list<int> allowed, const std::string &what);
/// A switch: 1 / true / on and 0 / false / off, any case (as OMPL's bool parameters and YAML).
bool onOff(const std::string &name, const std::string &value);
/// "on" / "off" for a switch word, else @p value lower-cased (for enums that also take a switch).
std::string switchWord(const std::string &value);
/// One of @p words (after switchWord()): its index.
int oneOf(const std::string &name, const std::string &value, const std::vector<std::string> &words, const std::string &what);
/// A number printed as OMPL prints its double parameters.
std::string print(double v);
}  // namespace settings

}  // namespace gridcar
