// A film to a file: every frame through the streaming encoder, or one frame as a PNG.
#include <cmath>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"
#include "dragon/film.hpp"
#include "render/png8.hpp"

namespace dragon {

EncodeStats write_film(const Film& film, const std::string& path, VideoOptions opt, const ProgressFn& progress) {
    opt.width = film.settings().width;
    opt.height = film.settings().height;
    opt.fps = film.settings().fps;
    return encode_frames(path, opt, film.frame_count(), [&](int index, cairo_t* cr) { film.paint(index, cr); }, progress);
}

void write_film_frame(const Film& film, double at, const std::string& path, double dpi, RunOutputs* outputs) {
    const double fps = film.settings().fps;
    if (!(at >= 0 && at < film.duration()))
        throw InputError(Key::at, error_value(at),
                         fmt::format("the film lasts {:.3f} s; give 0 up to that", film.duration()));
    const int index = std::min(film.frame_count() - 1, static_cast<int>(std::floor(at * fps + 1e-9)));
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, film.settings().width, film.settings().height));
    {
        cairo::Context cr = cairo::make_context(surface.get());
        film.paint(index, cr.get());
    }
    // A palette PNG, as the gallery's: a third of the bytes, no visible change to a drawing.
    render::write_png8(surface.get(), path, 256, dpi, {}, outputs);
}

}  // namespace dragon
