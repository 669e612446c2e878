#include "cli/contact_search.hpp"

#include <fmt/format.h>

#include "dragon/collision.hpp"

namespace dragon::cli {

OverlapAtStart::OverlapAtStart(int a, int b, double t, double d)
    : InputError(fmt::format("benches {} and {} already overlap at t = {} s, where the search starts (by {:.6f} m): "
                             "their first contact is before it", a, b, t, d)),
      bench_a(a), bench_b(b), time(t), depth(d) {}

std::optional<Contact> first_contact_after(const Simulation& sim, double from, double to,
                                           const ContactSearchOptions& options) {
    std::optional<Contact> c = first_contact(sim, from, to, options);
    // Touching exactly at `from` is a contact at `from`; overlapping there is not.
    if (c && c->time <= from) {
        const Clearance now = clearance(c->frame);
        if (now.distance < 0.0) throw OverlapAtStart(now.bench_a, now.bench_b, from, -now.distance);
    }
    return c;
}

}  // namespace dragon::cli
