// JSON numbers as the shortest decimal of the value meant: the arithmetic's last-bit noise gone
// (a grid spacing, a speed rounded to 6 decimals), whole numbers without ".0", every value of up
// to 15 significant digits kept exactly; and the commands' answers printed that way.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/decimals.hpp"
#include "dragon/json.hpp"

using dragon::Json;
using dragon::json_text;

TEST(JsonNumbers, TheValueMeant) {
    EXPECT_EQ(json_text(Json((0.55 - 0.35) / 80)), "0.0025");  // 0.002500000000000001 in binary
    EXPECT_EQ(json_text(Json(dragon::round6(0.97943499999))), "0.979435");
    EXPECT_EQ(json_text(Json(0.1 + 0.2)), "0.3");
    EXPECT_EQ(json_text(Json::array({0, 300.0})), "[0,300]");
    EXPECT_EQ(json_text(Json(-0.0)), "0");
    EXPECT_EQ(json_text(Json(NAN)), "null");
    EXPECT_EQ(json_text(Json(INFINITY)), "null");
    EXPECT_EQ(json_text(Json(1e308)), "1e+308");
    EXPECT_EQ(json_text(Json(1e-10)), "1e-10");
    EXPECT_EQ(json_text(Json(-2.5)), "-2.5");
    // Layout as nlohmann's: compact, or indented; text escaped as JSON.
    const Json v = {{"a", Json::array({1.5, Json::object()})}, {"b \"q\"", "x\ny"}, {"c", Json::array()}};
    EXPECT_EQ(json_text(v), R"({"a":[1.5,{}],"b \"q\"":"x\ny","c":[]})");
    EXPECT_EQ(json_text(v, 2), v.dump(2));
}

// Any decimal of up to 15 significant digits comes back as written (or shorter: trailing zeros
// dropped), and parses back to the same double.
TEST(JsonNumbers, DecimalsOfFifteenDigitsComeBackExactly) {
    std::mt19937_64 rng(20);
    std::uniform_int_distribution<long long> mantissa(1, 999999999999999LL);
    std::uniform_int_distribution<int> exponent(-30, 30), digits(1, 15);
    for (int k = 0; k < 20000; ++k) {
        const int d = digits(rng);
        long long m = mantissa(rng);
        while (m >= static_cast<long long>(std::pow(10, d))) m /= 10;
        const std::string written = fmt::format("{}e{}", m, exponent(rng));
        const double v = std::strtod(written.c_str(), nullptr);
        const std::string text = json_text(Json(v));
        EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << written << " -> " << text;
        // No longer than the shortest form of the double itself.
        EXPECT_LE(text.size(), fmt::format("{}", v).size()) << written << " -> " << text;
    }
}


// meant() reads its 15 digits back without strtod where one multiplication or division by a
// power of ten is exact enough (json_text.cpp): the same double as strtod's, for any value.
TEST(JsonNumbers, TheValueMeantIsStrtodsReading) {
    const auto by_strtod = [](double v) {
        const double r = std::strtod(fmt::format("{:.15g}", v).c_str(), nullptr);
        return r == 0.0 ? 0.0 : r;
    };
    const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> decade(-30.0, 30.0), unit(-1.0, 1.0);
    for (int k = 0; k < 200000; ++k) {
        // Any bit pattern (every exponent, subnormals included), and values of the answers' sizes.
        std::uint64_t bits = rng();
        double v = 0.0;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) continue;
        ASSERT_TRUE(same(dragon::meant(v), by_strtod(v))) << fmt::format("{:a}", v);
        const double w = unit(rng) * std::pow(10.0, decade(rng));
        ASSERT_TRUE(same(dragon::meant(w), by_strtod(w))) << fmt::format("{:a}", w);
    }
    // Halfway cases and the edges of the fast path: 15 digits at 10^-22 and 10^22, whole numbers.
    for (const double v : {0.5, 1.5, 2.5e-22, 9.99999999999999e22, 1e23, 1.23456789012345e-22, 123456789012345.0,
                           1e15, 999999999999999.0, 0.1 + 0.2, 412.849997470631, 5e-324, 1.7976931348623157e308}) {
        EXPECT_TRUE(same(dragon::meant(v), by_strtod(v))) << fmt::format("{:a}", v);
        EXPECT_TRUE(same(dragon::meant(-v), by_strtod(-v))) << fmt::format("{:a}", -v);
    }
}

// The whole text with its leaves: the same text as json_text, and each leaf's text what
// json_text prints for that value alone, under its key path, in the order written.
TEST(JsonNumbers, LeavesAreTheWholeTextsOwnCharacters) {
    const Json v = {{"time", 412.473837682117},
                    {"benches", Json::array({1, 9})},
                    {"enclosure", {{"travel", Json::array({412.47383768210701, 412.473837682117})}, {"none", Json::object()}}},
                    {"proof", {{"method", "rate"}, {"least_separation", nullptr}, {"steps", 0}}},
                    {"handles", Json::array({{{"x", 1.209931}, {"y", -0.0}}, {{"x", (0.55 - 0.35) / 80}}})},
                    {"key \"q\"", true}};
    std::vector<std::pair<std::string, std::string>> leaves;
    const std::string text =
        dragon::json_text_with_leaves(v, [&](const std::string& path, std::string_view t) { leaves.emplace_back(path, t); });
    EXPECT_EQ(text, json_text(v));
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"time", json_text(v["time"])},
        {"benches", "[1,9]"},
        {"enclosure.travel", json_text(v["enclosure"]["travel"])},
        {"enclosure.none", "{}"},
        {"proof.method", "\"rate\""},
        {"proof.least_separation", "null"},
        {"proof.steps", "0"},
        {"handles", json_text(v["handles"])},
        {"key \"q\"", "true"}};
    EXPECT_EQ(leaves, expected);
    // A scalar alone is its own leaf, at the path "".
    leaves.clear();
    const auto hear = [&](const std::string& p, std::string_view t) { leaves.emplace_back(p, t); };
    EXPECT_EQ(dragon::json_text_with_leaves(Json(0.1 + 0.2), hear), "0.3");
    EXPECT_EQ(leaves, (std::vector<std::pair<std::string, std::string>>{{"", "0.3"}}));
}
