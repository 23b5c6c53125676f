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

}  // namespace gridcar
