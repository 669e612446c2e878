// JSON numbers as the shortest decimal of the value meant: the arithmetic's last-bit noise gone
// (a grid spacing, a speed rounded to 6 decimals), whole numbers without ".0", every value of up
// to 15 significant digits kept exactly; and the commands' answers printed that way.
#include <cmath>
#include <random>
#include <string>

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

