// The collision figures: Fig. 3 (the broad phase around one bench), Fig. 4 (the first contact,
// zoomed in), Fig. 5 (the state at several pitches around the true minimum) and the clearance
// against time.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "render/cairo_handles.hpp"
#include "dragon/collision.hpp"
#include "figure_kit.hpp"
#include "render/paint.hpp"

namespace dragon::fig {

namespace {

// The last moment the coil-in figures show: the first contact, or with none the end of the run.
double last_moment(const Context& c, const Simulation& sim) {
    return shown_span(sim, 0.0, sim.end_time(), c.answers->contact()).to;
}

// Non-adjacent benches of a chain of n other than `bench`: every bench but itself and its
// one or two neighbours.
int others(int bench, int n) { return n - 1 - (bench > 1) - (bench < n); }

// The height on the page of a picture w x h px that is as wide as the print size asks, in.
double opt_height_in(const PrintSize& print, int w, int h) { return print.width_in * h / w; }

// The tallest figure a page's text block holds, pt: US letter less 1 in margins, 9 in (A4 less
// 2.5 cm margins is 700 pt).
constexpr double kTextBlockHeightPt = 648.0;

}  // namespace

void broad_phase(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const std::optional<Contact>& hit = c.answers->contact();
    const Frame f = hit ? hit->frame : sim.frame(last_moment(c, sim));
    const Theme& th = c.opt.theme;
    // The bench nearer the head of the touching pair (the head itself on the contest's dragon);
    // without a contact, the head.
    const int focus = hit ? hit->bench_a : 1;
    const double margin = kBroadPhaseMargin;  // the searches' broad-phase margin, m
    const Rect& r = f.benches[focus - 1];
    // The sweep band: the bench's bounding box on x, widened by half the margin each side (as in
    // candidate_pairs; a bench whose own band overlaps it goes on to the circle test).
    const double reach = r.half_length * std::abs(r.axis.x()) + r.half_width * std::abs(r.axis.y()) + 0.5 * margin;
    // Twice the circle of bench + margin across: the candidates and their neighbours.
    const double extent = 4.0 * (half_diagonal(r) + margin);

    std::vector<int> candidates;
    for (auto [i, j] : candidate_pairs(f, margin))
        if (i == focus || j == focus) candidates.push_back(i == focus ? j : i);

    SceneOptions so = c.scene_options();
    so.theme = th;
    so.title_band = true;  // a title hides nothing
    so.camera = Camera::at(r.centre, extent);
    so.highlight_benches = candidates;
    const std::string when =
        hit ? fmt::format(fmt::runtime(c.say("at the first contact (t = {:.2f} s)", "在首次碰撞时（t = {:.2f} s）")), hit->time)
            : fmt::format(fmt::runtime(c.say("at t = {:.2f} s (no two benches touch on the way in)",
                                             "在 t = {:.2f} s（盘入途中没有板凳相碰）")), f.time);
    so.annotation = fmt::format(
        fmt::runtime(c.say("Broad phase around bench {} {}: {} of {} benches are candidates\n"
                           "Sweep and prune on x (box extents), then bounding circles within a margin of {:g} m (purple); "
                           "only these get the exact test.",
                           "第 {} 节板凳周围的粗筛 {}：{} 节板凳（共 {} 节）为候选\n"
                           "先按 x 方向的包围盒扫描剪枝，再取外接圆相距不超过 {:g} m 者（紫色）；只有这些做精确检测。")),
        focus, when, candidates.size(), others(focus, static_cast<int>(f.benches.size())), margin);
    Scene s = make_scene(sim, f, so);

    // The sweep on x, then the circle test: a candidate's bounding circle comes within the
    // margin of the focus bench's.
    const double x0 = r.centre.x() - reach, x1 = r.centre.x() + reach;
    for (double x : {x0, x1})
        s.polylines.push_back(segment({x, r.centre.y() - extent}, {x, r.centre.y() + extent}, th.text, 1.2, true));
    for (int bench : candidates) {
        const Rect& b = f.benches[bench - 1];
        s.polylines.push_back(circle(b.centre, half_diagonal(b), with_alpha(th.highlight, 0.45), 1.0));
    }
    s.polylines.push_back(circle(r.centre, half_diagonal(r) + margin, th.head, 2.2, true));
    s.polylines.push_back(circle(r.centre, half_diagonal(r), th.head, 1.6));
    s.labels.push_back(label(r.centre + Vec2{0, half_diagonal(r) + margin},
                             fmt::format(fmt::runtime(c.say("bench {}'s bounding circle + margin", "第 {} 节板凳的外接圆 + 余量")),
                                         focus), th.head, 14, 6, -8));
    s.labels.push_back(label({x1, r.centre.y() - 0.42 * extent}, c.say("sweep band on x", "x 方向扫描带"), th.text, 14, 6, 0));
    write_scene(c, s, 900, 900, path);
    FigureData data{{"bench", "centre x (m)", "centre y (m)", "half diagonal (m)", "candidate"}, {}};
    for (std::size_t k = 0; k < f.benches.size(); ++k) {
        const Rect& b = f.benches[k];
        const int bench = static_cast<int>(k) + 1;
        if (distance(b.centre, r.centre) > extent) continue;  // out of the picture
        const bool candidate = std::find(candidates.begin(), candidates.end(), bench) != candidates.end();
        data.add({std::to_string(bench), num(b.centre.x()), num(b.centre.y()), num(half_diagonal(b)),
                  bench == focus ? "focus" : candidate ? "1" : "0"});
    }
    write_data(c, path, data);
}

void first_contact_zoom(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const std::optional<Contact>& hit = c.answers->contact();
    const Frame f = hit ? hit->frame : sim.frame(last_moment(c, sim));
    const Theme& th = c.opt.theme;
    // Without a contact, the closest pair at the last moment, said to be apart.
    const Clearance closest = clearance(f);
    const int bench_a = hit ? hit->bench_a : closest.bench_a, bench_b = hit ? hit->bench_b : closest.bench_b;
    if (bench_a == 0) {  // fewer than three benches: no pair that could touch
        SceneOptions so = c.scene_options();
        so.theme = th;
        so.title_band = true;  // a title hides nothing
        so.annotation = fmt::format(fmt::runtime(c.say("No contact: a chain of {} {} no two that do not share a handle",
                                                       "无碰撞：{} 节{}中没有两节不共用把手的板凳")),
                                    f.benches.size(), f.benches.size() == 1 ? c.say("bench has", "板凳") : c.say("benches has", "板凳"));
        write_scene(c, make_scene(sim, f, so), 1000, 1000, path);
        write_data(c, path, FigureData{{"bench", "corner", "x (m)", "y (m)"}, {}});
        return;
    }
    const Rect& a = f.benches[bench_a - 1];
    const Rect& b = f.benches[bench_b - 1];
    const Vec2 p = contact_point(a, b);
    const Separation sep = separation(a, b);
    // Boards and the gap between them, large: eight board widths, or three gaps if wider.
    const double extent = std::max(8.0 * c.base.bench.width, 3.0 * sep.distance);

    SceneOptions so = c.scene_options();
    so.theme = th;
    so.title_band = true;  // a title hides nothing
    so.camera = Camera::at(p, extent);
    if (hit) {
        so.collision = CollisionMark{bench_a, bench_b, p};
        so.annotation = fmt::format(fmt::runtime(c.say("First contact at t = {:.6f} s: bench {} touches bench {} (head at r = {:.4f} m)\n"
                                                       "Benches are numbered from 1 at the head; the small numbers are handles, from 0 "
                                                       "at the head's front",
                                                       "首次碰撞 t = {:.6f} s：第 {} 节板凳碰到第 {} 节（龙头位于 r = {:.4f} m）\n"
                                                       "板凳从龙头起编号为 1；小号数字是把手，从龙头前把手起编号为 0")),
                                    hit->time, bench_a, bench_b, hit->head_radius);
    } else {
        so.highlight_benches = {bench_a, bench_b};
        so.annotation = fmt::format(fmt::runtime(c.say("No contact on the way in: at t = {:.6f} s, the last moment, the closest benches "
                                                       "are {} and {}, {:.6f} m apart\n"
                                                       "Benches are numbered from 1 at the head; the small numbers are handles, from 0 "
                                                       "at the head's front",
                                                       "盘入途中无碰撞：在最后时刻 t = {:.6f} s，最近的板凳是第 {} 与第 {} 节，相距 {:.6f} m\n"
                                                       "板凳从龙头起编号为 1；小号数字是把手，从龙头前把手起编号为 0")),
                                    f.time, bench_a, bench_b, closest.distance);
    }
    // The whole dragon in the inset (its colours in the legend: the tail is the blue bench).
    so.show_inset = true;
    so.show_legend = true;
    Scene s = make_scene(sim, f, so);
    // Each bench of the pair named a little way back from the contact along its own board; the
    // label-placement rule keeps the names clear of everything else.
    auto name_at = [&](const Rect& r, int bench) {
        const double along = std::clamp(dot(p - r.centre, r.axis), -r.half_length, r.half_length);
        const double back = std::clamp(along + (along > 0 ? -0.23 : 0.23) * extent, -r.half_length, r.half_length);
        Label l = label(r.centre + back * r.axis,
                        bench == 1 ? std::string(c.say("bench 1 (head)", "第 1 节（龙头）"))
                                   : fmt::format(fmt::runtime(c.say("bench {}", "第 {} 节")), bench),
                        th.text, 15, -40, -16);
        l.bench = bench;
        s.labels.push_back(l);
    };
    name_at(a, bench_a);
    name_at(b, bench_b);
    s.labels.push_back(label(p, hit ? fmt::format(fmt::runtime(c.say("contact: separation {:.1e} m", "接触：间距 {:.1e} m")), sep.distance)
                                    : fmt::format(fmt::runtime(c.say("closest: {:.6f} m apart", "最近：相距 {:.6f} m")), sep.distance),
                             th.text, 13, 16, 26));
    // The handles in view, numbered; a number may lie on the bench the handle ends.
    for (std::size_t i = 0; i < f.handles.size(); ++i)
        if (const Vec2 d = f.handles[i].pos - p; std::abs(d.x()) < 0.5 * extent && std::abs(d.y()) < 0.5 * extent) {
            Label l = label(f.handles[i].pos, fmt::format("{}", i), with_alpha(th.text, 0.7), 12, 8, 14);
            l.bench = std::max(1, static_cast<int>(i));  // handle i joins benches i and i + 1
            l.benches = i == 0 ? 1 : 2;
            s.labels.push_back(l);
        }
    write_scene(c, s, 1000, 1000, path);
    FigureData data{{"bench", "corner", "x (m)", "y (m)"}, {}};
    for (int bench : {bench_a, bench_b}) {
        const Corners k = corners(f.benches[static_cast<std::size_t>(bench - 1)]);
        for (std::size_t i = 0; i < 4; ++i)
            data.add({std::to_string(bench), std::to_string(i + 1), num(k.p[i].x()), num(k.p[i].y())});
    }
    data.add({hit ? "contact" : "closest", "", num(p.x()), num(p.y())});
    write_data(c, path, data);
}

// Panel pitches a round step apart around `centre`, none below `lo`: three below it and three
// above (or all above lo when it is near).
std::vector<double> panel_pitches(double centre, double lo, double step) {
    double below = std::floor(centre / step) * step;
    if (below >= centre) below -= step;
    std::vector<double> out;
    for (int k = -2; out.size() < 6; ++k)
        if (const double p = below + k * step; p >= lo) out.push_back(p);
    return out;
}

void pitch_states(const Context& c, const std::string& path) {
    const Theme& th = c.opt.theme;
    const MinPitch& least = c.answers->min_pitch();
    const double radius = c.base.path.turn_radius;
    // Six panels around the scenario's own minimum pitch, 0.7 to 1.7 % of it apart (or around
    // the window's top when nothing in it is collision-free). Each is its own run to the
    // boundary: they show the minimum's neighbourhood; `min_pitch` found the minimum itself.
    const double centre = std::isnan(least.pitch) ? least.search_hi : least.pitch;
    const double step = render::nice_floor(centre / 60.0);
    const std::vector<double> pitches = panel_pitches(centre, least.search_lo, step);
    const int decimals = std::max(3, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    std::vector<Scene> panels;
    std::vector<std::string> captions;
    FigureData data{{"pitch (m)", "touch", "bench a", "bench b", "t (s)", "head radius (m)"}, {}};
    for (double pitch : pitches) {
        Scenario sc = c.base;
        sc.path.pitch = pitch;
        const Simulation sim(sc);
        SceneOptions so = c.scene_options();
        so.theme = th;
        so.show_scale_bar = false;
        so.annotation = "";
        const auto hit = contact_before_boundary(c.base, pitch);
        Frame f;
        if (hit) {
            f = hit->frame;
            const Vec2 q = contact_point(f.benches[hit->bench_a - 1], f.benches[hit->bench_b - 1]);
            so.collision = CollisionMark{hit->bench_a, hit->bench_b, q};
            data.add({num(pitch), "1", std::to_string(hit->bench_a), std::to_string(hit->bench_b), num(hit->time),
                      num(hit->head_radius)});
            captions.push_back(fmt::format(fmt::runtime(c.say("pitch {:.{}f} m: benches {} and {} touch at t = {:.2f} s",
                                                              "螺距 {:.{}f} m：第 {} 与第 {} 节在 t = {:.2f} s 相碰")),
                                           pitch, decimals, hit->bench_a, hit->bench_b, hit->time));
        } else {
            f = sim.frame(boundary_time(sim));
            data.add({num(pitch), "0", "", "", num(f.time), num(radius)});
            captions.push_back(fmt::format(fmt::runtime(c.say("pitch {:.{}f} m: the head reaches r = {:g} m, no contact",
                                                              "螺距 {:.{}f} m：龙头到达 r = {:g} m，无碰撞")),
                                           pitch, decimals, radius));
        }
        panels.push_back(make_scene(sim, f, so));
    }
    // One view for all six, about the centre, holding every panel's whole dragon: the pitches
    // compare at one scale and no outer coil is cut.
    double reach = 0;
    for (const Scene& p : panels)
        for (const Scene::Bench& b : p.benches)
            for (Vec2 q : corners(b.rect).p) reach = std::max({reach, std::abs(q.x()), std::abs(q.y())});
    for (Scene& p : panels) {
        p.view_centre = {0, 0};
        p.view_width = p.view_height = 2.06 * reach;
    }
    std::string verdict;
    if (std::isnan(least.pitch))
        verdict = fmt::format(fmt::runtime(c.say("no pitch in [{:.4f}, {:.4f}] m reaches it collision-free",
                                                 "[{:.4f}, {:.4f}] m 内没有螺距能无碰撞地到达")),
                              least.search_lo, least.search_hi);
    else if (least.pitch <= least.search_lo)
        verdict = fmt::format(fmt::runtime(c.say("every pitch searched, from {:.4f} m, reaches it collision-free",
                                                 "自 {:.4f} m 起搜索的每个螺距都能无碰撞地到达")),
                              least.search_lo);
    else
        verdict = fmt::format(fmt::runtime(c.say("the smallest collision-free pitch is {:.6f} m", "无碰撞的最小螺距为 {:.6f} m")),
                              least.pitch);
    const std::string title = fmt::format(fmt::runtime(c.say("Coiling in to the turning space (r = {:g} m): {}{}",
                                                             "盘入至调头空间（r = {:g} m）：{}{}")),
                                          radius, verdict,
                                          c.contest() ? c.say(" (the paper says 0.42 m)", "（论文给出 0.42 m）") : "");
    c.tell(title);
    for (const auto& caption : captions) c.tell(caption);

    // Three panels a row on screen. At a print size two, where a third of a column is too
    // narrow for a caption at the text size asked (the captions wrap at that size instead of
    // shrinking), unless two a row make the figure taller than a page's text block: then three
    // (a page's or an A4's width: two rows of panels a third of it wide).
    const bool print = c.print();
    const double text = print ? c.size(1000, 1000).text_px : 0.0;
    const double title_size = print ? 1.2 * text : 18.0 * c.opt.scale;
    const double inner = print ? 0.4 * text : 8.0;  // the title's indent beyond the gap
    const int gap = print ? std::max(2, static_cast<int>(std::lround(0.3 * text))) : 6;
    struct Layout {
        int cols = 3, rows = 2, w = 0, pw = 0, ph = 0, caption_h = 0, title_top = 0, title_h = 0, h = 0;
        render::FittedText title;  // no lines: no title
    };
    // The title and captions wrap rather than run off the picture: measured on a scratch
    // surface first, because the picture's height depends on them.
    const auto layout = [&](int cols) {
        Layout l;
        l.cols = cols, l.rows = (6 + cols - 1) / cols;
        l.w = print ? c.size(1000, 1000).w : cols * c.px(440) + (cols + 1) * gap;
        l.pw = (l.w - (cols + 1) * gap) / cols, l.ph = l.pw;
        l.caption_h = c.px(24);
        cairo::Surface scratch(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1));
        cairo::Context m = cairo::make_context(scratch.get());
        if (c.titles()) l.title = render::fit_text(m.get(), th.font, title_size, title, l.w - 2.0 * (gap + inner), true, 2, print);
        if (print) {
            std::size_t lines = 1;
            for (const auto& caption : captions)
                lines = std::max(lines, render::fit_text(m.get(), th.font, text, caption, l.pw - 0.6 * text, false, 1, true)
                                            .lines.size());
            l.caption_h = static_cast<int>(std::ceil((1.3 * static_cast<double>(lines) + 0.5) * text));
        }
        const double line_h = 1.3 * l.title.size;
        l.title_top = !c.titles() ? 0 : print ? static_cast<int>(std::ceil(2.2 * title_size)) : c.px(40);
        l.title_h = l.title.lines.empty() ? 0
                                          : l.title_top + static_cast<int>(std::ceil(line_h * (static_cast<double>(l.title.lines.size()) - 1)));
        l.h = l.rows * (l.ph + l.caption_h) + (l.rows + 1) * gap + l.title_h;
        return l;
    };
    Layout l = layout(print ? 2 : 3);
    if (print && opt_height_in(*c.opt.print, l.w, l.h) * 72.0 > kTextBlockHeightPt) l = layout(3);
    const int cols = l.cols, w = l.w, pw = l.pw, ph = l.ph, caption_h = l.caption_h, title_top = l.title_top,
              title_h = l.title_h, h = l.h;
    const render::FittedText& fitted = l.title;
    const double line_h = 1.3 * fitted.size;
    for (Scene& p : panels) p.text_px = text;
    Page page;
    if (print) {
        const double height_in = opt_height_in(*c.opt.print, w, h);
        page = {c.opt.print->width_in * 72.0, height_in * 72.0, c.opt.format == "png" ? c.opt.print->dpi : 0.0};
    }
    write_picture(w, h, path, 64, [&](cairo_t* cr) {
        cairo_set_source_rgb(cr, th.background.r, th.background.g, th.background.b);
        cairo_paint(cr);
        cairo_save(cr);
        cairo_translate(cr, 0, title_h);
        draw_panels(cr, panels, captions, cols, pw, ph, caption_h, th, gap, text);
        cairo_restore(cr);
        cairo_set_source_rgb(cr, th.text.r, th.text.g, th.text.b);
        for (std::size_t i = 0; i < fitted.lines.size(); ++i)
            render::text(cr, th.font, fitted.size, gap + inner, title_top * 0.7 + line_h * static_cast<double>(i),
                         fitted.lines[i], 0.0, 0.0, true);
    }, page, &th, c.opt.outputs);
    write_data(c, path, data);
}

void clearance_over_time(const Context& c, const std::string& path) {
    const Simulation sim(c.base);
    const std::optional<Contact>& hit = c.answers->contact();
    const TimeSpan span = shown_span(sim, 0.0, sim.end_time(), hit);
    Plot p;
    p.theme = c.opt.theme;
    p.title = c.say("Clearance: the smallest gap between non-adjacent benches", "间隙：不相邻板凳之间的最小距离");
    p.x_label = c.say("time (s)", "时间 (s)");
    p.y_label = c.say("clearance (m)", "间隙 (m)");
    p.legend = Plot::Legend::none;
    PlotSeries s{"", {}, series_colour(p.theme, 0), 1.6};
    FigureData data{{"t (s)", "clearance (m)", "bench a", "bench b"}, {}};
    Clearance least{std::numeric_limits<double>::infinity(), 0, 0, Vec2::Zero(), Vec2::Zero()};
    double least_t = span.from;
    Frame f;
    auto add = [&](double t) {
        sim.frame_into(t, f);
        const Clearance cl = clearance(f);
        if (!std::isfinite(cl.distance)) return;  // fewer than three benches: no pair
        s.points.push_back({t, cl.distance});
        data.add({num(t), num(cl.distance), std::to_string(cl.bench_a), std::to_string(cl.bench_b)});
        if (cl.distance < least.distance) least = cl, least_t = t;
    };
    // 400 samples over the run, and 300 more over its last 1.5 %, where the gap closes.
    const double length = span.to - span.from, fine_from = span.to - 0.015 * length;
    for (int k = 0; k < 400; ++k) {
        const double t = span.from + length * k / 400;
        if (t < fine_from) add(t);
    }
    for (int k = 0; k < 300; ++k) add(fine_from + (span.to - fine_from) * k / 300);
    add(span.to);
    if (hit) {
        p.note = fmt::format(fmt::runtime(c.say("Exact rectangle distances. First contact at t = {:.6f} s (benches {} and {}){}",
                                                "矩形间的精确距离。首次碰撞 t = {:.6f} s（第 {} 与第 {} 节板凳）{}")),
                             hit->time, hit->bench_a, hit->bench_b,
                             c.contest() ? c.say("; the paper's 0.1 s grid gives 413 s.", "；论文用 0.1 s 的网格得到 413 s。")
                                         : c.say(".", "。"));
        p.ref_lines.push_back({true, hit->time, fmt::format("{:.4f} s", hit->time), p.theme.collision});
    } else if (s.points.empty()) {
        p.note = fmt::format(fmt::runtime(c.say("A chain of {} {} no two that do not share a handle: nothing can touch.",
                                                "{} 节{}中没有两节不共用把手的板凳：不会相碰。")),
                             c.base.bench.bench_count,
                             c.base.bench.bench_count == 1 ? c.say("bench has", "板凳") : c.say("benches has", "板凳"));
    } else {
        p.note = fmt::format(fmt::runtime(c.say("Exact rectangle distances. No contact on the way in (to t = {:.2f} s): the smallest "
                                                "sampled clearance is {:.6f} m, benches {} and {} at t = {:.2f} s.",
                                                "矩形间的精确距离。盘入途中（至 t = {:.2f} s）无碰撞：采样到的最小间隙为 {:.6f} m，"
                                                "第 {} 与第 {} 节板凳，t = {:.2f} s。")),
                             span.to, least.distance, least.bench_a, least.bench_b, least_t);
        p.ref_lines.push_back({true, least_t, fmt::format("{:.2f} s", least_t), p.theme.text});
    }
    p.series.push_back(s);
    p.ref_lines.push_back({false, 0.0, "", with_alpha(p.theme.text, 0.6)});
    const double tick = render::nice_floor(std::max(span.to, 1e-9) / 8.0);
    p.x_min = 0;
    p.x_max = std::ceil(span.to / tick) * tick;
    double top = 0;
    for (Vec2 q : s.points) top = std::max(top, q.y());
    p.y_min = -0.1 * (top > 0 ? top : 0.2);
    if (s.points.empty()) p.y_max = 1.0;
    write_plot(c, p, 1000, 600, path);
    write_data(c, path, data);
}

}  // namespace dragon::fig
