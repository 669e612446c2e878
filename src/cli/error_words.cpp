#include "cli/error_words.hpp"

#include <map>

#include <fmt/format.h>

#include "cli/report.hpp"
#include "dragon/chain.hpp"

namespace dragon::cli {

namespace {

// The library's names for the values the flags set. A field missing here is worded as the
// library words it (scenario values are named as the flags name them already).
const std::map<std::string, std::string>& flag_of_field() {
    static const std::map<std::string, std::string> flags = {
        {"time range start", "--from"},
        {"time range end", "--to"},
        {"time range", "--from/--to"},
        {"clearance time range", "--from/--to"},
        {"time", "--time"},
        {"time step", "--step"},
        {"pitch grid", "--grid"},
        {"pitch search range end", "--hi"},
        {"speed limit", "--limit"},
        {"decimals", "--digits"},
        {"sweep axis", "--vary"},
        {"shard", "--shard"},
    };
    return flags;
}

}  // namespace

std::string word(const InputError& e) {
    const auto flag = flag_of_field().find(e.field());
    if (e.field().empty() || flag == flag_of_field().end()) return e.what();
    // A moment past the end of the valid motion: the jam in the CLI's own words.
    if (const auto* past = dynamic_cast<const PastTheValidMotion*>(&e))
        return fmt::format("{} {} is not allowed: {}", flag->second, e.value(), jam_sentence(past->jam, past->ahead));
    std::string allowed = e.allowed();
    if (e.field() == "clearance time range") allowed += " (--no-clearance)";
    return fmt::format("{} {} is not allowed: {}", flag->second, e.value(), allowed);
}

}  // namespace dragon::cli
