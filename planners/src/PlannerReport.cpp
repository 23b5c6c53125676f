/// @file PlannerReport.cpp
/// @brief The report of any planner (PlannerReport.h).
#include "gridcar/planners/PlannerReport.h"

namespace gridcar
{
PlannerReport reportOf(const ompl::base::Planner &planner)
{
    // the one place that asks what kind of planner it is
    if (const auto *r = dynamic_cast<const ReportingPlanner *>(&planner)) return r->lastReport();
    return {};
}
}  // namespace gridcar
