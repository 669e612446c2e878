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
    int px(double gallery_px) const { return static_cast<int>(gallery_px * opt.scale + 0.5) & ~1; }
    // Remarks about the contest's paper only for the contest's own scenario.
    bool contest() const { return is_contest_default(base); }
    // Hands every text a figure puts on its picture to opt.on_text (a no-op without one).
    void tell(const std::string& text) const;
    void tell(const Scene& scene) const;
    void tell(const Plot& plot) const;
};

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
void draw_panels(cairo_t* cr, const std::vector<Scene>& panels, const std::vector<std::string>& captions, int cols,
                 int panel_w, int panel_h, int caption_h, const Theme& theme, int gap_px);
// A picture of w x h px painted by `paint`, in the figures' format by the path's extension: a
// palette PNG (64 colours suit flat drawings; speed-coloured pictures need 256 so the colour
// map stays smooth), an SVG or a PDF.
void write_picture(int w, int h, const std::string& path, int colours, const std::function<void(cairo_t*)>& paint);
// One scene or one plot as the whole picture, its texts told first.
void write_scene(const Context& c, const Scene& scene, int w, int h, const std::string& path, int colours = 64);
void write_plot(const Context& c, const Plot& plot, int w, int h, const std::string& path);

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
