#include "dragon/chain.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "chain_front.hpp"
#include "jam_walk.hpp"
#include "make_path.hpp"
#include "spiral_chord.hpp"

namespace dragon {

Rect bench_rect(const BenchSpec& spec, int bench, const Vec2& front, const Vec2& rear) {
    const Vec2 axis = normalized(front - rear);
    return {0.5 * (front + rear), axis, 0.5 * spec.board_length(bench), 0.5 * spec.width};
}

namespace {

SolverError off_the_path(int i, double d) {
    return SolverError(fmt::format("handle {} does not fit on the path behind handle {} "
                                   "(link {} m): the chain runs off the path's end",
                                   i + 1, i, d));
}

// The first n handles on the plain spiral, from the head's place: the common case inline (the
// same solve as Spiral::behind), so that one link's state stays in registers for the next
// (spiral_chord.hpp). Each handle i + 1 goes to on_link(i, d, pos, tangent, place); a caller
// that ignores some of them lets the compiler leave them out.
template <class OnLink>
void walk_spiral_chain(const Spiral& spiral, const BenchSpec& spec, const Located& head, int n, OnLink&& on_link) {
    const double b = spiral.b();
    spiral_chord::Link l{head.place.u, head.pos.x(), head.pos.y(), head.memo};
    for (int i = 0; i + 1 < n; ++i) {
        const double d = spec.link_after(i);
        double tx = 0.0, ty = 0.0, th2 = 0.0;
        if (spiral_chord::within_half_turn(b, l.theta, d) && spiral_chord::next_link(b, d, l, tx, ty, th2)) {
            on_link(i, d, Vec2{l.x, l.y}, Vec2{tx, ty}, Place{0, l.theta});
            continue;
        }
        // Spiral::behind reads the place, the point and the memo; the tangent is no input.
        const Located here{{0, l.theta}, {l.x, l.y}, Vec2::Zero(), l.memo};
        const std::optional<Located> next = spiral_chord::within_half_turn(b, l.theta, d)
                                                ? std::optional<Located>(spiral.at({0, th2}))
                                                : spiral.behind(here, d);
        if (!next) throw off_the_path(i, d);
        l = {next->place.u, next->pos.x(), next->pos.y(), next->memo};
        on_link(i, d, next->pos, next->tangent, next->place);
    }
}

}  // namespace

void solve_chain_front(const Path& path, const BenchSpec& spec, double head_arc, double head_speed, int count,
                       Frame& out) {
    const int n = std::min(count, spec.handle_count());
    out.head_arc = head_arc;
    out.handles.resize(static_cast<size_t>(n));
    out.benches.resize(static_cast<size_t>(n - 1));

    Located head = path.at_arc(head_arc);
    out.handles[0] = {head.pos, head.tangent, head_speed, head.place};
    // The handle in front of the next link: where it is and its tangent.
    Vec2 front = head.pos, front_tangent = head.tangent;
    // Handle i + 1 placed behind handle i at link d: its speed and the bench between them.
    const auto link = [&](int i, double d, const Vec2& pos, const Vec2& tangent, const Place& place) {
        // Rigid link: equal velocity components along u; both tangents point along the travel.
        const Vec2 u = (front - pos) / d;
        const double along_front = dot(front_tangent, u);
        const double along_rear = dot(tangent, u);
        const double v = out.handles[static_cast<size_t>(i)].speed * along_front / along_rear;
        out.handles[static_cast<size_t>(i + 1)] = {pos, tangent, v, place};
        out.benches[static_cast<size_t>(i)] = {0.5 * (front + pos), u, 0.5 * spec.board_length(i + 1),
                                               0.5 * spec.width};
        front = pos;
        front_tangent = tangent;
    };
    if (const auto* spiral = dynamic_cast<const Spiral*>(&path)) {
        walk_spiral_chain(*spiral, spec, head, n, link);
        return;
    }
    Located cur = head;
    for (int i = 0; i + 1 < n; ++i) {
        const double d = spec.link_after(i);
        const std::optional<Located> next = path.behind(cur, d);
        if (!next) throw off_the_path(i, d);
        link(i, d, next->pos, next->tangent, next->place);
        cur = *next;
    }
}

void solve_chain(const Path& path, const BenchSpec& spec, double head_arc, double head_speed,
                 Frame& out) {
    solve_chain_front(path, spec, head_arc, head_speed, spec.handle_count(), out);
}

bool solve_spiral_chain_angles(const Path& path, const BenchSpec& spec, double head_arc, std::vector<double>& theta) {
    const auto* spiral = dynamic_cast<const Spiral*>(&path);
    if (!spiral) return false;
    const int n = spec.handle_count();
    theta.resize(static_cast<size_t>(n));
    const Located head = path.at_arc(head_arc);
    theta[0] = head.place.u;
    walk_spiral_chain(*spiral, spec, head, n, [&](int i, double, const Vec2&, const Vec2&, const Place& place) {
        theta[static_cast<size_t>(i + 1)] = place.u;
    });
    return true;
}

// What the jam searches have found: the motion is known continuous while the head's arc position
// is in [behind, ahead]. Each side has a walk (core/jam_walk.hpp) from the start outwards,
// made on first use and taken further under the lock as moments farther out are asked about;
// the bounds are read without the lock on every frame.
struct Simulation::Validity {
    std::mutex lock;
    std::atomic<double> ahead, behind;
    std::unique_ptr<jam::Walk> walk_ahead, walk_behind;
    explicit Validity(double start) : ahead(start), behind(start) {}
};

Simulation::Simulation(const Scenario& s) : scenario_(s) {
    validate(s);
    PathBuild built = make_path(s);
    path_ = std::move(built.path);
    start_arc_ = built.start_arc;
    validity_ = std::make_shared<Validity>(start_arc_);
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

void Simulation::require_on_path(double t, Key what) const {
    if (!std::isfinite(t)) throw InputError(what, error_value(t), "it must be a finite time in seconds");
    if (!arc_on_path(head_arc(t))) require_arc_on_path(head_arc(t), what, error_value(t));
}

// The checks of require_arc_on_path without a message: every frame passes them, and making the
// message's value (a formatted number) cost more than a tenth of a frame.
bool Simulation::arc_on_path(double s) const {
    return s <= path_->s_max() && s >= path_->s_min() &&
           entry_length_ + std::abs(s) + scenario_.bench.chain_length() <= kMaxReach;
}

void Simulation::require_arc_on_path(double s, Key what, const std::string& value) const {
    if (s > path_->s_max()) {
        throw InputError(what, value,
                         fmt::format("the head reaches the end of the path (the spiral's centre) at t = {:.6f} s",
                                     end_time()));
    }
    if (s < path_->s_min()) throw InputError(what, value, "it puts the head before the start of the path");
    // On the plain spiral -s is the head's arc length from the centre; on the turnaround path
    // it is at most the entry's plus |s|. The tail is a chain's length farther out at most.
    const double reach = entry_length_ + std::abs(s) + scenario_.bench.chain_length();
    if (!(reach <= kMaxReach)) {
        throw InputError(what, value,
                         fmt::format("it puts the chain {:.8g} m along the path from the spiral's centre; at most "
                                     "{:.0f} m keeps positions to 1e-8 m", reach, kMaxReach));
    }
}

double Simulation::travel_within(double t) const {
    const double x = travel(t);
    const bool forward = t >= 0.0;
    const std::optional<Jam> j = side_jam(head_arc(t), forward, false);
    if (j && (forward ? (t <= j->time && x > j->travel) : (t >= j->time && x < j->travel))) return j->travel;
    // The spiral's centre likewise: end_time() is on the path.
    return std::min(x, path_->s_max() - start_arc_);
}

std::optional<Jam> Simulation::side_jam(double s, bool forward, bool whole) const {
    Validity& v = *validity_;
    if (!whole && (forward ? s <= v.ahead.load() : s >= v.behind.load())) return std::nullopt;
    const std::lock_guard<std::mutex> hold(v.lock);
    std::unique_ptr<jam::Walk>& walk = forward ? v.walk_ahead : v.walk_behind;
    const double dir = forward ? 1.0 : -1.0;
    if (!walk) walk = std::make_unique<jam::Walk>(*path_, scenario_.bench, start_arc_, dir,
                                                  forward ? path_->s_max() : path_->s_min());
    walk->advance(whole ? dir * std::numeric_limits<double>::infinity() : s);
    (forward ? v.ahead : v.behind) = walk->known();
    if (!walk->found()) return std::nullopt;
    return jam::to_jam(*walk->found(), dir, start_arc_, scenario_.head_speed);
}

ValidRange Simulation::valid_range() const {
    ValidRange r;
    r.after = side_jam(std::numeric_limits<double>::infinity(), true, true);
    r.before = side_jam(-std::numeric_limits<double>::infinity(), false, true);
    r.to = r.after ? r.after->time : end_time();
    r.from = r.before ? r.before->time : -std::numeric_limits<double>::infinity();
    r.to_travel = r.after ? r.after->travel : travel(r.to);
    r.from_travel = r.before ? r.before->travel : -std::numeric_limits<double>::infinity();
    return r;
}

// Judged in time: valid_range().to is the jam's time, and frame(valid_range().to) must work
// however t -> arc rounds.
std::optional<Jam> Simulation::jam_before(double t) const {
    const bool forward = t >= 0.0;
    std::optional<Jam> j = side_jam(head_arc(t), forward, false);
    if (j && (forward ? t > j->time : t < j->time)) return j;
    return std::nullopt;
}

// Judged in travel, likewise.
std::optional<Jam> Simulation::jam_before_travel(double x) const {
    const bool forward = x >= 0.0;
    std::optional<Jam> j = side_jam(start_arc_ + x, forward, false);
    if (j && (forward ? x > j->travel : x < j->travel)) return j;
    return std::nullopt;
}

void Simulation::require_valid(double t, Key what) const {
    if (!std::isfinite(t)) require_on_path(t, what);
    // The jam first: past the spiral's centre the dragon has stopped following its path long
    // before, and that is the limit worth naming.
    const double on_path = std::clamp(t, -std::numeric_limits<double>::max(), end_time());
    if (const std::optional<Jam> j = jam_before(on_path)) {
        throw PastTheValidMotion(what, t, *j);
    }
    require_on_path(t, what);
}

void Simulation::require_valid_travel(double x, Key what) const {
    if (!std::isfinite(x)) throw InputError(what, error_value(x), "it must be a finite head travel in metres");
    const double on_path = std::min(x, path_->s_max() - start_arc_);
    if (const std::optional<Jam> j = jam_before_travel(on_path)) throw PastTheValidMotion(what, time_of(x), *j);
    if (!arc_on_path(start_arc_ + x)) require_arc_on_path(start_arc_ + x, what, fmt::format("{} m of head travel", x));
}

Simulation::Span Simulation::clip_to_valid(double t0, double t1, Key from_what, Key to_what) const {
    // A range starting past a jam (or ending before one, behind t = 0) has nothing valid in it.
    if (t0 >= 0.0) require_valid(t0, from_what);
    if (t1 <= 0.0) require_valid(t1, to_what);
    Span span{t0, t1, std::nullopt};
    if (t0 < 0.0) {
        if (const std::optional<Jam> j = jam_before(t0)) span.from = j->time, span.jam = j;
    }
    if (t1 > 0.0) {
        if (const std::optional<Jam> j = jam_before(t1)) span.to = j->time, span.jam = j;
    }
    require_on_path(span.from, from_what);
    require_on_path(span.to, to_what);
    return span;
}

Simulation::TravelSpan Simulation::clip_travel(double x0, double x1, Key from_what, Key to_what) const {
    if (x0 >= 0.0) require_valid_travel(x0, from_what);
    if (x1 <= 0.0) require_valid_travel(x1, to_what);
    TravelSpan span{x0, x1, std::nullopt, std::nullopt};
    if (x0 < 0.0) span.before = jam_before_travel(x0);
    if (span.before) span.from = span.before->travel;
    if (x1 > 0.0) span.after = jam_before_travel(x1);
    if (span.after) span.to = span.after->travel;
    // Past the spiral's centre the head has no place: the range ends where it arrives there.
    span.to = std::min(span.to, path_->s_max() - start_arc_);
    require_arc_on_path(start_arc_ + span.from, from_what, fmt::format("{} m of head travel", x0));
    require_arc_on_path(start_arc_ + span.to, to_what, fmt::format("{} m of head travel", x1));
    return span;
}

PastTheValidMotion::PastTheValidMotion(Key field, double t, const Jam& j)
    : PastTheValidMotion(field, error_value(t), j) {}

PastTheValidMotion::PastTheValidMotion(Key field, const std::string& value, const Jam& j)
    : InputError(field, value,
                 fmt::format("the dragon can follow its path only {} t = {:.9f} s, where {}", j.ahead ? "until" : "from",
                             j.time, describe(j))),
      jam(j),
      ahead(j.ahead) {}

std::string describe(const Jam& j) {
    const int h = j.handle;
    if (j.kind == JamKind::root_vanishes)
        return fmt::format("handle {} can no longer follow handle {}: the path at handle {} turns square to "
                           "their link, so its speed has no bound", h, h - 1, h);
    return fmt::format("handle {} would jump to a nearer point: the path between handles {} and {} swings "
                       "back out to their link's length", h, h - 1, h);
}

void Simulation::frame_into(double t, Frame& out) const {
    require_valid(t, Key::time);
    out.time = t;
    solve_chain_front(*path_, scenario_.bench, head_arc(t), scenario_.head_speed, solved_benches() + 1, out);
}

void Simulation::frame_at_travel_into(double x, Frame& out) const {
    require_valid_travel(x, Key::travel);
    out.time = time_of(x);
    solve_chain_front(*path_, scenario_.bench, start_arc_ + x, scenario_.head_speed, solved_benches() + 1, out);
}

Frame Simulation::frame_at_travel(double x) const {
    Frame f;
    frame_at_travel_into(x, f);
    return f;
}

Simulation Simulation::at_speed(double head_speed) const {
    Simulation other = *this;
    other.scenario_.head_speed = head_speed;
    validate(other.scenario_, value::head_speed);
    return other;
}

Simulation Simulation::leading(int k) const {
    Simulation lead = *this;
    lead.solved_ = std::clamp(k, 1, scenario_.bench.bench_count);
    return lead;
}

Frame Simulation::frame(double t) const {
    Frame f;
    frame_into(t, f);
    return f;
}

}  // namespace dragon
