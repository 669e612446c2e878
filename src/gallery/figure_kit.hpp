// Shared pieces of the gallery's figures: sizes, labels, panel layout.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <cairo.h>

#include "dragon/chain.hpp"
#include "gallery/figures.hpp"
#include "dragon/plot.hpp"
#include "dragon/render.hpp"
#include "figure_answers.hpp"

namespace dragon::fig {

struct Context {
    Scenario base;     // the coil-in scenario (path kind spiral)
    FigureOptions opt;
    std::shared_ptr<Answers> answers;  // the scenario's answers, shared by the run's figures
    std::string figure;                // the file stem of the figure being made
    std::vector<std::string>* data_files = nullptr;  // where write_data lists the files it wrote
    int px(double gallery_px) const { return static_cast<int>(gallery_px * opt.scale + 0.5) & ~1; }
    // A figure the gallery draws gallery_w x gallery_h px at scale 1: its pixels, its text size
    // (0 on screen) and its page, at the scale or at the print size asked.
    struct Size {
        int w = 0, h = 0;
        double text_px = 0;
        Page page;
    };
    Size size(double gallery_w, double gallery_h) const;
    bool print() const { return opt.print.has_value(); }
    bool titles() const { return opt.titles.value_or(!opt.print); }
    // The figure's words in its language: `en` or `zh`, a fmt format string of the same
    // arguments in the same order.
    const char* say(const char* en, const char* zh) const { return opt.language == Language::zh ? zh : en; }
    // A scene's options with the figures' theme and language.
    SceneOptions scene_options() const;
    // Remarks about the contest's paper only for the contest's own scenario.
    bool contest() const { return is_contest_default(base); }
    // Hands every text a figure puts on its picture to opt.on_text (a no-op without one).
    void tell(const std::string& text) const;
    void tell(const Scene& scene) const;
    void tell(const Plot& plot) const;
};

// The numbers a figure draws, written beside it as CSV when FigureOptions::data asks: a header
// of column names with their units, then the rows. Numbers are written as the shortest decimal
// that reads back as the same double.
struct FigureData {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
};
std::string num(double v);
// <figure path less its extension>.csv, all-or-nothing, when c.opt.data (nothing otherwise).
void write_data(const Context& c, const std::string& figure_path, const FigureData& data);

// A straight line from a to b (world units).
Polyline segment(const Vec2& a, const Vec2& b, Rgba colour, double width_px, bool dashed = false);
// A circle as a closed polyline (world units).
Polyline circle(const Vec2& centre, double radius, Rgba colour, double width_px = 1.2, bool dashed = false);
Label label(const Vec2& at, std::string text, Rgba colour, double size_px = 13, double dx = 6, double dy = -6);
Rgba with_alpha(Rgba c, double a);
// A time for a caption: up to three decimals, no trailing zeros ("300", "412.474").
std::string seconds(double t);

// Several scenes side by side: cols x rows panels of equal size, each drawn by draw() under a
// caption strip caption_h pixels tall.
// caption_px > 0 (a print size): captions at that size, wrapped into as many lines as the strip
// holds; 0: on one line, sized from the strip.
void draw_panels(cairo_t* cr, const std::vector<Scene>& panels, const std::vector<std::string>& captions, int cols,
                 int panel_w, int panel_h, int caption_h, const Theme& theme, int gap_px, double caption_px = 0);
// A picture of w x h px painted by `paint`, in the figures' format by the path's extension: a
// palette PNG (64 colours suit flat drawings; speed-coloured pictures need 256 so the colour
// map stays smooth), an SVG or a PDF.
// `theme`: its role colours (role_colours) stay exact in a palette PNG, so a legend's tail is
// the tail's blue in every format.
// `outputs`: the run it belongs to (FigureOptions::outputs).
void write_picture(int w, int h, const std::string& path, int colours, const std::function<void(cairo_t*)>& paint,
                   const Page& page = {}, const Theme* theme = nullptr, RunOutputs* outputs = nullptr);
// The colours of the theme's roles (ground, text, head, body, tail, touching, singled out,
// outline, handles, contact, paths, turning space) as 0xRRGGBB: what a palette keeps exactly.
std::vector<std::uint32_t> role_colours(const Theme& theme);
// One scene or one plot as the whole picture, its texts told first, drawn gallery_w x
// gallery_h px at scale 1 (Context::size: scaled, or at the print size).
void write_scene(const Context& c, Scene scene, double gallery_w, double gallery_h, const std::string& path,
                 int colours = 64);
void write_plot(const Context& c, Plot plot, double gallery_w, double gallery_h, const std::string& path);

// The figures (one file each).
void link_geometry(const Context& c, const std::string& path);
void dragon_at_300s(const Context& c, const std::string& path);
void broad_phase(const Context& c, const std::string& path);
void first_contact_zoom(const Context& c, const std::string& path);
void pitch_states(const Context& c, const std::string& path);
void speeds_by_handle(const Context& c, const std::string& path);
void clearance_over_time(const Context& c, const std::string& path);
void s_curve_geometry(const Context& c, const std::string& path);
void speed_ratio_on_turnaround(const Context& c, const std::string& path);
void turnaround_scene(const Context& c, const std::string& path);

}  // namespace dragon::fig
