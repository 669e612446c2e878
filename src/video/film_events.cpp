// The moments a film says in words, and how a frame carries them (clock, rate, captions).
#include <cmath>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/video.hpp"
#include "render/words.hpp"

namespace dragon {

std::string contact_caption(const CollisionMark& mark, double time, Language language) {
    return fmt::format(fmt::runtime(render::words(language).contact_caption), mark.bench_a, mark.bench_b, time);
}

std::vector<FilmEvent> clip_events(const Simulation& sim, double from, double to,
                                   const std::optional<CollisionMark>& contact, Language language) {
    const render::Words& w = render::words(language);
    std::vector<FilmEvent> out;
    const Scenario& s = sim.scenario();
    if (s.path.kind == PathKind::spiral) {
        const double t = boundary_time(sim);
        if (t > from && t <= to)
            out.push_back({t, fmt::format(fmt::runtime(w.turning_caption), s.path.turn_radius, t)});
    }
    if (contact) {
        out.push_back({to, contact_caption(*contact, to, language)});
    } else if (const std::optional<Contact> c = first_contact_covering(sim, from, to).contact; c && c->time <= to) {
        // The range passes the first contact: from there on the benches overlap.
        const CollisionMark mark{c->bench_a, c->bench_b, c->point};
        if (c->time > from) out.push_back({c->time, contact_caption(mark, c->time, language)});
        else out.push_back({from, fmt::format(fmt::runtime(w.past_contact), c->bench_a, c->bench_b, c->time)});
    }
    const ValidRange valid = sim.valid_range();
    if (valid.after && to == valid.to)
        out.push_back({to, fmt::format(fmt::runtime(w.end_caption), to,
                                       language == Language::en ? describe(*valid.after)
                                                                : render::jam_words(language, valid.after->handle,
                                                                                    valid.after->kind == JamKind::root_vanishes))});
    return out;
}

}  // namespace dragon
