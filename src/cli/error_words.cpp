#include "error_words.hpp"

#include <map>
#include <utility>

#include <fmt/format.h>

#include "report.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/chain.hpp"
#include "dragon/video.hpp"

namespace dragon::cli {

namespace {

// How the CLI words a value the library names: the flag that set it, and, where the library's
// field says more than the flag does, what the line adds after "is not allowed" (the codec whose
// scale a --crf is on) or the CLI's own advice in place of the library's (which may not name
// flags: the library has none).
struct FlagWords {
    FlagWords(std::string f, std::string q = "", std::string a = "")
        : flag(std::move(f)), qualifier(std::move(q)), allowed(std::move(a)) {}
    std::string flag;
    std::string qualifier;  // " for H.264": after "is not allowed"
    std::string allowed;    // replaces the library's allowed text when not empty
};

// The library's names for the values the flags set. A field missing here is worded as the
// library words it (scenario values are named as the flags name them already).
const std::map<std::string, FlagWords>& flag_of_field() {
    static const std::map<std::string, FlagWords> flags = {
        {"time range start", {"--from"}},
        {"time range end", {"--to"}},
        {"time range", {"--from/--to"}},
        {"clearance time range", {"--from/--to"}},
        {"time", {"--time"}},
        {"time step", {"--step"}},
        {"pitch grid", {"--grid"}},
        {"pitch search range start", {"--lo"}},
        {"pitch search range end", {"--hi"}},
        {"speed limit", {"--limit"}},
        {"decimals", {"--digits"}},
        {"sweep axis", {"--vary"}},
        {"measure", {"--measure"}},
        {"shard", {"--shard"}},
        // Pictures and films.
        {"picture size", {"--size"}},
        {"print size", {"--print"}},
        {"language", {"--lang"}},
        {"print width", {"--width-in"}},
        {"font size", {"--font-pt"}},
        {"dpi", {"--dpi"}},
        {"map file", {"--plot"}},
        {"frame rate", {"--fps"}},
        {"speedup", {"--speedup"}},
        {"hold", {"--hold"}},
        {"film moment", {"--at"}},
        {"H.264 quality (crf)", {"--crf", " for H.264"}},
        {"VP9 quality (crf)", {"--crf", " for VP9"}},
        {"GIF quality (crf)", {"--crf", " for .gif", "a GIF has no quality setting (--colours sets its palette)"}},
        {"encoder preset", {"--preset"}},
        {"encoder tune", {"--tune"}},
        {"palette colours", {"--colours"}},
        {"encoder threads", {"--threads"}},
    };
    return flags;
}

}  // namespace

std::string word(const InputError& e) {
    // Two flags at once, worded as the CLI always has.
    if (e.field() == "film frame count")
        return fmt::format("the film would have {} frames, more than {}: raise --speedup or lower --fps", e.value(),
                           kMaxFilmFrames);
    const auto flag = flag_of_field().find(e.field());
    if (e.field().empty() || flag == flag_of_field().end()) return e.what();
    const FlagWords& w = flag->second;
    // Benches already overlapping where a search starts: not a refusal of a --from the user may
    // never have given, but what the scenario does there, and how to find the contact.
    if (const auto* o = dynamic_cast<const OverlapAtStart*>(&e))
        return fmt::format("benches {} and {} already overlap where the search starts, at {} (by {:.6f} m): their "
                           "first contact lies before it (an earlier --from finds it)", o->bench_a, o->bench_b,
                           e.value().back() == 'm' ? e.value() + " of head travel" : "t = " + e.value() + " s",
                           o->depth);
    // A moment past the end of the valid motion: the jam in the CLI's own words.
    if (const auto* past = dynamic_cast<const PastTheValidMotion*>(&e))
        return fmt::format("{} {} is not allowed: {}", w.flag, e.value(), jam_sentence(past->jam));
    // A file whose extension names no format: said as the other output flags say it.
    if (e.field() == "map file")
        return fmt::format("{} {} has extension '{}': {}", w.flag, e.value(), extension_of(e.value()), e.allowed());
    std::string allowed = w.allowed.empty() ? e.allowed() : w.allowed;
    if (e.field() == "clearance time range") allowed += " (--no-clearance)";
    return fmt::format("{} {} is not allowed{}: {}", w.flag, e.value(), w.qualifier, allowed);
}

}  // namespace dragon::cli
