#include "render/png8.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include <png.h>

#include "dragon/atomic_file.hpp"
#include "dragon/errors.hpp"
#include "render/median_cut.hpp"

namespace dragon::render {

namespace {

int channel(std::uint32_t rgb, int c) { return static_cast<int>((rgb >> (16 - 8 * c)) & 0xff); }

// Median cut on the image's exact colours, each weighing its pixel count (render/median_cut.hpp).
// Each box's colour is its most frequent member, not its mean, so the flat colours of a drawing
// (background, boards) stay exact.
// `keep`: colours the picture holds that are entries of their own (a role's colour: the tail's
// swatch in a legend covers a few hundred pixels, and a box of median cut would give it its
// neighbour's grey); the cut shares out the rest.
std::vector<std::uint32_t> palette_of(std::vector<ColourCount> colours, std::size_t max_colours,
                                      const std::vector<std::uint32_t>& keep) {
    std::vector<std::uint32_t> palette;
    for (std::uint32_t k : keep)
        if (palette.size() + 2 <= max_colours && std::find(palette.begin(), palette.end(), k) == palette.end() &&
            std::any_of(colours.begin(), colours.end(), [&](const ColourCount& c) { return c.rgb == k; }))
            palette.push_back(k);
    if (!palette.empty())
        std::erase_if(colours, [&](const ColourCount& c) {
            return std::find(palette.begin(), palette.end(), c.rgb) != palette.end();
        });
    for (const ColourBox& b : median_cut(colours, max_colours - palette.size(), CutWeight::pixels, BoxOrder::lower_in_place)) {
        auto best = std::max_element(colours.begin() + static_cast<std::ptrdiff_t>(b.begin),
                                     colours.begin() + static_cast<std::ptrdiff_t>(b.end),
                                     [](const ColourCount& x, const ColourCount& y) { return x.pixels < y.pixels; });
        palette.push_back(best->rgb);
    }
    return palette;
}

struct PngWrite {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngWrite() { png_destroy_write_struct(&png, &info); }
};

// pHYs holds pixels per metre.
png_uint_32 per_metre(double dpi) { return static_cast<png_uint_32>(std::lround(dpi / 0.0254)); }

// An 8-bit PNG's bytes from its rows: RGB (no palette) or palette indices (with `palette`),
// stating `dpi` (> 0). `tune` sets the encoder's options before the header is written.
// libpng's default handlers print on stderr; its errors come back as one SolverError instead.
std::string encode_png(int w, int h, const std::vector<png_bytep>& rows, const std::vector<png_color>& palette,
                       double dpi, void (*tune)(png_structp)) {
    std::string bytes;
    PngWrite pw;
    const auto fail = [](png_structp png, png_const_charp) { png_longjmp(png, 1); };
    const auto ignore = [](png_structp, png_const_charp) {};
    pw.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, fail, ignore);
    if (pw.png) pw.info = png_create_info_struct(pw.png);
    if (!pw.png || !pw.info) throw SolverError("libpng: out of memory");
    // libpng reports errors by longjmp: nothing with a destructor may be created below.
    if (setjmp(png_jmpbuf(pw.png))) throw SolverError("libpng could not encode the picture");
    const auto append = [](png_structp png, png_bytep chunk, png_size_t length) {
        static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(chunk), length);
    };
    png_set_write_fn(pw.png, &bytes, append, nullptr);
    png_set_IHDR(pw.png, pw.info, w, h, 8, palette.empty() ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_PALETTE,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(pw.png, pw.info, palette.data(), static_cast<int>(palette.size()));
    if (dpi > 0) png_set_pHYs(pw.png, pw.info, per_metre(dpi), per_metre(dpi), PNG_RESOLUTION_METER);
    if (tune) tune(pw.png);
    png_write_info(pw.png, pw.info);
    png_write_image(pw.png, const_cast<png_bytepp>(rows.data()));
    png_write_end(pw.png, nullptr);
    return bytes;
}

}  // namespace

void write_png8(cairo_surface_t* surface, const std::string& path, int max_colours, double dpi,
                const std::vector<std::uint32_t>& keep, RunOutputs* outputs) {
    cairo_surface_flush(surface);
    const int w = cairo_image_surface_get_width(surface), h = cairo_image_surface_get_height(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    auto pixel = [&](int x, int y) { return reinterpret_cast<const std::uint32_t*>(data + y * stride)[x] & 0xffffffu; };

    std::unordered_map<std::uint32_t, std::uint32_t> histogram;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ++histogram[pixel(x, y)];
    std::vector<ColourCount> colours;
    colours.reserve(histogram.size());
    for (auto [rgb, n] : histogram) colours.push_back({rgb, n});
    const std::vector<std::uint32_t> palette =
        palette_of(std::move(colours), static_cast<std::size_t>(std::clamp(max_colours, 2, 256)), keep);

    std::unordered_map<std::uint32_t, std::uint8_t> index;
    for (auto& [rgb, n] : histogram) {
        int best = 0, best_d = 1 << 30;
        for (std::size_t k = 0; k < palette.size(); ++k) {
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                const int e = channel(rgb, c) - channel(palette[k], c);
                d += e * e;
            }
            if (d < best_d) best_d = d, best = static_cast<int>(k);
        }
        index[rgb] = static_cast<std::uint8_t>(best);
    }

    std::vector<png_color> pal;
    for (std::uint32_t rgb : palette)
        pal.push_back({static_cast<png_byte>(channel(rgb, 0)), static_cast<png_byte>(channel(rgb, 1)),
                       static_cast<png_byte>(channel(rgb, 2))});
    std::vector<png_byte> rows(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rows[static_cast<std::size_t>(y) * w + x] = index[pixel(x, y)];
    std::vector<png_bytep> row_ptrs(h);
    for (int y = 0; y < h; ++y) row_ptrs[y] = rows.data() + static_cast<std::size_t>(y) * w;
    const std::string bytes = encode_png(w, h, row_ptrs, pal, dpi, [](png_structp png) {
        png_set_compression_level(png, 9);
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);  // palette images: no filter compresses best
    });
    AtomicFile out(path, outputs);
    write_text_file(out, bytes);
    out.commit();
}

std::string png_bytes(cairo_surface_t* surface, double dpi) {
    cairo_surface_flush(surface);
    const int w = cairo_image_surface_get_width(surface), h = cairo_image_surface_get_height(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    std::vector<png_byte> rows(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint32_t rgb = reinterpret_cast<const std::uint32_t*>(data + y * stride)[x];
            png_byte* p = rows.data() + (static_cast<std::size_t>(y) * w + x) * 3;
            for (int c = 0; c < 3; ++c) p[c] = static_cast<png_byte>(channel(rgb, c));
        }
    std::vector<png_bytep> row_ptrs(h);
    for (int y = 0; y < h; ++y) row_ptrs[y] = rows.data() + static_cast<std::size_t>(y) * w * 3;
    return encode_png(w, h, row_ptrs, {}, dpi, nullptr);
}

void write_png(cairo_surface_t* surface, AtomicFile& out, double dpi) { write_text_file(out, png_bytes(surface, dpi)); }

}  // namespace dragon::render
