#include "error_words.hpp"

#include <fmt/format.h>

#include "report.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/chain.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"

namespace dragon::cli {

namespace {

// The flag that sets a key: its name with hyphens ("--bench-count"), both flags for a range
// ("--from/--to").
std::string flag_of(Key key) {
    std::string out;
    for (const char c : hyphenated(key)) out += c == '/' ? std::string("/--") : std::string(1, c);
    return "--" + out;
}

// Whether the tool sets this key with a flag of its own name: the others (a table's frame
// count, a study's entry radius) are worded as the library words them.
bool has_flag(Key key) {
    switch (key) {
        case Key::from: case Key::to: case Key::time_range: case Key::clearance_range: case Key::time:
        case Key::step: case Key::grid: case Key::lo: case Key::hi: case Key::limit: case Key::digits:
        case Key::vary: case Key::measure: case Key::shard: case Key::size: case Key::print:
        case Key::lang: case Key::width_in: case Key::font_pt: case Key::dpi: case Key::plot: case Key::fps:
        case Key::speedup: case Key::hold: case Key::at: case Key::crf_h264: case Key::crf_vp9: case Key::crf_gif:
        case Key::preset: case Key::tune: case Key::colours: case Key::threads: case Key::film_frame_count:
        case Key::tables: case Key::zoom: case Key::centre: case Key::out: case Key::resume:
        case Key::workers: case Key::scale:
            return true;
        default: return false;
    }
}

// What the line adds after "is not allowed" where the flag alone does not say which scale a
// value is on (--crf is H.264's, VP9's or a GIF's).
std::string qualifier(Key key) {
    switch (key) {
        case Key::crf_h264: return " for H.264";
        case Key::crf_vp9: return " for VP9";
        case Key::crf_gif: return " for .gif";
        default: return "";
    }
}

}  // namespace

bool takes_flag(Key key) {
    if (has_flag(key) || key_info(key).scenario != 0) return true;
    switch (key) {
        case Key::path: case Key::collision: case Key::only:
        case Key::width_cm: case Key::video_size:
        case Key::theme: case Key::speed_colours: case Key::guides: case Key::text: case Key::annotation:
        case Key::legend: case Key::inset: case Key::follow_head: case Key::titles: case Key::data: case Key::table:
        case Key::scenario: case Key::prove: case Key::clearance: case Key::format:
            return true;
        default: return false;
    }
}

std::string flag_spelling(Key key) {
    switch (key) {
        // Switches on unless switched off: their flags say "no".
        case Key::guides: case Key::text: case Key::clearance:
            return "--no-" + hyphenated(key);
        // Switches whose default differs by command (a video's legend is on, a picture's off).
        case Key::legend: case Key::inset: case Key::titles:
            return "--[no-]" + hyphenated(key);
        default: return flag_of(key);
    }
}

std::string word(const InputError& e) {
    const Key key = e.key();
    // Two flags at once, worded as the CLI always has.
    if (key == Key::film_frame_count)
        return fmt::format("the film would have {} frames, more than {}: raise --speedup or lower --fps", e.value(),
                           kMaxFilmFrames);
    // A sentence of the library's own (a rule between values, a malformed file), and the
    // scenario's values, whose sentences name them as their flags do.
    if (!has_flag(key) || dynamic_cast<const ScenarioError*>(&e)) return e.what();
    const std::string flag = flag_of(key);
    // A moment past the end of the valid motion: the jam in the CLI's own words.
    if (const auto* past = dynamic_cast<const PastTheValidMotion*>(&e))
        return fmt::format("{} {} is not allowed: {}", flag, e.value(), jam_sentence(past->jam));
    // Going on with a sweep's rows (a flag of no value): refused, or needed and not given.
    if (key == Key::resume)
        return e.value() == "false" ? fmt::format("{}: add {} to go on with it, or remove it", e.allowed(), flag)
                                    : fmt::format("{} is not allowed: {}", flag, e.allowed());
    // A file whose extension names no format: said as the other output flags say it.
    if (key == Key::plot)
        return fmt::format("{} {} has extension '{}': {}", flag, e.value(), extension_of(e.value()), e.allowed());
    std::string allowed = key == Key::crf_gif ? "a GIF has no quality setting (--colours sets its palette)" : e.allowed();
    if (key == Key::clearance_range) allowed += " (--no-clearance)";
    return fmt::format("{} {} is not allowed{}: {}", flag, e.value(), qualifier(key), allowed);
}

}  // namespace dragon::cli
