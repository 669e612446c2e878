// Whole-file outputs: the same draw() onto an image surface (PNG) or a vector surface (SVG, PDF).
#include <cerrno>
#include <cstring>

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <fmt/format.h>

#include "render/vector_out.hpp"

#include "picture_checks.hpp"

#include "dragon/atomic_file.hpp"
#include "render/cairo_handles.hpp"
#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

using render::check_picture_size;

namespace {
void check(cairo_status_t st, const char* what) { render::check_cairo(st, what); }
}  // namespace

void render_png(const Scene& scene, int w, int h, const std::string& path) {
    check_picture_size(w, h);
    require_drawable(scene, w, h);
    AtomicFile out(path);
    // Opaque pictures: RGB24 writes a PNG without an alpha channel (a quarter smaller).
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    check(cairo_surface_status(surface.get()), "creating the image surface");
    {
        cairo::Context cr = cairo::make_context(surface.get());
        draw(cr.get(), scene, w, h);
        check(cairo_status(cr.get()), "drawing");
    }
    errno = 0;
    if (const cairo_status_t st = cairo_surface_write_to_png(surface.get(), out.temp_path().c_str()))
        throw out.write_error(errno != 0 ? std::strerror(errno) : cairo_status_to_string(st));
    out.commit();
}

namespace render {

PictureFormat picture_format(const std::string& path) {
    const std::string ext = extension_of(path);
    if (ext == ".png") return PictureFormat::png;
    if (ext == ".svg") return PictureFormat::svg;
    if (ext == ".pdf") return PictureFormat::pdf;
    throw InputError(fmt::format("output '{}' has extension '{}': pictures are .png, .svg or .pdf", path, ext));
}

void write_vector(const std::string& path, PictureFormat format, int w, int h,
                  const std::function<void(cairo_t*)>& paint) {
    AtomicFile out(path);
    {
        // CSS pixels: 96 to the inch, 72 points to the inch.
        constexpr double pt_per_px = 72.0 / 96.0;
        cairo::Surface surface(format == PictureFormat::pdf
                                   ? cairo_pdf_surface_create(out.temp_path().c_str(), w * pt_per_px, h * pt_per_px)
                                   : cairo_svg_surface_create(out.temp_path().c_str(), w, h));
        check(cairo_surface_status(surface.get()), "creating the vector surface");
        if (format == PictureFormat::svg) cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
        else cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "benchdragon");
        cairo::Context cr = cairo::make_context(surface.get());
        if (format == PictureFormat::pdf) cairo_scale(cr.get(), pt_per_px, pt_per_px);
        paint(cr.get());
        check(cairo_status(cr.get()), "drawing");
        cr.reset();
        errno = 0;
        cairo_surface_finish(surface.get());  // writes the file
        if (const cairo_status_t st = cairo_surface_status(surface.get()))
            throw out.write_error(errno != 0 ? std::strerror(errno) : cairo_status_to_string(st));
    }
    out.commit();
}

}  // namespace render

void render_svg(const Scene& scene, int w, int h, const std::string& path) {
    check_picture_size(w, h);
    require_drawable(scene, w, h);
    render::write_vector(path, render::PictureFormat::svg, w, h, [&](cairo_t* cr) { draw(cr, scene, w, h); });
}

void render_pdf(const Scene& scene, int w, int h, const std::string& path) {
    check_picture_size(w, h);
    require_drawable(scene, w, h);
    render::write_vector(path, render::PictureFormat::pdf, w, h, [&](cairo_t* cr) { draw(cr, scene, w, h); });
}

}  // namespace dragon
