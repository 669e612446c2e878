// The proved first-contact search against a brute-force scan (support/contact_scan.hpp says what
// is compared), on random scenarios and random windows of their motion: seeded, the same cases
// every run, so that ctest runs it in every build (under a second in Release); a failure prints
// the case as the tool's flags. tests/fuzz/fuzz_contact.cpp draws the cases from a fuzzer's
// input instead (scripts/fuzz.sh, clang).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "support/contact_scan.hpp"

using namespace dragon;

namespace {

constexpr unsigned kSeed = 20261127;

}  // namespace

TEST(ContactVsScan, ProvedFirstContactAgreesWithABruteForceScan) {
    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<double> dist(0.0, 1.0);
    auto u = [&] { return dist(rng); };
    int contacts = 0, clear_windows = 0;
    for (int round = 0; round < 16; ++round) {
        const auto c = dragon_test::draw_contact_case(u, round % 2 ? PathKind::turnaround : PathKind::spiral,
                                                      round % 4 < 2, 1000);
        ASSERT_TRUE(c.has_value()) << "round " << round << ": no case in 1000 draws";
        SCOPED_TRACE(c->describe());
        const dragon_test::ContactVsScan r = dragon_test::compare_with_scan(*c);
        for (const std::string& v : r.violations) ADD_FAILURE() << v;
        ++(r.found ? contacts : clear_windows);
    }
    // The draw holds both kinds of window.
    EXPECT_GE(contacts, 6);
    EXPECT_GE(clear_windows, 6);
}
