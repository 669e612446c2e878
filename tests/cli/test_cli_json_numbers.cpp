// The answers' numbers as the tool prints them in --json: the value meant, at most the decimals
// asked (the library's side is tests/answers/test_json_numbers.cpp).
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace {

TEST(JsonNumbers, AnswersPrintTheValueMeant) {
    const dragon_test::CliRun mp = dragon_test::run_dragon("min-pitch --lo 0.44 --hi 0.46 --grid 0.0025 --json");
    ASSERT_EQ(mp.code, 0) << mp.err;
    EXPECT_TRUE(dragon_test::contains(mp.out, "\"grid\":0.0025,")) << mp.out.substr(0, 300);
    // Every handle's speed in collide's answer: at most 6 decimals, as rounded.
    const dragon_test::CliRun c = dragon_test::run_dragon("collide --json");
    ASSERT_EQ(c.code, 0) << c.err;
    const std::regex speed("\"speed\":(-?[0-9.e+-]+)");
    int speeds = 0;
    for (auto it = std::sregex_iterator(c.out.begin(), c.out.end(), speed); it != std::sregex_iterator(); ++it) {
        const std::string number = (*it)[1];
        const std::size_t dot = number.find('.');
        EXPECT_TRUE(dot == std::string::npos || number.size() - dot - 1 <= 6) << number;
        ++speeds;
    }
    EXPECT_EQ(speeds, 224);
    EXPECT_TRUE(dragon_test::contains(c.out, "\"from\":0,")) << c.out.substr(0, 300);
}

}  // namespace
