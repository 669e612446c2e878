// Whole-file outputs: the in-memory pictures (picture_bytes.cpp) written all-or-nothing.
#include <fmt/format.h>

#include "render/vector_out.hpp"

#include "dragon/atomic_file.hpp"
#include "dragon/picture_bytes.hpp"
#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

namespace {

void write_picture(const Scene& scene, int w, int h, const std::string& path, PictureType type, const Page& page,
                   RunOutputs* outputs) {
    // Checked before the file is touched: a bad size or view leaves nothing behind.
    const std::string bytes = render_bytes(scene, w, h, type, page);
    AtomicFile out(path, outputs);
    write_text_file(out, bytes);
    out.commit();
}

}  // namespace

// Each file is the in-memory picture's bytes (dragon/picture_bytes.hpp), written all-or-nothing.
void render_png(const Scene& scene, int w, int h, const std::string& path, const Page& page, RunOutputs* outputs) {
    write_picture(scene, w, h, path, PictureType::png, page, outputs);
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
                  const std::function<void(cairo_t*)>& paint, const Page& page, RunOutputs* outputs) {
    AtomicFile out(path, outputs);
    write_text_file(out, vector_bytes(format, w, h, paint, page));
    out.commit();
}

}  // namespace render

void render_svg(const Scene& scene, int w, int h, const std::string& path, const Page& page, RunOutputs* outputs) {
    write_picture(scene, w, h, path, PictureType::svg, page, outputs);
}

void render_pdf(const Scene& scene, int w, int h, const std::string& path, const Page& page, RunOutputs* outputs) {
    write_picture(scene, w, h, path, PictureType::pdf, page, outputs);
}

void render_print(Scene scene, const PrintSize& size, double aspect, const std::string& path, RunOutputs* outputs) {
    const render::PictureFormat format = render::picture_format(path);
    const PrintLayout layout = print_layout(size, aspect, format == render::PictureFormat::png);
    scene.text_px = layout.text_px;
    const int w = layout.width_px, h = layout.height_px;
    if (format == render::PictureFormat::png) render_png(scene, w, h, path, layout.page, outputs);
    else if (format == render::PictureFormat::svg) render_svg(scene, w, h, path, layout.page, outputs);
    else render_pdf(scene, w, h, path, layout.page, outputs);
}

}  // namespace dragon
