// run_sweep makes every scenario not yet done exactly once and hands the rows over one at a time.
#include <gtest/gtest.h>

#include <atomic>
#include <set>
#include <string>
#include <vector>

#include "dragon/sweep.hpp"

using namespace dragon;

TEST(SweepRun, EachScenarioNotDoneIsMadeOnceAndEmittedOneAtATime) {
    const SweepGrid grid({parse_axis("width=0.1:0.5:9"), parse_axis("speed=1,2,3")});
    std::vector<bool> done(grid.size(), false);
    for (std::size_t i = 0; i < grid.size(); i += 4) done[i] = true;
    ThreadPool pool(3);
    for (const Shard shard : {Shard{1, 1}, Shard{2, 5}}) {
        std::vector<std::atomic<int>> made(grid.size());
        std::atomic<int> inside{0};
        std::set<std::size_t> emitted;
        std::int64_t last_progress = 0, total = 0;
        run_sweep<std::string>(
            grid, shard, done, pool,
            [&](std::size_t i, int) {
                ++made[i];
                return csv_line(grid.cells(i));
            },
            [&](std::size_t i, std::string&& row) {
                EXPECT_EQ(inside++, 0);  // never two at once
                EXPECT_EQ(row, csv_line(grid.cells(i)));
                EXPECT_TRUE(emitted.insert(i).second);
                --inside;
            },
            [&](std::int64_t d, std::int64_t t) { last_progress = d, total = t; });
        std::size_t expected = 0;
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const bool wanted = shard.holds(i) && !done[i];
            EXPECT_EQ(made[i].load(), wanted ? 1 : 0) << i;
            EXPECT_EQ(emitted.count(i), wanted ? 1u : 0u) << i;
            expected += wanted;
        }
        EXPECT_EQ(static_cast<std::size_t>(total), expected);
        EXPECT_EQ(last_progress, total);
    }
}
