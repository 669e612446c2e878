// The words pictures, maps and films carry by themselves, in each language (dragon/language.hpp).
// Sentences with numbers are fmt format strings (fmt::runtime): the same arguments in the same
// order in every language.
#pragma once

#include <string>

#include "dragon/language.hpp"

namespace dragon::render {

struct Words {
    // The legend of a scene.
    const char* head_outlined;     // the head, outlined, when benches are coloured by speed
    const char* benches_by_speed;
    const char* head_bench;        // the head's colour: bench 1
    const char* body;
    const char* tail;
    const char* touching;          // benches that touch or overlap
    const char* path;              // the one path of a plain spiral
    const char* path_in;
    const char* s_curve;
    const char* path_out;
    const char* turning_space;
    const char* speed_axis;        // the colour bar's title, with its unit
    // Scene texts: {time s} {pitch m}; {depth m} {bench} {bench}; {bench}.
    const char* annotation;
    const char* overlap;
    const char* bench;
    const char* bench_head;        // bench 1, the head
    // A still's default annotation: {t s} {bench} {bench} at the first contact; {t s} {pitch m}
    // {bench} {bench} {contact's t s} past it.
    const char* still_contact;
    const char* still_past_contact;
    // Films: the clock {t s}, a held frame, the events' captions.
    const char* clock;
    const char* held;
    const char* coiling_in_line;   // {pitch m} {head speed m/s}
    const char* turnaround_line;
    const char* contact_caption;   // {bench} {bench} {t s}
    const char* turning_caption;   // {radius m} {t s}
    const char* past_contact;      // {bench} {bench} {t s}
    const char* end_caption;       // {t s} {why}
    const char* jam_vanishes;      // {handle} {handle - 1}
    const char* jam_nearer;        // {handle}
    // Sweep maps.
    const char* map_over;          // {quantity} over {x} and {y}
    const char* map_against;       // {quantity} against {x}
    const char* no_value;          // the strip of scenarios without a value
    const char* contest_dragon;    // the mark of the contest's own scenario
    const char* cell_jam;
    const char* cell_refused;
    const char* cell_none;
    const char* cell_below;
    const char* cell_above;
    const char* cell_overlapping;
    const char* cell_missing;
};

const Words& words(Language language);

// The end of the valid motion in a film's words: which handle and how (Jam's kind, forward).
std::string jam_words(Language language, int handle, bool root_vanishes);

}  // namespace dragon::render
