#pragma once
/// @file CarLatticeParams.h
/// @brief The car lattice's OMPL parameters: the table that names, parses and prints each field
/// of CarLatticeSettings.

#include "gridcar/planners/Settings.h"
#include "gridcar/planners/search/CarLatticeSettings.h"

#include <vector>

namespace gridcar
{
/// One entry per CarLatticeSettings field, in the order the planners declare them.
const std::vector<SettingField<CarLatticeSettings>> &carLatticeSettingFields();
/// The words of each enum as the parameters take and print them.
const char *word(AutoSwitch v);
const char *word(PrimitiveSet v);
const char *word(CurveHeuristic v);
const char *word(TurnShape v);
}  // namespace gridcar
