#include "wording.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace dragon::cli {

std::string count_of(long long n, const std::string& one, const std::string& many) {
    return fmt::format("{} {}", n, n == 1 ? one : many.empty() ? one + "s" : many);
}

std::string proved_interval(double lo, double hi, int decimals, Rounding r) {
    // Rounded to the decimals, then stepped by one unit of the last decimal wherever the rounding
    // went the wrong way (judged on the printed value read back as a double: right to within an
    // ulp, far inside the proofs' own slack, contact::kProofSlack = 1e-12 m).
    const double unit = std::pow(10.0, -decimals);
    double a = std::stod(fmt::format("{:.{}f}", lo, decimals));
    double b = std::stod(fmt::format("{:.{}f}", hi, decimals));
    if (r == Rounding::outward) {
        if (a > lo) a -= unit;
        if (b < hi) b += unit;
    } else {
        if (a < lo) a += unit;
        if (b > hi) b -= unit;
        if (a > b) return fmt::format("[{:.17g}, {:.17g}]", lo, hi);
    }
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
                        "{} steps proved contact-free by enclosing every bench over each step",
                        c->enclosure_time_lo, c->enclosure_time_hi, c->enclosure_lo, c->enclosure_hi, p.proved_steps)
          : fmt::format("proved: no contact over head travel [{:.15g}, {:.15g}] m: {} steps proved contact-free by "
                        "enclosing every bench over each step",
                        p.proved_from, p.proved_to, p.proved_steps);
    if (std::isfinite(p.least_gap)) out += fmt::format(", least separation proved {:.3g} m", p.least_gap);
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


}  // namespace dragon::cli
