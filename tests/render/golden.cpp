#include "golden.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"

namespace dragon::test {

namespace fs = std::filesystem;

namespace {

bool rebaseline_requested() {
    const char* v = std::getenv("DRAGON_REBASELINE");
    return v && std::string_view(v) != "" && std::string_view(v) != "0";
}

int channel(std::uint32_t px, int shift) { return static_cast<int>((px >> shift) & 0xff); }

}  // namespace

GoldenResult compare_golden(cairo_surface_t* actual, const std::string& name, const GoldenTolerance& tol) {
    GoldenResult r;
    cairo_surface_flush(actual);
    const fs::path golden = fs::path(DRAGON_SOURCE_DIR) / "tests" / "golden" / name;
    if (rebaseline_requested()) {
        fs::create_directories(golden.parent_path());
        r.ok = cairo_surface_write_to_png(actual, golden.c_str()) == CAIRO_STATUS_SUCCESS;
        r.rebaselined = true;
        r.message = "re-baselined " + golden.string();
        return r;
    }
    const fs::path out_dir = fs::path(DRAGON_TEST_TMP) / "golden";
    fs::create_directories(out_dir);
    auto save_actual = [&] {
        cairo_surface_write_to_png(actual, (out_dir / name).c_str());
        return (out_dir / name).string();
    };

    cairo::Surface expected(cairo_image_surface_create_from_png(golden.c_str()));
    if (cairo_surface_status(expected.get()) != CAIRO_STATUS_SUCCESS) {
        r.message = fmt::format("no readable reference {} (actual saved to {}); run with "
                                "DRAGON_REBASELINE=1 to create it", golden.string(), save_actual());
        return r;
    }
    const int w = cairo_image_surface_get_width(actual), h = cairo_image_surface_get_height(actual);
    if (cairo_image_surface_get_width(expected.get()) != w || cairo_image_surface_get_height(expected.get()) != h) {
        r.message = fmt::format("size {}x{} differs from the reference's {}x{} (actual saved to {})", w, h,
                                cairo_image_surface_get_width(expected.get()),
                                cairo_image_surface_get_height(expected.get()), save_actual());
        return r;
    }
    // The reference may load as RGB24 (opaque PNG): compare colour channels only, alpha too when
    // both carry it.
    const bool both_alpha = cairo_image_surface_get_format(expected.get()) == CAIRO_FORMAT_ARGB32 &&
                            cairo_image_surface_get_format(actual) == CAIRO_FORMAT_ARGB32;
    cairo::Surface diff(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h));
    const auto* a = cairo_image_surface_get_data(actual);
    const auto* e = cairo_image_surface_get_data(expected.get());
    auto* d = cairo_image_surface_get_data(diff.get());
    const int sa = cairo_image_surface_get_stride(actual), se = cairo_image_surface_get_stride(expected.get());
    const int sd = cairo_image_surface_get_stride(diff.get());
    long differing = 0;
    int largest = 0;
    for (int y = 0; y < h; ++y) {
        const auto* ra = reinterpret_cast<const std::uint32_t*>(a + y * sa);
        const auto* re = reinterpret_cast<const std::uint32_t*>(e + y * se);
        auto* rd = reinterpret_cast<std::uint32_t*>(d + y * sd);
        for (int x = 0; x < w; ++x) {
            int m = 0;
            for (int shift : {0, 8, 16, 24}) {
                if (shift == 24 && !both_alpha) continue;
                m = std::max(m, std::abs(channel(ra[x], shift) - channel(re[x], shift)));
            }
            largest = std::max(largest, m);
            if (m > tol.channel) ++differing;
            // Diff image: differing pixels in red (brighter = larger), the rest a faint grey of
            // the reference so one can see where they are.
            const int grey = 200 + channel(re[x], 8) / 5;
            rd[x] = m > tol.channel ? (0xffu << 16) | (static_cast<std::uint32_t>(255 - m) << 8)
                                    : (static_cast<std::uint32_t>(grey) * 0x010101u);
        }
    }
    cairo_surface_mark_dirty(diff.get());
    const long allowed = static_cast<long>(tol.max_fraction * w * h);
    r.ok = differing <= allowed && largest <= tol.max_difference;
    if (!r.ok) {
        const fs::path diff_path = out_dir / (fs::path(name).stem().string() + "-diff.png");
        cairo_surface_write_to_png(diff.get(), diff_path.c_str());
        r.message = fmt::format("{}: {} pixels differ by more than {} (allowed {}), largest channel "
                                "difference {} (allowed {}); actual: {}, diff: {}",
                                name, differing, tol.channel, allowed, largest, tol.max_difference,
                                save_actual(), diff_path.string());
    }
    return r;
}

void outline_fonts(cairo_t* cr) {
    cairo_font_options_t* fo = cairo_font_options_create();
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
}

}  // namespace dragon::test
