// Pictures in memory (dragon/picture_bytes.hpp): Cairo's stream writers into a string, libpng
// where a PNG states its resolution, and the image surface's pixels unpacked. The files
// (output.cpp) are these bytes.
#include "dragon/picture_bytes.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include "picture_checks.hpp"
#include "render/cairo_handles.hpp"
#include "render/paint.hpp"
#include "render/png8.hpp"
#include "render/vector_out.hpp"

namespace dragon {

namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

// Drawn onto an opaque image surface: RGB24 writes a PNG without an alpha channel (a quarter
// smaller).
cairo::Surface paint_image(const Scene& scene, int w, int h) {
    render::check_picture_size(w, h);
    require_drawable(scene, w, h);
    cairo::Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    render::check_cairo(cairo_surface_status(surface.get()), "creating the image surface");
    cairo::Context cr = cairo::make_context(surface.get());
    draw(cr.get(), scene, w, h);
    render::check_cairo(cairo_status(cr.get()), "drawing");
    cairo_surface_flush(surface.get());
    return surface;
}

}  // namespace

namespace render {

std::string vector_bytes(PictureFormat format, int w, int h, const std::function<void(cairo_t*)>& paint,
                         const Page& page) {
    std::string bytes;
    // CSS pixels: 96 to the inch, 72 points to the inch; or the page a print size asks.
    constexpr double pt_per_px = 72.0 / 96.0;
    const bool printed = page.width_pt > 0 && page.height_pt > 0;
    const double page_w = printed ? page.width_pt : w * pt_per_px, page_h = printed ? page.height_pt : h * pt_per_px;
    cairo::Surface surface(format == PictureFormat::pdf ? cairo_pdf_surface_create_for_stream(append, &bytes, page_w, page_h)
                           : printed ? cairo_svg_surface_create_for_stream(append, &bytes, page_w, page_h)
                                     : cairo_svg_surface_create_for_stream(append, &bytes, w, h));
    check_cairo(cairo_surface_status(surface.get()), "creating the vector surface");
    if (format == PictureFormat::svg)
        cairo_svg_surface_set_document_unit(surface.get(), printed ? CAIRO_SVG_UNIT_PT : CAIRO_SVG_UNIT_PX);
    else cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "benchdragon");
    {
        cairo::Context cr = cairo::make_context(surface.get());
        render::log_picture(format == PictureFormat::pdf || printed ? page_w : w,
                            format == PictureFormat::pdf || printed ? page_h : h);
        if (format == PictureFormat::pdf || printed) cairo_scale(cr.get(), page_w / w, page_h / h);
        paint(cr.get());
        check_cairo(cairo_status(cr.get()), "drawing");
    }
    cairo_surface_finish(surface.get());  // writes the rest into `bytes`
    check_cairo(cairo_surface_status(surface.get()), "writing the picture");
    return bytes;
}

}  // namespace render

PictureType picture_type(const std::string& name) {
    if (name == "png") return PictureType::png;
    if (name == "svg") return PictureType::svg;
    if (name == "pdf") return PictureType::pdf;
    throw InputError(Key::format, "'" + name + "'", "pictures are png, svg or pdf");
}

std::string render_bytes(const Scene& scene, int w, int h, PictureType type, const Page& page) {
    if (type == PictureType::png) {
        const cairo::Surface surface = paint_image(scene, w, h);
        if (page.dpi > 0) return render::png_bytes(surface.get(), page.dpi);  // libpng states the resolution
        std::string bytes;
        render::check_cairo(cairo_surface_write_to_png_stream(surface.get(), append, &bytes), "writing the PNG");
        return bytes;
    }
    render::check_picture_size(w, h);
    require_drawable(scene, w, h);
    return render::vector_bytes(type, w, h, [&](cairo_t* cr) { draw(cr, scene, w, h); }, page);
}

std::vector<std::uint8_t> render_rgba(const Scene& scene, int w, int h) {
    const cairo::Surface surface = paint_image(scene, w, h);
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const int stride = cairo_image_surface_get_stride(surface.get());
    std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    for (int y = 0; y < h; ++y) {
        // RGB24: one native-endian 32-bit word a pixel, 0x00RRGGBB.
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        std::uint8_t* o = out.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w) * 4;
        for (int x = 0; x < w; ++x, o += 4) {
            const std::uint32_t p = row[x];
            o[0] = static_cast<std::uint8_t>(p >> 16);
            o[1] = static_cast<std::uint8_t>(p >> 8);
            o[2] = static_cast<std::uint8_t>(p);
            o[3] = 255;
        }
    }
    return out;
}

}  // namespace dragon
