#pragma once
/// @file ParameterHelp.h
/// @brief One line on what each planner parameter does, for `gridcar planners` and anyone who
/// lists a planner's ompl::base::ParamSet.

#include <string>

namespace gridcar
{
/// What parameter @p name of a planner does, with its unit where it has one: from the settings
/// tables (CarLatticeSettings, ImprovedSettings, the corner weights), the parameters GridPlanner
/// and the grid planners declare themselves, and the common ones of OMPL's planners; for any
/// other OMPL parameter a line saying where it is documented.
std::string parameterHelp(const std::string &name);

/// The kind of value a parameter takes, read off its OMPL range suggestion @p range: "flag"
/// (0,1), "whole number" or "number" (LOW:STEP:HIGH or LOW:HIGH, whole where no bound has a
/// decimal point), "choice" (words separated by commas), else "text".
std::string parameterType(const std::string &range);

}  // namespace gridcar
