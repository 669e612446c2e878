#include "cli/scenario_flags.hpp"

#include <fmt/format.h>

namespace dragon::cli {

void ScenarioFlags::add_to(CLI::App* sub) {
    auto* g = sub;
    g->add_option("--scenario", file_, "Scenario TOML file (see assets/cumcm2024.toml)");
    g->add_option("--path", path_kind_, "Path: spiral (Q1-Q3) or turnaround (Q4-Q5)");
    g->add_option("--pitch", pitch_, "Coil-in spiral pitch, m (default 0.55)");
    g->add_option("--speed", speed_, "Head speed, m/s (default 1)");
    g->add_option("--body-count", bench_count_, "Benches in the chain, head and tail included (default 223)");
    g->add_option("--head-length", head_length_, "Head board length, m (default 3.41)");
    g->add_option("--body-length", body_length_, "Body and tail board length, m (default 2.20)");
    g->add_option("--width", width_, "Board width, m (default 0.30)");
    g->add_option("--hole-offset", hole_offset_, "Hole centre to the nearer board end, m (default 0.275)");
    g->add_option("--start-turn", start_turn_, "Turn of the spiral the head starts on (default 16)");
    g->add_option("--turn-radius", turn_radius_, "Radius of the turning space, m (default 4.5)");
    g->add_option("--turn-pitch", turn_pitch_, "Pitch of the turnaround path's spirals, m (default 1.7)");
    g->add_option("--arc-ratio", arc_ratio_, "First S-curve arc radius over the second's (default 2)");
}

Scenario ScenarioFlags::resolve() const {
    Scenario s;
    if (!file_.empty()) s = load_scenario(file_, s);
    if (!path_kind_.empty()) {
        if (path_kind_ == "spiral") s.path.kind = PathKind::spiral;
        else if (path_kind_ == "turnaround") s.path.kind = PathKind::turnaround;
        else throw InputError(fmt::format("--path {} is not allowed: use spiral or turnaround", path_kind_));
    }
    if (bench_count_) {
        if (*bench_count_ < 1 || *bench_count_ > 1000000)
            throw InputError(fmt::format("--body-count {} is not allowed: the chain needs 1 to 1000000 benches",
                                         *bench_count_));
        s.bench.bench_count = static_cast<int>(*bench_count_);
    }
    if (pitch_) s.path.pitch = *pitch_;
    if (speed_) s.head_speed = *speed_;
    if (head_length_) s.bench.head_length = *head_length_;
    if (body_length_) s.bench.body_length = *body_length_;
    if (width_) s.bench.width = *width_;
    if (hole_offset_) s.bench.hole_offset = *hole_offset_;
    if (start_turn_) s.path.start_turn = *start_turn_;
    if (turn_radius_) s.path.turn_radius = *turn_radius_;
    if (turn_pitch_) s.path.turn_pitch = *turn_pitch_;
    if (arc_ratio_) s.path.arc_ratio = *arc_ratio_;
    validate(s);
    return s;
}

}  // namespace dragon::cli
