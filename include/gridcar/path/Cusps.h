#pragma once
/// @file Cusps.h
/// @brief Where splitAtCusps() was declared before it moved to core (the vehicle's driving time
/// uses it, and core is below path): kept so that applications including this path still build.

#include "gridcar/core/Cusps.h"
