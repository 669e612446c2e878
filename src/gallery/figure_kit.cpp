#include "figure_kit.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "render/cairo_handles.hpp"
#include "render/paint.hpp"
#include "render/png8.hpp"
#include "render/vector_out.hpp"

namespace dragon::fig {

Polyline segment(const Vec2& a, const Vec2& b, Rgba colour, double width_px, bool dashed) {
    Polyline p;
    p.points = {a, b};
    p.colour = colour;
    p.width_px = width_px;
    p.dashed = dashed;
    return p;
}

Polyline circle(const Vec2& centre, double radius, Rgba colour, double width_px, bool dashed) {
    Polyline pl;
    constexpr int n = 144;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        pl.points.push_back(centre + radius * Vec2{std::cos(a), std::sin(a)});
    }
    pl.colour = colour;
    pl.width_px = width_px;
    pl.dashed = dashed;
    pl.closed = true;
    return pl;
}

Label label(const Vec2& at, std::string text, Rgba colour, double size_px, double dx, double dy) {
    Label l;
    l.pos = at;
    l.text = std::move(text);
    l.colour = colour;
    l.size_px = size_px;
    l.dx_px = dx;
    l.dy_px = dy;
    return l;
}

std::string seconds(double t) {
    std::string s = fmt::format("{:.3f}", t);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

Rgba with_alpha(Rgba c, double a) {
    c.a = a;
    return c;
}

void draw_panels(cairo_t* cr, const std::vector<Scene>& panels, const std::vector<std::string>& captions, int cols,
                 int pw, int ph, int caption_h, const Theme& theme, int gap, double caption_px) {
    cairo_set_source_rgb(cr, theme.grid.r, theme.grid.g, theme.grid.b);
    cairo_paint(cr);
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const int col = static_cast<int>(i) % cols, row = static_cast<int>(i) / cols;
        cairo_save(cr);
        cairo_translate(cr, gap + col * (pw + gap), gap + row * (ph + caption_h + gap));
        cairo_rectangle(cr, 0, 0, pw, ph + caption_h);
        cairo_clip(cr);
        cairo_set_source_rgb(cr, theme.background.r, theme.background.g, theme.background.b);
        cairo_paint(cr);
        if (i < captions.size()) {
            // Captions outside the picture, at a size that reads whatever the panel's size, on
            // one line: smaller rather than cut at the panel's edge.
            cairo_set_source_rgb(cr, theme.text.r, theme.text.g, theme.text.b);
            if (caption_px > 0) {
                const render::FittedText t =
                    render::fit_text(cr, theme.font, caption_px, captions[i], pw - 0.6 * caption_px, false, 1, true);
                for (std::size_t k = 0; k < t.lines.size(); ++k)
                    render::text(cr, theme.font, caption_px, 0.3 * caption_px,
                                 (1.05 + 1.3 * static_cast<double>(k)) * caption_px, t.lines[k]);
            } else {
                const render::FittedText t =
                    render::fit_text(cr, theme.font, 0.6 * caption_h, captions[i], pw - 0.6 * caption_h, false, 1);
                render::text(cr, theme.font, t.size, 0.3 * caption_h, 0.72 * caption_h, captions[i]);
            }
        }
        cairo_translate(cr, 0, caption_h);
        cairo_rectangle(cr, 0, 0, pw, ph);
        cairo_clip(cr);
        draw(cr, panels[i], pw, ph);
        cairo_restore(cr);
    }
}

std::string num(double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); }

void write_data(const Context& c, const std::string& figure_path, const FigureData& data) {
    if (!c.opt.data) return;
    std::filesystem::path path(figure_path);
    path.replace_extension(".csv");
    // Fields are numbers and plain words; one holding a comma or a quote is quoted.
    const auto field = [](const std::string& f) {
        if (f.find_first_of(",\"\n") == std::string::npos) return f;
        std::string q = "\"";
        for (char ch : f) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return q + "\"";
    };
    std::string text;
    const auto line = [&](const std::vector<std::string>& row) {
        for (std::size_t i = 0; i < row.size(); ++i) text += (i ? "," : "") + field(row[i]);
        text += "\n";
    };
    line(data.header);
    for (const auto& row : data.rows) line(row);
    AtomicFile out(path.string(), c.opt.outputs);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(out.temp_path().c_str(), "wb"), &std::fclose);
    if (!f) throw out.write_error(std::strerror(errno));
    if (std::fwrite(text.data(), 1, text.size(), f.get()) != text.size() || std::fflush(f.get()) != 0)
        throw out.write_error(std::strerror(errno));
    if (std::fclose(f.release()) != 0) throw out.write_error(std::strerror(errno));
    out.commit();
    if (c.data_files) c.data_files->push_back(path.string());
}

SceneOptions Context::scene_options() const {
    SceneOptions so;
    so.theme = opt.theme;
    so.language = opt.language;
    return so;
}

Context::Size Context::size(double gallery_w, double gallery_h) const {
    if (!opt.print) return {px(gallery_w), px(gallery_h), 0.0, {}};
    const PrintLayout l = print_layout(*opt.print, gallery_h / gallery_w, opt.format == "png");
    return {l.width_px, l.height_px, l.text_px, l.page};
}

std::vector<std::uint32_t> role_colours(const Theme& th) {
    std::vector<std::uint32_t> out;
    // As Cairo sets an opaque colour on an image surface: 16 bits truncated, then the top 8.
    const auto byte = [](double v) { return static_cast<std::uint32_t>(std::clamp(v, 0.0, 1.0) * (65536.0 - 1e-5)) >> 8; };
    for (const Rgba* c : {&th.background, &th.text, &th.head, &th.body, &th.tail, &th.collision, &th.highlight,
                          &th.outline, &th.handle, &th.contact, &th.guide, &th.guide_out, &th.s_curve, &th.turning_space})
        out.push_back(byte(c->r) << 16 | byte(c->g) << 8 | byte(c->b));
    return out;
}

void write_picture(int w, int h, const std::string& path, int colours, const std::function<void(cairo_t*)>& paint,
                   const Page& page, const Theme* theme, RunOutputs* outputs) {
    const render::PictureFormat format = render::picture_format(path);
    if (format != render::PictureFormat::png) {
        render::write_vector(path, format, w, h, paint, page, outputs);
        return;
    }
    // The gallery is kept small (it lives in the repository): palette PNGs.
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    {
        cairo::Context cr = cairo::make_context(surface.get());
        paint(cr.get());
    }
    render::write_png8(surface.get(), path, colours, page.dpi, theme ? role_colours(*theme) : std::vector<std::uint32_t>{},
                       outputs);
}

void Context::tell(const std::string& text) const {
    if (opt.on_text && !text.empty()) opt.on_text(figure, text);
}

void Context::tell(const Scene& s) const {
    if (!s.show_text) return;
    tell(s.annotation);
    for (const Label& l : s.labels) tell(l.text);
}

void Context::tell(const Plot& p) const {
    for (const std::string* t : {&p.title, &p.note, &p.x_label, &p.y_label}) tell(*t);
    for (const PlotSeries& s : p.series) tell(s.label);
    for (const PlotRefLine& r : p.ref_lines) tell(r.label);
    for (const PlotLabel& l : p.labels) tell(l.text);
}

void write_scene(const Context& c, Scene scene, double gallery_w, double gallery_h, const std::string& path,
                 int colours) {
    c.tell(scene);
    if (!c.titles()) scene.annotation.clear();
    const Context::Size z = c.size(gallery_w, gallery_h);
    scene.text_px = z.text_px;
    write_picture(z.w, z.h, path, colours, [&](cairo_t* cr) { draw(cr, scene, z.w, z.h); }, z.page, &scene.theme,
                  c.opt.outputs);
}

void write_plot(const Context& c, Plot plot, double gallery_w, double gallery_h, const std::string& path) {
    c.tell(plot);
    if (!c.titles()) plot.title.clear(), plot.note.clear();
    const Context::Size z = c.size(gallery_w, gallery_h);
    plot.text_px = z.text_px;
    write_picture(z.w, z.h, path, 64, [&](cairo_t* cr) { draw_plot(cr, plot, 0, 0, z.w, z.h); }, z.page, &plot.theme,
                  c.opt.outputs);
}

}  // namespace dragon::fig
