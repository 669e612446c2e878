// The library's sentences about its answers: the minimum pitch's guarantee, Q4's conclusion
// (dragon/answers.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dragon/answers.hpp"

namespace dragon {

std::string min_pitch_guarantee(const MinPitch& m) {
    return fmt::format(
        "feasibility evaluated on a {:.4g} m pitch grid over [{}, {}], each change narrowed to {:.0e} m (from a "
        "contact to none, where the touching pair's closest approach is zero, confirmed by full runs on either "
        "side; any other change by sections of full runs); each run checks the whole way to the boundary in steps "
        "of head travel no pair can touch within at closing speeds up to twice those bounded at the step's start "
        "(second order near grazing passes), and each step is checked at its end, where the gaps the step began "
        "with must last it at the closing speeds bounded there, or it is taken again shorter: a contact inside a "
        "step would need a pair to close faster than twice its bound at the start and than its bound at the end; "
        "benches whose turn of the spiral keeps them apart are left out, as proved; a run whose motion ends "
        "before the boundary is infeasible; a window narrower than the grid spacing could still lie unseen "
        "between two grid points of the same state (a finer grid rules out narrower ones)",
        m.grid, m.search_lo, m.search_hi, m.tolerance);
}

namespace {

// "0.5, 1, 1.5 and 2": the studied ratios this dragon can (or cannot) follow.
std::string ratio_list(const std::vector<TurnStudyRow>& rows, bool followable) {
    std::vector<std::string> items;
    for (const TurnStudyRow& r : rows)
        if (r.followable() == followable) items.push_back(fmt::format("{:g}", r.ratio));
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
    return out;
}

}  // namespace

std::string turnaround_conclusion(const TurnaroundStudy& st) {
    const TurnStudyRow& inner = st.by_entry.back();
    std::string c = fmt::format(
        "Not by changing the ratio: tangent at A and B, r1 + r2 = R sqrt(1 + theta^2) / theta and "
        "both arcs sweep the same angle whatever r1 / r2 is, so the S-curve is {:.6f} m for every "
        "ratio (spread {:.1e} m over ratios {:g}..{:g}).",
        st.design.length, st.ratio_spread, st.by_ratio.front().ratio, st.by_ratio.back().ratio);
    const std::string usable = ratio_list(st.by_ratio, true), unusable = ratio_list(st.by_ratio, false);
    if (unusable.empty())
        c += " This dragon can follow it at every ratio studied.";
    else if (usable.empty())
        c += " This dragon can follow it at none of them: at every ratio a handle would have to jump on the way "
             "through.";
    else
        c += fmt::format(" This dragon can follow it only at ratios {}; at {} a handle would have to jump on the "
                         "way through (an arc too tight for its benches).", usable, unusable);
    if (st.design_jam)
        c += fmt::format(" At the chosen ratio {:g} the dragon's motion ends at t = {:.6f} s: {}.", st.design.ratio,
                         st.design_jam->time, describe(*st.design_jam));
    c += fmt::format(
        " The S-curve gets shorter only if the turn starts deeper inside the turning space ({:.6f} m "
        "from radius {:.4g} m), but then the head coils in and out further along the spirals: its whole "
        "way inside the turning space grows from {:.6f} m to {:.6f} m.",
        inner.s_curve_length, inner.entry_radius, st.by_entry.front().inside_length, inner.inside_length);
    // The outermost entry radius inside the boundary this dragon cannot follow, if any (the
    // boundary's own row is the chosen design, said above).
    for (size_t k = 1; k < st.by_entry.size(); ++k) {
        if (!st.by_entry[k].followable()) {
            c += fmt::format(" Nor can this dragon follow those from entry radius {:.4g} m inward.",
                             st.by_entry[k].entry_radius);
            break;
        }
    }
    return c + " With the turn tangent at the boundary the curve is as short as it gets for the way through the "
               "turning space.";
}


}  // namespace dragon
