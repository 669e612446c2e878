// Pictures and films: a moment drawn as `dragon render` draws it (into memory: PNG, SVG or PDF
// bytes, or pixels for numpy), a clip as `dragon video` plans it, a storyboard's film.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "common.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/clip_plan.hpp"
#include "dragon/decimals.hpp"
#include "dragon/film.hpp"
#include "dragon/language.hpp"
#include "dragon/look.hpp"
#include "dragon/picture_bytes.hpp"
#include "dragon/picture_size.hpp"
#include "dragon/still.hpp"
#include "dragon/video.hpp"

namespace dragon::python {

namespace {

template <class T>
T get(const py::dict& d, const char* key, T fallback) {
    return d.contains(key) && !d[key].is_none() ? d[key].cast<T>() : fallback;
}

// The look asked with the call's keywords (the render and video commands' look flags).
LookRequest look_request(const py::dict& look) {
    LookRequest r;
    r.theme = get<std::string>(look, "theme", r.theme);
    r.lang = get<std::string>(look, "lang", r.lang);
    r.speed_colours = get(look, "speed_colours", r.speed_colours);
    r.guides = get(look, "guides", r.guides);
    r.text = get(look, "text", r.text);
    if (look.contains("annotation") && !look["annotation"].is_none()) r.annotation = look["annotation"].cast<std::string>();
    r.legend = get(look, "legend", r.legend);
    r.inset = get(look, "inset", r.inset);
    if (look.contains("zoom") && !look["zoom"].is_none()) r.zoom = look["zoom"].cast<double>();
    if (look.contains("centre") && !look["centre"].is_none()) {
        const auto c = look["centre"].cast<std::pair<double, double>>();
        r.centre = Vec2(c.first, c.second);
    }
    r.follow_head = get(look, "follow_head", r.follow_head);
    r.text_px = get(look, "text_px", r.text_px);
    return r;
}

// A print size from the render call's keywords (print_size, width_in, width_cm, font_pt, dpi),
// as the tool's --print flags; unset when none is given (sizes in pixels).
std::optional<PrintSize> print_size_of(const py::dict& p) {
    const auto given = [&](const char* k) { return p.contains(k) && !p[k].is_none(); };
    if (!given("print_size") && !given("width_in") && !given("width_cm") && !given("font_pt") && !given("dpi"))
        return std::nullopt;
    PrintSize size = given("print_size") ? print_preset(p["print_size"].cast<std::string>()) : PrintSize{};
    if (given("width_in")) size.width_in = p["width_in"].cast<double>();
    if (given("width_cm")) {
        const double cm = p["width_cm"].cast<double>();
        if (!(cm >= kMinPrintWidthIn * kCmPerInch && cm <= kMaxPrintWidthIn * kCmPerInch))
            throw InputError(Key::width_cm, error_value(cm), fmt::format("give centimetres, {:g}..{:g}",
                                                                      kMinPrintWidthIn * kCmPerInch,
                                                                      kMaxPrintWidthIn * kCmPerInch));
        size.width_in = cm / kCmPerInch;
    }
    if (given("font_pt")) size.font_pt = p["font_pt"].cast<double>();
    if (given("dpi")) size.dpi = p["dpi"].cast<double>();
    check_print_size(size);
    return size;
}

// A picture's pixels, page and look once a print size (if any) has laid it out: the size in
// pixels gives the shape; the print size, the pixels and the text.
struct Sized {
    int width, height;
    Page page;
    py::dict look;
};
Sized sized_for(const py::dict& print, int width, int height, bool raster, const py::dict& look) {
    Sized out{width, height, {}, py::dict(look)};
    if (const std::optional<PrintSize> size = print_size_of(print)) {
        const PrintLayout layout = print_layout(*size, static_cast<double>(height) / width, raster);
        out.look["text_px"] = layout.text_px;
        out.width = layout.width_px, out.height = layout.height_px, out.page = layout.page;
    }
    return out;
}

// The moment to draw, at width x height pixels: a time, or the first contact (its view `zoom`
// wide about the contact); a zoom whose pixels doubles cannot resolve there is refused.
Still make_still(const Simulation& sim, const py::object& time, bool collision, const py::dict& look,
                 const std::string& assets, int width, int height) {
    if (collision == !time.is_none())
        throw InputError("render needs a time t (s) or collision=True, one of them");
    const LookRequest asked = look_request(look);
    const SceneOptions so = picture_scene_options(asked, assets);
    std::optional<Still> still;
    CollideAnswer searched;
    if (!collision) {
        const double t = time.cast<double>();
        py::gil_scoped_release release;
        still = still_at(sim, t, so);
    } else {
        {
            py::gil_scoped_release release;
            still = still_at_first_contact(sim, so, asked.zoom, &searched);
        }
        if (!still)
            throw InputError(Key::collision, "True",
                             fmt::format("no two benches touch between t = {} s and {} s on this scenario{}; give a time",
                                         format_time(searched.window.from), format_time(searched.window.to),
                                         searched.jam ? " (" + jam_sentence(*searched.jam) + ")" : ""));
    }
    if (asked.zoom) require_zoom_resolves(still->scene, width, height, *asked.zoom);
    return std::move(*still);
}

py::dict stats_dict(const EncodeStats& s, const VideoOptions& vo) {
    py::dict d;
    d["frames"] = s.frames;
    d["seconds"] = s.frames / vo.fps;
    d["width"] = vo.width;
    d["height"] = vo.height;
    d["fps"] = vo.fps;
    d["encode_seconds"] = s.seconds;
    return d;
}

// The encoder's settings from the call's keywords (unset: the library's defaults), checked for
// this format.
VideoOptions encoder_options(const py::dict& enc, VideoFormat format, bool speed_colours = false) {
    EncoderRequest r;
    r.width = get(enc, "width", r.width);
    r.height = get(enc, "height", r.height);
    r.fps = get(enc, "fps", r.fps);
    const auto given = [&](const char* k) { return enc.contains(k) && !enc[k].is_none(); };
    if (given("crf")) r.crf = enc["crf"].cast<int>();
    if (given("preset")) r.preset = enc["preset"].cast<std::string>();
    if (given("tune")) r.tune = enc["tune"].cast<std::string>();
    if (given("threads")) r.threads = enc["threads"].cast<int>();
    if (given("colours")) r.colours = enc["colours"].cast<int>();
    r.speed_colours = speed_colours;
    return encoder_options(r, format);
}

ProgressFn frame_progress(const WorkProgress& report) {
    if (!report) return {};
    return [report](const Progress& p) { report(p.done, p.total); };
}

}  // namespace

void bind_pictures(py::module_& m) {
    m.def("_render",
          [](const Simulation& sim, const py::object& time, bool collision, int width, int height,
             const std::string& format, const py::dict& look, const py::dict& print, const std::string& assets) {
              const PictureType type = picture_type(format);
              const Sized sized = sized_for(print, width, height, type == PictureType::png, look);
              width = sized.width, height = sized.height;
              const Page& page = sized.page;
              const py::dict& looks = sized.look;
              const Still still = make_still(sim, time, collision, looks, assets, width, height);
              std::string bytes;
              {
                  py::gil_scoped_release release;
                  bytes = render_bytes(still.scene, width, height, type, page);
              }
              return py::make_tuple(py::bytes(bytes), still.frame.time, width, height);
          },
          py::arg("sim"), py::arg("time"), py::arg("collision"), py::arg("width"), py::arg("height"),
          py::arg("format"), py::arg("look"), py::arg("print"), py::arg("assets"));

    m.def("_render_rgba",
          [](const Simulation& sim, const py::object& time, bool collision, int width, int height,
             const py::dict& look, const py::dict& print, const std::string& assets) {
              const Sized sized = sized_for(print, width, height, true, look);
              const Still still = make_still(sim, time, collision, sized.look, assets, sized.width, sized.height);
              std::vector<std::uint8_t> pixels;
              {
                  py::gil_scoped_release release;
                  pixels = render_rgba(still.scene, sized.width, sized.height);
              }
              py::array_t<std::uint8_t> out({py::ssize_t{sized.height}, py::ssize_t{sized.width}, py::ssize_t{4}});
              std::memcpy(out.mutable_data(), pixels.data(), pixels.size());
              return out;
          },
          py::arg("sim"), py::arg("time"), py::arg("collision"), py::arg("width"), py::arg("height"),
          py::arg("look"), py::arg("print"), py::arg("assets"));

    m.def("_save_bytes",
          [](const py::bytes& data, const std::string& path, const std::string& format) {
              // The name says the format, as the tool's --out does: a picture is not written under
              // another format's extension (an SVG's bytes in y.png).
              const std::string ext = extension_of(path);
              if (ext != "." + format) {
                  const bool picture = ext == ".png" || ext == ".svg" || ext == ".pdf";
                  throw InputError(Key::out, fmt::format("'{}'", path),
                                   fmt::format("the picture is {0}: give a name ending in .{0}{1}", format,
                                               picture ? fmt::format(" (for {} render with format=\"{}\")", ext,
                                                                     ext.substr(1))
                                                       : ""));
              }
              std::string text = data;
              py::gil_scoped_release release;
              AtomicFile file(path);
              write_text_file(file, text);
              file.commit();
          },
          "Writes a picture's bytes all-or-nothing, as the tool writes its files, to a name ending in its "
          "format's extension.",
          py::arg("data"), py::arg("path"), py::arg("format"));

    m.def("_video",
          [](const py::dict& scenario, const std::string& path, const std::string& out, const py::object& from,
             const py::object& to, double speedup, const py::object& hold, const py::dict& enc, const py::dict& look,
             const std::string& assets, const py::object& progress, int workers) {
              Scenario s = scenario_from(scenario);
              s.path.kind = path_kind(path);
              const VideoFormat format = video_format_for(out);
              const LookRequest asked = look_request(look);
              VideoOptions vo = encoder_options(enc, format, asked.speed_colours);
              const SceneOptions scene = clip_scene_options(asked, assets);
              ClipRequest request;
              if (!from.is_none()) request.from = py::str(from).cast<std::string>();
              if (!to.is_none()) request.to = py::str(to).cast<std::string>();
              request.speedup = speedup;
              if (!hold.is_none()) request.hold = hold.cast<double>();
              request.language = scene.language;
              FilmLook film_look;
              film_look.legend = get(look, "legend", true);
              film_look.inset = get(look, "inset", true);
              const WorkProgress report = progress_from(progress);
              { AtomicFile probe(out); }  // an unwritable path fails here, before any work
              const Simulation sim(s);
              const EncodeStats stats = interruptible([&](Executor& ex) {
                  const ClipPlan plan = plan_clip(sim, request, {"from_", "to"});
                  film_look.events = plan.events;
                  const Animation anim(sim, plan.clip, vo.fps, scene, plan.end_mark, film_look);
                  if (asked.zoom) require_zoom_resolves(anim, vo.width, vo.height, *asked.zoom);
                  VideoOptions o = vo;
                  o.executor = &ex;
                  return write_video(anim, out, o, frame_progress(report));
              }, workers_from(workers));
              return stats_dict(stats, vo);
          },
          py::arg("scenario"), py::arg("path"), py::arg("out"), py::arg("from_"), py::arg("to"), py::arg("speedup"),
          py::arg("hold"), py::arg("encoder"), py::arg("look"), py::arg("assets"), py::arg("progress"),
          py::arg("workers"));

    m.def("_film",
          [](const std::string& storyboard, const std::string& out, const py::object& size, const py::object& fps,
             const py::object& at, const py::dict& enc, const std::string& assets, const py::object& progress,
             int workers, const py::object& warn) {
              const bool poster = !at.is_none();
              Storyboard board = load_storyboard(storyboard, assets);
              for (const KeyWarning& w : board.warnings) warn(w.message);  // old names, said before the work
              if (!size.is_none()) {
                  const auto [w, h] = size.cast<std::pair<int, int>>();
                  const PictureSize checked = parse_picture_size(fmt::format("{}x{}", w, h), kMaxVideoSide);
                  board.film.width = checked.width;
                  board.film.height = checked.height;
              }
              if (!fps.is_none()) board.film.fps = fps.cast<double>();
              py::dict settings = enc;
              settings["width"] = board.film.width;
              settings["height"] = board.film.height;
              settings["fps"] = board.film.fps;
              // A poster is one PNG: only the film's size and rate matter to it.
              VideoOptions vo;
              if (poster) {
                  vo.width = board.film.width;
                  vo.height = board.film.height;
                  vo.fps = board.film.fps;
              } else {
                  vo = encoder_options(settings, video_format_for(out));
              }
              const WorkProgress report = progress_from(progress);
              const std::optional<double> moment = poster ? std::optional(at.cast<double>()) : std::nullopt;
              { AtomicFile probe(out); }
              struct Made {
                  EncodeStats stats;
                  std::size_t shots = 0;
              };
              const Made made = interruptible([&](Executor& ex) {
                  const Film film(board);
                  if (moment) {
                      write_film_frame(film, *moment, out);
                      return Made{{1, 0.0}, film.spans().size()};
                  }
                  VideoOptions o = vo;
                  o.executor = &ex;
                  return Made{write_film(film, out, o, frame_progress(report)), film.spans().size()};
              }, workers_from(workers));
              py::dict d = stats_dict(made.stats, vo);
              d["shots"] = made.shots;
              return d;
          },
          py::arg("storyboard"), py::arg("out"), py::arg("size"), py::arg("fps"), py::arg("at"), py::arg("encoder"),
          py::arg("assets"), py::arg("progress"), py::arg("workers"), py::arg("warn"));
}

}  // namespace dragon::python
