#include "dragon/chain.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/make_path.hpp"

namespace dragon {

Rect bench_rect(const BenchSpec& spec, int bench, Vec2 front, Vec2 rear) {
    const Vec2 axis = normalized(front - rear);
    return {0.5 * (front + rear), axis, 0.5 * spec.board_length(bench), 0.5 * spec.width};
}

void solve_chain(const Path& path, const BenchSpec& spec, double head_arc, double head_speed,
                 Frame& out) {
    const int n = spec.handle_count();
    out.head_arc = head_arc;
    out.handles.resize(static_cast<size_t>(n));
    out.benches.resize(static_cast<size_t>(spec.bench_count));

    Located cur = path.at_arc(head_arc);
    out.handles[0] = {cur.pos, cur.tangent, head_speed, cur.place};
    for (int i = 0; i + 1 < n; ++i) {
        const double d = spec.link_after(i);
        const std::optional<Located> next = path.behind(cur, d);
        if (!next) {
            throw InputError(fmt::format("handle {} does not fit on the path behind handle {} "
                                         "(link {} m): the chain runs off the path's end",
                                         i + 1, i, d));
        }
        // Rigid link: equal velocity components along u; both tangents point along the travel.
        const Vec2 u = (cur.pos - next->pos) / d;
        const double along_front = dot(cur.tangent, u);
        const double along_rear = dot(next->tangent, u);
        const double v = out.handles[static_cast<size_t>(i)].speed * along_front / along_rear;
        out.handles[static_cast<size_t>(i + 1)] = {next->pos, next->tangent, v, next->place};
        out.benches[static_cast<size_t>(i)] = {0.5 * (cur.pos + next->pos), u,
                                               0.5 * spec.board_length(i + 1), 0.5 * spec.width};
        cur = *next;
    }
}

Simulation::Simulation(const Scenario& s) : scenario_(s) {
    validate(s);
    PathBuild built = make_path(s);
    path_ = std::move(built.path);
    start_arc_ = built.start_arc;
    if (s.path.kind == PathKind::turnaround) {
        const Spiral coil(s.path.turn_pitch);
        entry_length_ = coil.length_to(s.path.turn_radius / coil.b());
    }
}

double Simulation::end_time() const {
    const double smax = path_->s_max();
    if (std::isinf(smax)) return std::numeric_limits<double>::infinity();
    // The division rounds: step back until the head is on the path at the time returned, so
    // that frame(end_time()) always works (at 180 m/s it was one rounding past the centre).
    double t = (smax - start_arc_) / scenario_.head_speed;
    while (head_arc(t) > smax) t = std::nextafter(t, -INFINITY);
    return t;
}

void Simulation::require_on_path(double t, const char* what) const {
    if (!std::isfinite(t))
        throw InputError(fmt::format("{} {} is not allowed: it must be a finite time in seconds", what, t));
    const double s = head_arc(t);
    if (s > path_->s_max()) {
        throw InputError(fmt::format("{} {} is not allowed: the head reaches the end of the path "
                                     "(the spiral's centre) at t = {:.6f} s", what, t, end_time()));
    }
    if (s < path_->s_min()) {
        throw InputError(fmt::format("{} {} is not allowed: it puts the head before the start of the path",
                                     what, t));
    }
    // On the plain spiral -s is the head's arc length from the centre; on the turnaround path
    // it is at most the entry's plus |s|. The tail is a chain's length farther out at most.
    const double reach = entry_length_ + std::abs(s) + scenario_.bench.chain_length();
    if (!(reach <= kMaxReach)) {
        throw InputError(fmt::format("{} {} is not allowed: it puts the chain {:.8g} m along the path from "
                                     "the spiral's centre; at most {:.0f} m keeps positions to 1e-8 m",
                                     what, t, reach, kMaxReach));
    }
}

void Simulation::frame_into(double t, Frame& out) const {
    require_on_path(t, "time");
    out.time = t;
    solve_chain(*path_, scenario_.bench, head_arc(t), scenario_.head_speed, out);
}

Frame Simulation::frame(double t) const {
    Frame f;
    frame_into(t, f);
    return f;
}

}  // namespace dragon
