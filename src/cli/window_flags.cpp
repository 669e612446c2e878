#include "window_flags.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "dragon/errors.hpp"

namespace dragon::cli {

Along parse_along(const std::string& flag, const std::string& text) {
    if (const std::optional<Along> a = dragon::parse_along(text)) return *a;
    throw InputError(fmt::format("{} {} is not allowed: give a time in seconds (12.5, or 12.5s) or a length of the "
                                 "head's travel in metres (-100m)", flag, text.empty() ? "''" : text));
}

void WindowFlags::add_to(CLI::App* sub, const std::string& what_from, const std::string& what_to) {
    from_opt_ = sub->add_option("--from", from_, what_from + " (a time, s, or head travel with m: -100m)");
    to_opt_ = sub->add_option("--to", to_, what_to + " (a time, s, or head travel with m: 100m)");
    from_opt_->type_name("T|Xm");
    to_opt_->type_name("T|Xm");
}

RunWindow WindowFlags::resolve(const RunWindow& defaults) const {
    RunWindow w = defaults;
    if (from_) w.from = parse_along("--from", *from_);
    if (to_) w.to = parse_along("--to", *to_);
    return w;
}

}  // namespace dragon::cli
