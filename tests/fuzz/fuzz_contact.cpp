// libFuzzer target: the proved first-contact search against a brute-force scan.
//
// From the input: the path's kind, whether the window holds the motion's first contact, and the
// scenario and window themselves (a short dragon of any reasonable make; support/contact_scan.hpp
// draws them, the input's bytes standing in for the seeded generator of
// tests/core/test_contact_vs_scan.cpp, which checks the same on 16 fixed cases in every build).
//
// Property: compare_with_scan() finds nothing the search claims that the scan contradicts (no
// touching sample inside the travel its proved steps cover, the contact no later than the scan's
// first touching sample and its enclosure holding the scan's crossing, no contact missed).
#include <cstdint>
#include <exception>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

#include "fuzz_check.hpp"
#include "support/contact_scan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider p(data, size);
    const dragon::PathKind kind = p.ConsumeBool() ? dragon::PathKind::turnaround : dragon::PathKind::spiral;
    const bool contact = p.ConsumeBool();
    // Once the input runs out every draw is 0: a few tries, not a loop that cannot end.
    auto u = [&] { return p.ConsumeProbability<double>() * (1.0 - 1e-16); };
    const auto c = dragon_test::draw_contact_case(u, kind, contact, 4);
    if (!c) return 0;
    fuzz_context() = c->describe();
    // A scenario the draw accepted is valid: any error from the search is a failure, not a refusal.
    dragon_test::ContactVsScan r;
    try {
        r = dragon_test::compare_with_scan(*c);
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "the search failed: %s", e.what());
    }
    std::string all;
    for (const std::string& v : r.violations) all += "\n  " + v;
    FUZZ_CHECK(r.violations.empty(), "the proved search contradicts the scan:%s", all.c_str());
    return 0;
}
