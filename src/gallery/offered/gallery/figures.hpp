// The figure gallery: the paper's five figures done right, and plots of the quantities behind
// them. Each figure is a PNG drawn with the same renderer and plot module as everything else.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dragon/picture_size.hpp"
#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

// The smallest FigureOptions::scale: the plots' smallest text (11 px at 800 px) stays at the
// floor, kMinTextPx * 11 / 13 (tests/paper/test_layout.cpp checks every figure at it).
inline constexpr double kMinFigureScale = 0.65;

struct FigureOptions {
    Theme theme;            // light by default
    std::string asset_dir;  // where named themes are (find_asset_dir's hint; "": its default)
    double scale = 1.0;     // pixel size relative to the gallery's (about 1000 px wide)
    std::vector<std::string> only;  // names to make (e.g. "fig2_dragon_300s"); empty: all
    // "png" (palette PNGs, small for a repository), "svg" or "pdf" (for papers: vector shapes,
    // fonts embedded, text selectable).
    std::string format = "png";
    // A print size (a width on the page, text in points): every figure that wide, its text at
    // that size, PNGs at its dpi; `scale` is then unused. Unset: the gallery's pixel sizes.
    std::optional<PrintSize> print;
    // Titles and notes on the figures. Unset: on screen yes, at a print size no (a paper sets
    // its own caption under a figure; the words stay in the figure's data file, see `data`).
    std::optional<bool> titles;
    // Also write beside each figure, as <name>.csv, the numbers it draws (one header line, each
    // column's unit in it: "t (s)", "clearance (m)"), so that a paper can redraw it in its own
    // style.
    bool data = false;
    // The language of every word the figures draw (titles, notes, labels, legends, axis names).
    Language language = Language::en;
    // Hears every text each figure puts on its picture (titles, notes, captions, labels, axis
    // names), with the figure's name: what the figures say, without reading their pixels.
    std::function<void(const std::string& figure, const std::string& text)> on_text;
    // The run the figures (and the folder made for them) belong to: see dragon/atomic_file.hpp.
    // Null: each file put in place as soon as it is written.
    RunOutputs* outputs = nullptr;
};

struct FigureInfo {
    std::string name;     // file stem, e.g. "fig1_link_geometry"
    std::string caption;  // one sentence: what the figure shows
};

// Every figure the gallery holds, in order.
std::vector<FigureInfo> figure_list();

// Writes <dir>/<name>.<format> for each figure (all-or-nothing per file) from the scenario `base`
// (the coil-in figures use it as given; the turnaround ones switch its path kind). Every number
// a figure prints, and the times and pitches it shows, come from that scenario's own answers
// (its first contact, its minimum pitch); remarks about the contest's paper appear only for the
// contest's own scenario (is_contest_default). Calls `done` after each file. Throws InputError
// for an unknown name in opt.only or an unknown format. `done` hears of every file written: each
// figure, then its data file (FigureOptions::data) under the same FigureInfo.
void write_figures(const std::string& dir, const Scenario& base, const FigureOptions& opt,
                   const std::function<void(const FigureInfo&, const std::string& path)>& done = {});

}  // namespace dragon
