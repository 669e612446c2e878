// Q4's question, "can the turning curve be made shorter?", answered by computing the S-curve
// against the radius ratio and against where the turn starts.
#include <algorithm>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "dragon/chain.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

namespace {

TurnStudyRow row_of(const SCurve& d, double turn_radius) {
    const Spiral spiral(d.pitch);
    // Coil-in spiral from the boundary to A, and (by symmetry) coil-out from B to the boundary.
    const double approach = spiral.length_to(turn_radius / spiral.b()) - spiral.length_to(d.entry_theta);
    return {d.ratio, d.entry_radius, d.r1, d.r2, d.angle1, d.length, d.length + 2.0 * approach,
            d.max_radius, std::nullopt};
}

}  // namespace

std::vector<TurnStudyRow> length_vs_ratio(double pitch, double turn_radius,
                                          const std::vector<double>& ratios) {
    std::vector<TurnStudyRow> rows;
    for (double k : ratios) rows.push_back(row_of(design_s_curve(pitch, turn_radius, k), turn_radius));
    return rows;
}

std::vector<TurnStudyRow> length_vs_entry_radius(double pitch, double turn_radius, double ratio,
                                                 const std::vector<double>& entry_radii) {
    std::vector<TurnStudyRow> rows;
    for (double r : entry_radii) {
        if (r > turn_radius)
            throw InputError(Key::entry_radius, error_value(r),
                             fmt::format("the turn must start inside the turning space (radius {})", turn_radius));
        rows.push_back(row_of(design_s_curve(pitch, r, ratio), turn_radius));
    }
    return rows;
}

void followability(std::vector<TurnStudyRow>& rows, double pitch, const BenchSpec& bench, double head_speed) {
    for (TurnStudyRow& r : rows) {
        const TurnaroundPath path(design_s_curve(pitch, r.entry_radius, r.ratio));
        // From far out on the coil-in spiral (where the search starts on calm path) for ever.
        r.jam = find_jam(path, bench, path.join_arc(1), head_speed, -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity());
    }
}


std::optional<Jam> turnaround_jam(const Simulation& sim) {
    const ValidRange r = sim.valid_range();
    return r.before ? r.before : r.after;
}

TurnaroundStudy study_turnaround(const Scenario& s) {
    const double pitch = s.path.turn_pitch, radius = s.path.turn_radius, ratio = s.path.arc_ratio;
    TurnaroundStudy st;
    st.design = design_s_curve(pitch, radius, ratio);
    std::vector<double> ratios = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 10.0};
    if (std::find(ratios.begin(), ratios.end(), ratio) == ratios.end()) ratios.push_back(ratio);
    std::sort(ratios.begin(), ratios.end());
    st.by_ratio = length_vs_ratio(pitch, radius, ratios);
    std::vector<double> radii;
    for (int k = 0; k <= 10; ++k) radii.push_back(radius * (1.0 - 0.05 * k));
    st.by_entry = length_vs_entry_radius(pitch, radius, ratio, radii);
    followability(st.by_ratio, pitch, s.bench, s.head_speed);
    followability(st.by_entry, pitch, s.bench, s.head_speed);
    // The scenario's own S-curve is the one every command simulates: its row says what they say.
    Scenario turn = s;
    turn.path.kind = PathKind::turnaround;
    st.design_jam = turnaround_jam(Simulation(turn));
    for (TurnStudyRow& r : st.by_ratio)
        if (r.ratio == ratio) r.jam = st.design_jam;
    for (TurnStudyRow& r : st.by_entry)
        if (r.entry_radius == radius) r.jam = st.design_jam;

    auto [lo, hi] = std::minmax_element(st.by_ratio.begin(), st.by_ratio.end(),
                                        [](const TurnStudyRow& a, const TurnStudyRow& b) {
                                            return a.s_curve_length < b.s_curve_length;
                                        });
    st.ratio_spread = hi->s_curve_length - lo->s_curve_length;
    return st;
}

std::string study_csv(const TurnaroundStudy& study) {
    std::string out = "study,ratio,entry_radius,r1,r2,angle,s_curve_length,inside_length,max_radius,"
                      "followable,jam_time,jam_handle,jam_kind\n";
    auto rows = [&](const char* name, const std::vector<TurnStudyRow>& rs) {
        for (const TurnStudyRow& r : rs) {
            out += fmt::format("{},{:.6f},{:.6f},{:.9f},{:.9f},{:.9f},{:.9f},{:.9f},{:.9f},", name, r.ratio,
                               r.entry_radius, r.r1, r.r2, r.angle, r.s_curve_length, r.inside_length, r.max_radius);
            if (r.jam) out += fmt::format("false,{:.9f},{},{}\n", r.jam->time, r.jam->handle, to_string(r.jam->kind));
            else out += "true,,,\n";
        }
    };
    rows("ratio", study.by_ratio);
    rows("entry_radius", study.by_entry);
    return out;
}

}  // namespace dragon
