#include "wording.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "report.hpp"

namespace dragon::cli {

std::string count_of(long long n, const std::string& one, const std::string& many) {
    return fmt::format("{} {}", n, n == 1 ? one : many.empty() ? one + "s" : many);
}

double rounded_to(double x, int decimals, bool up) {
    // Rounded to the decimals, then stepped by one unit of the last decimal wherever the rounding
    // went the wrong way (judged on the printed value read back as a double: right to within an
    // ulp, far inside the proofs' own slack, contact::kProofSlack = 1e-12 m).
    const double unit = std::pow(10.0, -decimals);
    const double r = std::stod(fmt::format("{:.{}f}", x, decimals));
    return up ? (r < x ? r + unit : r) : (r > x ? r - unit : r);
}

std::string proved_interval(double lo, double hi, int decimals, Rounding r) {
    const bool outward = r == Rounding::outward;
    const double a = rounded_to(lo, decimals, !outward), b = rounded_to(hi, decimals, outward);
    if (a > b) return fmt::format("[{:.17g}, {:.17g}]", lo, hi);  // inward, narrower than the decimals
    return fmt::format("[{:.{}f}, {:.{}f}]", a, decimals, b, decimals);
}

std::string proof_words(const ContactProof& p, const Contact* c) {
    if (p.proved_steps == 0)
        return p.motion_checked  // asked to prove (the valid motion was), but no step could be enclosed
                   ? fmt::format("not proved: none of the search's {} steps could be enclosed (a link turning too far "
                                 "for the enclosures and the speed bounds); each rests on its rate bound checked at "
                                 "its end\n", p.unproved_steps)
                   : fmt::format("not proved: each of the search's {} steps rests on its rate bound checked at its end "
                                 "(--prove encloses every bench over each step)\n",
                                 p.unproved_steps);
    std::string out =
        c ? fmt::format("proved: the first contact lies in t = [{:.15g}, {:.15g}] s (head travel [{:.15g}, {:.15g}] m): "
                        "{} steps proved contact-free by enclosing every bench that may touch over each step",
                        c->enclosure_time_lo, c->enclosure_time_hi, c->enclosure_lo, c->enclosure_hi, p.proved_steps)
          : fmt::format("proved: no contact over head travel [{:.15g}, {:.15g}] m: {} steps proved contact-free by "
                        "enclosing every bench that may touch over each step",
                        p.proved_from, p.proved_to, p.proved_steps);
    if (std::isfinite(p.least_gap))
        out += fmt::format(", least separation proved {:.3g} m between the benches enclosed", p.least_gap);
    if (p.motion_checked)
        out += p.motion.unproved_steps == 0
                   ? std::string("; the valid motion proved over it")
                   : fmt::format("; the valid motion proved over it but for {} steps ({:.6g} m of head travel) on their "
                                 "rates checked at their ends", p.motion.unproved_steps, p.motion.unproved_travel);
    if (p.unproved_steps > 0)
        out += fmt::format("; not proved: {} steps over {:.6g} m of head travel, where neither the handles' motion nor their speed bounds "
                           "enclose the benches, rest on the rate bound checked at their ends",
                           p.unproved_steps, p.unproved_travel);
    return out + "\n";
}

namespace {

// "[lo, hi], [lo, hi] and [lo, hi]", m to ten decimals, rounded as `r` says (proved_interval); a
// single pitch (the search's answer, proved on its own) as itself, to all 17 digits.
std::string range_list(const std::vector<PitchInterval>& v, Rounding r) {
    std::string out;
    for (size_t k = 0; k < v.size(); ++k)
        out += (k == 0 ? "" : k + 1 == v.size() ? " and " : ", ") +
               (v[k].lo == v[k].hi ? fmt::format("{:.17g}", v[k].lo) : proved_interval(v[k].lo, v[k].hi, 10, r));
    return out;
}

}  // namespace

std::string pitch_proof_words(const MinPitch& m) {
    if (!m.proof) return "not proved between the pitches run (--prove proves every pitch of the range)\n";
    const PitchProof& p = *m.proof;
    std::vector<std::string> parts;
    if (!p.proved.empty()) {
        std::string feasible = "every pitch in " + range_list(p.proved, Rounding::inward) +
                               fmt::format(" m reaches the boundary with no contact ({} cells of head radius and pitch "
                                           "enclosed", p.cells);
        if (std::isfinite(p.least_gap))
            feasible += fmt::format(", least separation proved {:.3g} m between the benches enclosed", p.least_gap);
        parts.push_back(feasible + ")");
    }
    if (!p.proved_colliding.empty())
        parts.push_back("every pitch in " + range_list(p.proved_colliding, Rounding::inward) + " m meets a contact before it");
    std::string out = "proved: ";
    for (size_t k = 0; k < parts.size(); ++k) out += (k == 0 ? "" : "; ") + parts[k];
    if (parts.empty()) out += "nothing";
    std::vector<PitchInterval> unproved = p.unproved;
    unproved.insert(unproved.end(), p.unproved_colliding.begin(), p.unproved_colliding.end());
    std::sort(unproved.begin(), unproved.end(), [](const PitchInterval& a, const PitchInterval& b) { return a.lo < b.lo; });
    if (!unproved.empty()) out += "; not proved: " + range_list(unproved, Rounding::outward) + " m (rests on the runs at the pitches probed)";
    if (!std::isnan(p.least_lo))
        out += fmt::format("\nproved: the least feasible pitch of the range lies in {} m",
                           proved_interval(p.least_lo, p.least_hi, 10));
    return out + "\n";
}

std::string speed_proof_words(const MaxSpeed& m) {
    if (!m.proof) return "not proved: the maximum is the coarse scan's and its refinement's (--prove bounds every "
                         "handle's speed over every stretch of the window)\n";
    const MaxSpeedProof& p = *m.proof;
    if (!p.proved)
        return fmt::format("not proved: {} of the window's stretches ({} m of head travel) could not be bounded; "
                           "the largest speed is at most {} m/s\n", count_of(p.unproved, "stretch", "stretches"),
                           format_amount(p.unproved_travel), format_amount(p.max_head_speed_hi));
    const std::string motion =
        p.motion.unproved_steps == 0
            ? std::string("; the valid motion proved over the window")
            : fmt::format("; the valid motion proved over the window but for {} ({} m of head travel) on their rates",
                          count_of(p.motion.unproved_steps, "step", "steps"), format_amount(p.motion.unproved_travel));
    return fmt::format("proved: the largest head speed lies in {} m/s (every handle's speed bounded "
                       "over {}, {} split){}\n", proved_interval(p.max_head_speed_lo, p.max_head_speed_hi, 12),
                       count_of(p.stretches, "stretch", "stretches"), p.subdivisions, motion);
}

}  // namespace dragon::cli
