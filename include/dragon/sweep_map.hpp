// Maps of a sweep's answers (dragon sweep --plot): over one varied value a line plot per
// measure, over two a heat map per measure with contour lines, a colour bar with its unit and
// the contest's dragon marked where the map holds it. Scenarios without an answer are shown as
// what they are, each kind with its own colour and legend entry: cut short by the end of the
// dragon's valid motion (hatched), refused (grey), colliding from the start, the answer below or
// above the range searched, no answer; on line plots as markers in a strip under the values,
// outside their axis.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/picture_size.hpp"
#include "dragon/render.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp (io): the run a file written below belongs to, if given

// What a map's cell holds: a value, or why it has none (each kind drawn and keyed apart).
enum class MapCell : unsigned char {
    value,        // the answer
    jam,          // cut short: the dragon cannot follow its path far enough
    refused,      // the scenario's values are not allowed (or the analysis failed)
    no_value,     // the analysis ran, and found no answer in its range
    missing,      // no row for it (a shard's map)
    below_range,  // the answer lies at or below the range searched
    above_range,  // the answer, if any, lies above the range searched
    overlapping,  // benches already overlap where the analysis starts: the chain collides
};

// One axis of a map: the quantity a sweep varied and the values it took.
struct MapAxis {
    std::string quantity;         // "bench width"
    std::string unit;             // "m", or "" for none
    std::vector<double> values;   // in any order; each once
    // Where the contest's dragon lies on this axis, when it is marked: one of `values` (mark it
    // only on a map that holds the contest's scenario).
    std::optional<double> mark;
};

// One measured quantity over the map's scenarios: a panel of its own.
struct MapPanel {
    std::string quantity;  // "minimum pitch"
    std::string unit;      // "m"
    // One per scenario: index ix * (y ? y->values.size() : 1) + iy, as the axes list their
    // values; NaN where the cell is not a value.
    std::vector<double> values;
    std::vector<MapCell> cells;  // what each cell holds, indexed as `values`
    // The legend's words for the kinds whose meaning depends on the measure.
    std::string jam_label = "cut short: the dragon cannot follow its path";
    std::string below_label = "answer below the range searched";
    std::string above_label = "answer above the range searched";
};

// A sweep's results as pictures: a heat map per panel over two axes (x, y), or line plots over
// one (x).
struct SweepMap {
    Theme theme;               // the colours and type
    MapAxis x;                 // across
    std::optional<MapAxis> y;  // none: line plots
    std::vector<MapPanel> panels;  // one per measured quantity, drawn one under another
    std::string note;          // under each panel's title: what was held fixed
    std::string mark_label = "the contest's dragon";  // the legend's words for the axes' marks
    // The body text's size, px, for a map at a print size (Plot::text_px); 0: on screen.
    double text_px = 0.0;
    // The language of the map's own words (titles, the legend of cells without a value); the
    // quantities, notes and labels above are drawn as the caller gives them.
    Language language = Language::en;
};

// "bench width (m)", or "benches" without a unit.
std::string axis_label(const std::string& quantity, const std::string& unit);

// The picture's size at scale 1: a panel of 1000 x 640 px (heat maps) or 1000 x 520 (lines) each.
std::pair<int, int> sweep_map_size(const SweepMap& map);
// Draws the panels one under the other inside (0, 0, w, h), background included.
void draw_sweep_map(cairo_t* cr, const SweepMap& map, double w, double h);
// Throws InputError (field "map file", the path, the formats allowed) unless `path` names a
// format a map can be written in: .png, .svg or .pdf.
void require_map_format(const std::string& path);
// All-or-nothing .png, .svg or .pdf of sweep_map_size(map) (a PDF as render_pdf writes one: 96
// px per inch, fonts embedded, text selectable); or, given a print size, the map that wide on
// the page with its text at that size, a PNG at its dpi: its panels a little taller than on
// screen, without titles or notes (a paper captions its figures).
void write_sweep_map(const SweepMap& map, const std::string& path, const std::optional<PrintSize>& print = std::nullopt,
                     RunOutputs* outputs = nullptr);

}  // namespace dragon
