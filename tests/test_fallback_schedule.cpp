// FallbackSchedule: the car lattice's fallback stages, their order, the budgets of the rounds,
// when a stage is run again and when the schedule stops.
#include "gridcar/planners/FallbackSchedule.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

using namespace gridcar;

namespace
{
FallbackOptions everything()
{
    FallbackOptions o;
    o.fixedEnds = true;
    o.latticeReverses = true;
    o.hybrid = true;
    o.hybridReverses = true;
    o.fine = true;
    return o;
}
}  // namespace

TEST(FallbackSchedule, StagesInTheirDocumentedOrder)
{
    const FallbackSchedule all(everything());
    const std::vector<FallbackStage> expected{{FallbackSearch::Lattice, true},   {FallbackSearch::Hybrid, false},
                                              {FallbackSearch::Hybrid, true},    {FallbackSearch::FineHybrid, false},
                                              {FallbackSearch::FineHybrid, true}};
    EXPECT_EQ(all.stages(), expected);

    FallbackOptions forward = everything();  // a forward-only car: nothing from the goal back
    forward.latticeReverses = forward.hybridReverses = false;
    EXPECT_EQ(FallbackSchedule(forward).stages(),
              (std::vector<FallbackStage>{{FallbackSearch::Hybrid, false}, {FallbackSearch::FineHybrid, false}}));

    FallbackOptions position = everything();  // a goal position: the goal cannot be searched from
    position.fixedEnds = false;
    EXPECT_EQ(FallbackSchedule(position).stages(),
              (std::vector<FallbackStage>{{FallbackSearch::Hybrid, false}, {FallbackSearch::FineHybrid, false}}));

    FallbackOptions coarse = everything();  // a hybrid cell too small to halve
    coarse.fine = false;
    EXPECT_EQ(FallbackSchedule(coarse).stages().size(), 3u);

    FallbackOptions nearEnds = everything();  // reverse=auto: first the lattice reversing everywhere
    nearEnds.reverseNearEnds = true;
    ASSERT_EQ(FallbackSchedule(nearEnds).stages().size(), 6u);
    EXPECT_EQ(FallbackSchedule(nearEnds).stages().front(), (FallbackStage{FallbackSearch::Lattice, false}));
    EXPECT_EQ(FallbackSchedule(nearEnds).stages()[1], (FallbackStage{FallbackSearch::Lattice, true}));
    nearEnds.latticeReverses = false;  // (a forward lattice has nothing to reverse everywhere)
    EXPECT_FALSE(FallbackSchedule(nearEnds).stages().front() == (FallbackStage{FallbackSearch::Lattice, false}));

    FallbackOptions shut = everything();  // the first search could not leave its start: no lattice stage
    shut.reverseNearEnds = true;
    shut.startShut = true;
    const std::vector<FallbackStage> hybridOnly{{FallbackSearch::Hybrid, false}, {FallbackSearch::Hybrid, true},
                                                {FallbackSearch::FineHybrid, false}, {FallbackSearch::FineHybrid, true}};
    EXPECT_EQ(FallbackSchedule(shut).stages(), hybridOnly);
    shut.hybrid = false;  // and without the hybrid set nothing is left to run
    EXPECT_TRUE(FallbackSchedule(shut).stages().empty());

    FallbackOptions none = everything();  // no hybrid set, forward lattice: nothing to fall back on
    none.hybrid = false;
    none.latticeReverses = false;
    EXPECT_TRUE(FallbackSchedule(none).stages().empty());
    EXPECT_EQ(FallbackSchedule(none).run([](const FallbackStage &, std::uint64_t) { return true; }, [] { return false; }), 0);
}

TEST(FallbackSchedule, RoundsGrowTheBudgetFourfoldAndSkipStagesThatEnded)
{
    const FallbackSchedule s(everything());
    std::vector<std::pair<FallbackStage, std::uint64_t>> runs;
    // the hybrid search ends by itself (ran out of its graph) in the second round; the others
    // always run out of budget; the answer is final after 12 stage runs
    const int n = s.run(
        [&](const FallbackStage &st, std::uint64_t budget) {
            runs.push_back({st, budget});
            return st == FallbackStage{FallbackSearch::Hybrid, false} && budget >= 8000;
        },
        [&] { return runs.size() >= 12; });
    EXPECT_EQ(n, 12);
    ASSERT_EQ(runs.size(), 12u);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(runs[k].second, 2000u) << k;
    for (std::size_t k = 5; k < 10; ++k) EXPECT_EQ(runs[k].second, 8000u) << k;
    EXPECT_EQ(runs[10].first, (FallbackStage{FallbackSearch::Lattice, true}));
    EXPECT_EQ(runs[10].second, 32000u);
    // the ended hybrid stage is not run in the third round
    EXPECT_EQ(runs[11].first, (FallbackStage{FallbackSearch::Hybrid, true}));
}

TEST(FallbackSchedule, StopsWhenAnsweredAndWhenEveryStageEnded)
{
    const FallbackSchedule s(everything());
    int calls = 0;
    // answered after the second stage: the rest of the round is not run
    EXPECT_EQ(s.run([&](const FallbackStage &, std::uint64_t) { return ++calls, false; }, [&] { return calls >= 2; }), 2);
    // every stage ends by itself in the first round: one round only
    EXPECT_EQ(s.run([](const FallbackStage &, std::uint64_t) { return true; }, [] { return false; }), 5);
    // answered before anything ran
    EXPECT_EQ(s.run([](const FallbackStage &, std::uint64_t) { return false; }, [] { return true; }), 0);
}

TEST(FallbackSchedule, OneStageRunsOnceWithoutABudget)
{
    FallbackOptions o;
    o.hybrid = true;  // a forward car towards a position, hybrid cell too small to halve
    const FallbackSchedule s(o);
    ASSERT_EQ(s.stages().size(), 1u);
    EXPECT_EQ(s.firstBudget(), std::numeric_limits<std::uint64_t>::max());
    std::uint64_t seen = 0;
    // even when it reports running out (the termination condition stopped it), it is not repeated
    EXPECT_EQ(s.run([&](const FallbackStage &, std::uint64_t b) { return seen = b, false; }, [] { return false; }), 1);
    EXPECT_EQ(seen, std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(FallbackSchedule::nextBudget(std::numeric_limits<std::uint64_t>::max()), std::numeric_limits<std::uint64_t>::max());
}
