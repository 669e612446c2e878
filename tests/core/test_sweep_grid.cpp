// A sweep's grid: axes parsed from their specs (values and the cells that name them), bad specs
// refused naming the spec, every combination enumerated once with the first axis slowest, and
// shards that are disjoint and together the whole.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "dragon/sweep.hpp"
#include "support/param_name.hpp"

using namespace dragon;

TEST(SweepAxis, RangeIsCountValuesWithBothEndsAsWritten) {
    const Axis a = parse_axis("width=0.20:0.40:21");
    EXPECT_STREQ(a.parameter->name, "width");
    ASSERT_EQ(a.values.size(), 21u);
    EXPECT_EQ(a.values.front(), 0.20);
    EXPECT_EQ(a.values.back(), 0.40);
    // Each value is the decimal a person would write, and its cell reads back as exactly it.
    for (std::size_t k = 0; k < a.values.size(); ++k) {
        const double expected = std::stod(std::to_string(20 + k)) / 100.0;
        EXPECT_EQ(a.values[k], expected) << k;
        EXPECT_EQ(std::stod(a.cells[k]), a.values[k]) << a.cells[k];
    }
    EXPECT_EQ(a.cells[1], "0.21");
    const Axis down = parse_axis("arc-ratio=3:1:5");
    EXPECT_EQ(down.cells, (std::vector<std::string>{"3", "2.5", "2", "1.5", "1"}));
    EXPECT_EQ(parse_axis("pitch=0.5:0.5:1").values, std::vector<double>{0.5});
}

TEST(SweepAxis, ListKeepsItsOrderAndWholeNumbersStayWhole) {
    const Axis a = parse_axis("speed=2,0.5,1");
    EXPECT_EQ(a.values, (std::vector<double>{2, 0.5, 1}));
    EXPECT_EQ(a.cells, (std::vector<std::string>{"2", "0.5", "1"}));
    const Axis b = parse_axis("bench-count=10:40:4");
    EXPECT_EQ(b.cells, (std::vector<std::string>{"10", "20", "30", "40"}));
    Scenario s;
    set_parameter(s, *b.parameter, b.values[2]);
    EXPECT_EQ(s.bench.bench_count, 30);
}

class SweepAxisBad : public ::testing::TestWithParam<const char*> {};

TEST_P(SweepAxisBad, IsRefusedNamingTheSpec) {
    const std::string spec = GetParam();
    try {
        parse_axis(spec);
        FAIL() << spec << " was taken";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Specs, SweepAxisBad,
                         ::testing::Values("width", "width=", "=1", "colour=1,2", "width=0.2:0.4", "width=0.2:0.4:x",
                                           "width=0.2:0.4:0", "width=0.2:0.4:2.5", "width=0.2:0.4:1", "width=a,b",
                                           "width=0.2,,0.3", "width=nan", "width=inf,1", "width=0.2,0.2",
                                           "width=0.3:0.3:3", "bench-count=1:2:3", "bench-count=1.5", "width=1:2:1e9",
                                           "width=1::3", "width=1:2:3:4"),
                         [](const auto& info) { return dragon_test::param_name(info.index, info.param); });

TEST(SweepGrid, EveryCombinationOnceFirstAxisSlowest) {
    const SweepGrid g({parse_axis("width=0.2,0.3"), parse_axis("body-length=1.6:2.0:3"), parse_axis("speed=1,2")});
    ASSERT_EQ(g.size(), 12u);
    EXPECT_EQ(g.cells(0), (std::vector<std::string>{"0.2", "1.6", "1"}));
    EXPECT_EQ(g.cells(1), (std::vector<std::string>{"0.2", "1.6", "2"}));
    EXPECT_EQ(g.cells(11), (std::vector<std::string>{"0.3", "2", "2"}));
    std::set<std::vector<std::string>> seen;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const std::vector<std::string> cells = g.cells(i);
        EXPECT_TRUE(seen.insert(cells).second);
        EXPECT_EQ(g.index_of(cells), i);
        const Scenario s = g.scenario(Scenario{}, i);
        EXPECT_EQ(s.bench.width, std::stod(cells[0]));
        EXPECT_EQ(s.bench.body_length, std::stod(cells[1]));
        EXPECT_EQ(s.head_speed, std::stod(cells[2]));
        EXPECT_EQ(s.path.pitch, Scenario{}.path.pitch);  // what is not varied stays
    }
    EXPECT_FALSE(g.index_of({"0.2", "1.6"}).has_value());
    EXPECT_FALSE(g.index_of({"0.20", "1.6", "1"}).has_value());  // cells are matched exactly as written
    EXPECT_EQ(g.varied(), value::width | value::body_length | value::head_speed);
    EXPECT_THROW(SweepGrid({parse_axis("width=1,2"), parse_axis("width=3")}), InputError);
    EXPECT_THROW(SweepGrid({}), InputError);
    EXPECT_THROW(SweepGrid({parse_axis("width=1:2:5000"), parse_axis("speed=1:2:5000")}), InputError);  // 25 million
}

TEST(SweepShard, PartsAreDisjointAndMakeTheWhole) {
    for (std::size_t total : {0u, 1u, 7u, 12u, 100u}) {
        for (std::size_t n : {1u, 2u, 3u, 5u, 13u}) {
            std::vector<int> count(total, 0);
            std::size_t sizes = 0;
            for (std::size_t k = 1; k <= n; ++k) {
                const Shard s{k, n};
                sizes += s.size(total);
                for (std::size_t j = 0; j < s.size(total); ++j) {
                    ASSERT_LT(s.scenario(j), total);
                    EXPECT_TRUE(s.holds(s.scenario(j)));
                    ++count[s.scenario(j)];
                }
            }
            EXPECT_EQ(sizes, total);
            for (std::size_t i = 0; i < total; ++i) EXPECT_EQ(count[i], 1) << i << " of " << total << " in " << n;
        }
    }
    EXPECT_EQ(parse_shard("2/8").index, 2u);
    EXPECT_EQ(parse_shard("2/8").count, 8u);
    for (const char* bad : {"", "0/3", "4/3", "1", "1/0", "a/b", "1/2/3", "-1/2", "1 /2"})
        EXPECT_THROW(parse_shard(bad), InputError) << bad;
}

TEST(SweepCsv, FieldsRoundTripThroughQuotes) {
    const std::vector<std::string> fields = {"0.2", "", "[1,9]", "say \"hi\", then go", "refused (x): a, b", "plain"};
    const std::string line = csv_line(fields);
    EXPECT_EQ(line, "0.2,,\"[1,9]\",\"say \"\"hi\"\", then go\",\"refused (x): a, b\",plain");
    EXPECT_EQ(split_csv(line), fields);
    EXPECT_EQ(split_csv(""), std::vector<std::string>{""});
    EXPECT_THROW(split_csv("a,\"b"), InputError);
}
