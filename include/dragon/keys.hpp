// Every value a user can set, described once. The library names a value by its Key (an error
// says which Key it refuses, never only in words); the front ends map a Key to their own
// spelling and nothing more: the CLI's flag and the web page's URL key are the name with
// hyphens (--bench-count, #bench-count=), TOML files and Python's keywords the name with
// underscores (bench_count). A front end that shows an error looks its Key up here.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace dragon {

using ScenarioValues = unsigned;

// A value a user can set, as the library names it (its description: key_info).
enum class Key : std::uint8_t {
    none,  // a sentence about several values, or about none
    // The scenario (dragon/scenario.hpp).
    pitch, speed, bench_count, head_length, body_length, width, hole_offset, start_turn, turn_radius, turn_pitch,
    arc_ratio, path,
    // Moments and windows (seconds, or "-100m" of head travel).
    from, to, time_range, clearance_range, time, travel, times, step,
    // Searches.
    grid, lo, hi, limit, digits, only, entry_radius,
    // Sweeps.
    vary, measure, shard, row,
    // Pictures: size, print size, language, view, then the look's switches and the gallery's.
    size, print, lang, width_in, width_cm, font_pt, dpi, zoom, centre, collision, format, plot, theme, speed_colours,
    guides, text, annotation, legend, inset, follow_head, titles, scale, data, table,
    // Films and videos.
    video_size, fps, speedup, hold, at, crf_h264, crf_vp9, crf_gif, preset, tune, colours, threads, keyint,
    frame_count, film_frame_count,
    // Files and runs.
    out, resume, tables, compression_level, scenario, workers, prove, clearance,
};

// One key's description: how each front end spells it, its unit and what it means.
struct KeyInfo {
    Key key;                 // which key this describes
    std::string_view name;   // snake_case; the flag and URL key have hyphens instead
    std::string_view words;  // how a sentence names it: "time range end"
    std::string_view unit;   // "m", "m/s", "s", "px", "pt", or "" (a count, a ratio, a word)
    std::string_view help;   // one line for references and tooltips
    ScenarioValues scenario = 0;  // the scenario value it sets (value::*), 0 for none
};

// A file used an old name for a key and was read all the same: which key, the old name as the
// file wrote it ("[motion] head_speed", "body-length"), and one sentence naming the file, the old
// name and the key's name today. The library returns these with what it read (a scenario, a
// sweep file, a storyboard) and never prints them; the CLI prints each as a warning line on
// stderr, Python warns with a FutureWarning.
struct KeyWarning {
    Key key;               // the key the old name sets
    std::string old_name;  // as the file wrote it
    std::string message;   // "scenario file 'x.toml': [motion] head_speed is an old name: write speed = 1 ..."
};
using KeyWarnings = std::vector<KeyWarning>;  ///< a file's warnings, in the order of its keys

// Every key, in the order of the enum (key_info(k).key == k).
std::span<const KeyInfo> all_keys();
const KeyInfo& key_info(Key k);
// The key named `name` (hyphens and underscores alike), or nullptr.
const KeyInfo* find_key(std::string_view name);
// The key named `name` exactly as TOML files and Python spell it (underscores), or nullptr.
const KeyInfo* find_toml_key(std::string_view name);
// The name with hyphens: the CLI's flag without "--", the web page's URL key.
std::string hyphenated(Key k);
// The scenario key that sets `value` (one value:: bit; the lowest one of several), Key::none if none.
Key scenario_key(ScenarioValues value);

}  // namespace dragon
