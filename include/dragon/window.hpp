// Where along the motion an analysis looks: a window of head travel, or of time.
//
// The chain's shape depends only on how far the head has travelled from its place at t = 0; the
// head's speed sets the clock (t = travel / speed). So an analysis's window is a length of head
// travel, and the answers inside it (which benches touch and where, how close they come, how
// fast a handle goes against the head) are the same at any head speed, with their times scaled
// by 1 / speed. The contest's "100 s either side of the turn" is at 1 m/s: 100 m of travel.
// A window's end may also be given in seconds, at the scenario's head speed.
#pragma once

#include <optional>
#include <string>

#include "dragon/valid_motion.hpp"

namespace dragon {

// One end of a window: a time in seconds, or a head travel in metres.
struct Along {
    // What `value` measures.
    enum class Unit { seconds, metres };
    double value = 0.0;        // s, or m of head travel, from t = 0; +inf: open
    Unit unit = Unit::metres;  // which of the two

    static constexpr Along seconds(double t) { return {t, Unit::seconds}; }  // t seconds
    static constexpr Along metres(double x) { return {x, Unit::metres}; }    // x metres of head travel
    // As head travel (m) and as time (s), at this head speed.
    double travel(double head_speed) const { return unit == Unit::metres ? value : value * head_speed; }
    double time(double head_speed) const { return unit == Unit::seconds ? value : value / head_speed; }
    bool operator==(const Along&) const = default;
};

// A window of the motion: from one end to the other (each in seconds or head travel).
struct RunWindow {
    Along from;  // where it starts
    Along to;    // where it ends
    bool operator==(const RunWindow&) const = default;
};

// The turnaround's window: the contest's 100 s before and after the turn, at 1 m/s.
inline constexpr RunWindow kTurnaroundWindow{Along::metres(-100.0), Along::metres(100.0)};

// "-100 m" / "12.5 s": how an end was given, for messages; "open" for +inf (as far as the motion goes).
std::string to_string(const Along& a);
// "12.5", "12.5s" or "12.5 s": seconds; "-100m" or "-100 m": metres of head travel. nullopt for
// anything else (a number that is not finite included).
std::optional<Along> parse_along(const std::string& text);

// A window as the analysis searched it: in travel and in time, after cutting it to the valid
// motion (the ends are then where the motion ends, and the jams there say why).
struct Searched {
    double from = 0.0;          // s
    double to = 0.0;            // s
    double from_travel = 0.0;   // m
    double to_travel = 0.0;     // m
    std::optional<Jam> before;  // the end of the valid motion that cut its start
    std::optional<Jam> after;   // the end of the valid motion that cut its end
};

}  // namespace dragon
