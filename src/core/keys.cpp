#include "dragon/keys.hpp"

#include <array>
#include <cstddef>

#include "dragon/scenario.hpp"

namespace dragon {

namespace {

constexpr std::array kKeys = {
    KeyInfo{Key::none, "", "", "", ""},
    KeyInfo{Key::pitch, "pitch", "pitch", "m", "the plain spiral's pitch: its turns' spacing", value::pitch},
    KeyInfo{Key::speed, "speed", "head speed", "m/s", "the head's speed along the path", value::head_speed},
    KeyInfo{Key::bench_count, "bench_count", "bench count", "", "benches in the chain, the head's included",
            value::bench_count},
    KeyInfo{Key::head_length, "head_length", "head length", "m", "the head's board length", value::head_length},
    KeyInfo{Key::body_length, "body_length", "body length", "m", "every other board's length", value::body_length},
    KeyInfo{Key::width, "width", "width", "m", "the boards' width", value::width},
    KeyInfo{Key::hole_offset, "hole_offset", "hole offset", "m", "a handle's hole from its board's end",
            value::hole_offset},
    KeyInfo{Key::start_turn, "start_turn", "start turn", "", "the plain spiral's turn where the head starts",
            value::start_turn},
    KeyInfo{Key::turn_radius, "turn_radius", "turn radius", "m", "the turning space's radius", value::turn_radius},
    KeyInfo{Key::turn_pitch, "turn_pitch", "turn pitch", "m", "the turnaround path's spiral pitch", value::turn_pitch},
    KeyInfo{Key::arc_ratio, "arc_ratio", "arc ratio", "", "the S-curve's arc radii r1/r2", value::arc_ratio},
    KeyInfo{Key::path, "path", "path", "", "spiral or turnaround"},
    KeyInfo{Key::from, "from", "time range start", "s", "where a window starts: seconds, or \"-100m\" of head travel"},
    KeyInfo{Key::to, "to", "time range end", "s", "where a window ends: seconds, or \"100m\" of head travel"},
    KeyInfo{Key::time_range, "from/to", "time range", "s", "a window: its start and end"},
    KeyInfo{Key::clearance_range, "from/to", "clearance time range", "s", "the window the clearance is scanned over"},
    KeyInfo{Key::time, "time", "time", "s", "a moment of the motion"},
    KeyInfo{Key::travel, "travel", "head travel", "m", "a moment as the head's travel along the path"},
    KeyInfo{Key::times, "times", "times", "s", "moments of the motion"},
    KeyInfo{Key::step, "step", "time step", "s", "a table's spacing in time"},
    KeyInfo{Key::grid, "grid", "pitch grid", "m", "the minimum-pitch search's grid spacing"},
    KeyInfo{Key::lo, "lo", "pitch search range start", "m", "the smallest pitch searched"},
    KeyInfo{Key::hi, "hi", "pitch search range end", "m", "the largest pitch searched"},
    KeyInfo{Key::limit, "limit", "speed limit", "m/s", "the speed no handle may exceed"},
    KeyInfo{Key::digits, "digits", "decimals", "", "decimals of a .csv or .json table"},
    KeyInfo{Key::only, "only", "question", "", "the questions answered, q1 to q5"},
    KeyInfo{Key::entry_radius, "entry_radius", "entry radius", "m", "where the turnaround study's path enters"},
    KeyInfo{Key::vary, "vary", "sweep axis", "", "a varied value: name=values"},
    KeyInfo{Key::measure, "measure", "measure", "", "what a sweep measures in every scenario"},
    KeyInfo{Key::shard, "shard", "shard", "", "the part of a sweep run here: K/N"},
    KeyInfo{Key::row, "row", "row", "", "a sweep's row"},
    KeyInfo{Key::size, "size", "picture size", "px", "a picture's size, WIDTHxHEIGHT"},
    KeyInfo{Key::print, "print", "print size", "", "a print size: column, page or a4"},
    KeyInfo{Key::lang, "lang", "language", "", "the words' language: en or zh"},
    KeyInfo{Key::width_in, "width_in", "print width", "in", "the printed width in inches"},
    KeyInfo{Key::width_cm, "width_cm", "print width", "cm", "the printed width in centimetres"},
    KeyInfo{Key::font_pt, "font_pt", "font size", "pt", "the printed text size"},
    KeyInfo{Key::dpi, "dpi", "dpi", "", "a printed PNG's dots per inch"},
    KeyInfo{Key::zoom, "zoom", "zoom", "m", "the view's width: a square this many metres across"},
    KeyInfo{Key::centre, "centre", "centre", "m", "the view's centre, x,y"},
    KeyInfo{Key::collision, "collision", "collision", "", "the moment of the first contact"},
    KeyInfo{Key::format, "format", "format", "", "a picture's format: png, svg or pdf"},
    KeyInfo{Key::plot, "plot", "map file", "", "a sweep's map, .png, .svg or .pdf"},
    KeyInfo{Key::theme, "theme", "theme", "", "the colours and font: light, dark or a .toml file"},
    KeyInfo{Key::speed_colours, "speed_colours", "speed colours", "", "each bench coloured by its speed, with a colour bar"},
    KeyInfo{Key::guides, "guides", "guides", "", "the path and the turning-space circle drawn (on unless switched off)"},
    KeyInfo{Key::text, "text", "text", "", "any text drawn at all (on unless switched off)"},
    KeyInfo{Key::annotation, "annotation", "annotation", "", "the text at the top left (default: time and pitch)"},
    KeyInfo{Key::legend, "legend", "legend", "", "a key to the colours"},
    KeyInfo{Key::inset, "inset", "inset", "", "with a zoom, the whole dragon small in a corner"},
    KeyInfo{Key::follow_head, "follow_head", "follow head", "", "the view centred on the head"},
    KeyInfo{Key::titles, "titles", "titles", "", "the gallery's titles and notes on its figures"},
    KeyInfo{Key::scale, "scale", "figure scale", "", "the gallery's pixel size against its ~1000 px"},
    KeyInfo{Key::data, "data", "figure data", "", "each figure's numbers written beside it as NAME.csv"},
    KeyInfo{Key::table, "table", "handle table", "", "the paper-style handle table: latex, markdown or csv"},
    KeyInfo{Key::video_size, "size", "video size", "px", "a film's size, WIDTHxHEIGHT"},
    KeyInfo{Key::fps, "fps", "frame rate", "1/s", "frames per second"},
    KeyInfo{Key::speedup, "speedup", "speedup", "", "seconds of motion per second of film"},
    KeyInfo{Key::hold, "hold", "hold", "s", "how long the last frame stays"},
    KeyInfo{Key::at, "at", "film moment", "s", "the film's moment a poster shows"},
    KeyInfo{Key::crf_h264, "crf", "H.264 quality (crf)", "", "H.264's constant rate factor"},
    KeyInfo{Key::crf_vp9, "crf", "VP9 quality (crf)", "", "VP9's constant rate factor"},
    KeyInfo{Key::crf_gif, "crf", "GIF quality (crf)", "", "a GIF has none (colours sets its palette)"},
    KeyInfo{Key::preset, "preset", "encoder preset", "", "libx264's speed preset"},
    KeyInfo{Key::tune, "tune", "encoder tune", "", "libx264's tuning"},
    KeyInfo{Key::colours, "colours", "palette colours", "", "a GIF's palette size"},
    KeyInfo{Key::threads, "threads", "encoder threads", "", "the codec's threads"},
    KeyInfo{Key::keyint, "keyint", "key frame interval", "s", "seconds between key frames"},
    KeyInfo{Key::frame_count, "frame_count", "frame count", "", "frames of a table or video"},
    KeyInfo{Key::film_frame_count, "frame_count", "film frame count", "", "frames of a film"},
    KeyInfo{Key::out, "out", "output file", "", "the file written"},
    KeyInfo{Key::resume, "resume", "resume", "", "go on with a sweep's unfinished rows file instead of starting afresh"},
    KeyInfo{Key::tables, "tables", "table format", "", "the paper's tables: latex, markdown or csv"},
    KeyInfo{Key::compression_level, "compression_level", "compression level", "", "a workbook's zlib level, 0 to 9"},
    KeyInfo{Key::scenario, "scenario", "scenario file", "", "a scenario .toml file (values given beside it win)"},
    KeyInfo{Key::workers, "workers", "workers", "", "how many computations run at once (default: one per core)"},
    KeyInfo{Key::prove, "prove", "prove", "", "the answer proved, not only searched: the first contact's steps and the valid motion (collide, turnaround), the smallest clearance (turnaround), every feasible pitch (min-pitch), the largest head speed (max-speed), each of these (solve)"},
    KeyInfo{Key::clearance, "clearance", "clearance", "", "the turnaround check's first contact and clearance (on unless switched off)"},
};

// The table is in the enum's order: key_info indexes it.
constexpr bool in_order() {
    for (std::size_t i = 0; i < kKeys.size(); ++i)
        if (static_cast<std::size_t>(kKeys[i].key) != i) return false;
    return true;
}
static_assert(in_order(), "kKeys must list the keys in the order of enum Key");
static_assert(static_cast<std::size_t>(Key::clearance) + 1 == kKeys.size(), "a key without its description");

bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const char x = a[i] == '-' ? '_' : a[i], y = b[i] == '-' ? '_' : b[i];
        if (x != y) return false;
    }
    return true;
}

}  // namespace

std::span<const KeyInfo> all_keys() { return kKeys; }

const KeyInfo& key_info(Key k) { return kKeys[static_cast<std::size_t>(k)]; }

const KeyInfo* find_key(std::string_view name) {
    if (name.empty()) return nullptr;
    for (const KeyInfo& k : kKeys)
        if (same_name(k.name, name)) return &k;
    return nullptr;
}

const KeyInfo* find_toml_key(std::string_view name) {
    if (name.empty()) return nullptr;
    for (const KeyInfo& k : kKeys)
        if (k.name == name) return &k;
    return nullptr;
}

std::string hyphenated(Key k) {
    std::string out(key_info(k).name);
    for (char& c : out)
        if (c == '_') c = '-';
    return out;
}

Key scenario_key(ScenarioValues value) {
    for (const KeyInfo& k : kKeys)
        if (k.scenario != 0 && (value & k.scenario)) return k.key;
    return Key::none;
}

}  // namespace dragon
