// Windows of the motion (dragon/window.hpp): the path's default, and a window cut to the valid
// motion.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "dragon/analyses.hpp"

namespace dragon {

namespace {

// The end as the caller gave it, for messages: seconds as a bare number (as --from 5 was
// always worded), travel with its unit.
std::string given(const Along& a) {
    return a.unit == Along::Unit::seconds ? error_value(a.value) : fmt::format("{} m", error_value(a.value));
}

}  // namespace

void require_valid_at(const Simulation& sim, const Along& a, Key field) {
    const double x = a.travel(sim.scenario().head_speed);
    try {
        if (a.unit == Along::Unit::seconds) sim.require_valid(a.value, field);
        else sim.require_valid_travel(x, field);
    } catch (const PastTheValidMotion& e) {
        throw PastTheValidMotion(field, given(a), e.jam);
    } catch (const InputError& e) {
        throw InputError(field, given(a), e.allowed());
    }
}

RunWindow default_window(PathKind kind) {
    if (kind == PathKind::turnaround) return kTurnaroundWindow;
    return {Along::metres(0.0), Along::metres(std::numeric_limits<double>::infinity())};
}

Searched WindowCut::searched(double head_speed) const {
    return {from / head_speed, to / head_speed, from, to, before, after};
}

WindowCut cut_window(const Simulation& sim, const RunWindow& w) {
    const double v = sim.scenario().head_speed;
    if (!std::isfinite(w.from.value))
        throw InputError(Key::from, given(w.from), "give a finite time in seconds or head travel in metres");
    const bool open = w.to.value == std::numeric_limits<double>::infinity();
    if (std::isnan(w.to.value) || w.to.value == -std::numeric_limits<double>::infinity())
        throw InputError(Key::to, given(w.to),
                         "give a finite time in seconds or head travel in metres, or none: as far as the dragon "
                         "can follow its path");
    WindowCut cut;
    cut.from = w.from.travel(v);
    const ValidRange valid = sim.valid_range();
    if (open) {
        if (!std::isfinite(valid.to_travel))
            throw InputError(Key::to, "open",
                             "on this path the dragon's motion never ends: give the window's end");
        cut.to = valid.to_travel;
        cut.after = valid.after;
    } else {
        cut.to = w.to.travel(v);
        if (!(cut.to > cut.from))
            throw InputError(Key::to, given(w.to), fmt::format("it must be after the start, {}", given(w.from)));
    }
    // A start past the motion's end (or an end before its beginning) leaves nothing valid.
    if (cut.from >= 0.0) require_valid_at(sim, w.from, Key::from);
    if (!open && cut.to <= 0.0) require_valid_at(sim, w.to, Key::to);
    if (cut.from < valid.from_travel) cut.from = valid.from_travel, cut.before = valid.before;
    if (!open && cut.to > valid.to_travel) {
        cut.to = valid.to_travel;
        if (valid.after) {
            cut.after = valid.after;
        } else {
            // Past the spiral's centre, with no jam before it: the head has no place there.
            require_valid_at(sim, w.to, Key::to);
        }
    }
    if (!(cut.to > cut.from))
        throw InputError(Key::from, given(w.from),
                         open ? fmt::format("the search would be empty: the dragon can follow its path only until "
                                            "t = {:.9f} s", valid.to)
                              : "the window holds no moment of the valid motion");
    return cut;
}

}  // namespace dragon
