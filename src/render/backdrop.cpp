// The backdrop cache and its copies in and out of an image surface's pixels.
#include <algorithm>
#include <cstring>
#include <utility>

#include "backdrop_key.hpp"

namespace dragon::render {

namespace {

bool same(const Rgba& a, const Rgba& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a; }

// The cache's two entries: a crossfade draws the shot before and the shot after in each frame.
constexpr std::size_t kEntries = 2;

}  // namespace

bool BackdropKey::operator==(const BackdropKey& o) const {
    if (format != o.format || width != o.width || height != o.height || stride != o.stride) return false;
    if (cx != o.cx || cy != o.cy || scale != o.scale || ox != o.ox || oy != o.oy || u != o.u || top != o.top ||
        right != o.right)
        return false;
    if (!same(background, o.background) || !same(turning_fill, o.turning_fill) ||
        !same(turning_space, o.turning_space) || turning_radius != o.turning_radius)
        return false;
    return std::equal(guides.begin(), guides.end(), o.guides.begin(), o.guides.end(),
                      [](const Guide& a, const Guide& b) {
                          return a.path == b.path && a.s0 == b.s0 && a.s1 == b.s1 && a.width_px == b.width_px &&
                                 same(a.colour, b.colour) && a.dashed == b.dashed;
                      });
}

std::shared_ptr<const BackdropCache::Entry> BackdropCache::find(const BackdropKey& key) const {
    std::lock_guard lock(mutex_);
    for (const auto& e : entries_)
        if (e->key == key) {
            ++hits_;
            return e;
        }
    return nullptr;
}

bool BackdropCache::worth_keeping(const BackdropKey& key) {
    std::lock_guard lock(mutex_);
    for (const auto& e : entries_)
        if (e->key == key) return false;
    if (last_missed_ && *last_missed_ == key) return true;
    last_missed_ = key;
    return false;
}

void BackdropCache::keep(BackdropKey key, std::vector<unsigned char> pixels) {
    auto entry = std::make_shared<const Entry>(Entry{std::move(key), std::move(pixels)});
    std::lock_guard lock(mutex_);
    // Frames drawn at once by several threads may all miss: keep one entry a key.
    for (const auto& e : entries_)
        if (e->key == entry->key) return;
    if (entries_.size() == kEntries) entries_.erase(entries_.begin());
    entries_.push_back(std::move(entry));
}

long BackdropCache::hits() const {
    std::lock_guard lock(mutex_);
    return hits_;
}

std::optional<BackdropKey> backdrop_key(cairo_t* cr, const Scene& s, const View& v, double u, double top,
                                        double right, int width, int height) {
    cairo_surface_t* target = cairo_get_target(cr);
    if (cairo_surface_get_type(target) != CAIRO_SURFACE_TYPE_IMAGE) return std::nullopt;
    const cairo_format_t format = cairo_image_surface_get_format(target);
    if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24) return std::nullopt;
    if (cairo_image_surface_get_width(target) != width || cairo_image_surface_get_height(target) != height)
        return std::nullopt;
    if (static_cast<long>(width) * height > kMaxBackdropPixels) return std::nullopt;
    // Drawn through an identity transform onto the whole surface: the copy is the drawing.
    cairo_matrix_t m;
    cairo_get_matrix(cr, &m);
    if (m.xx != 1 || m.yx != 0 || m.xy != 0 || m.yy != 1 || m.x0 != 0 || m.y0 != 0) return std::nullopt;
    double dx = 0, dy = 0, sx = 1, sy = 1;
    cairo_surface_get_device_offset(target, &dx, &dy);
    cairo_surface_get_device_scale(target, &sx, &sy);
    if (dx != 0 || dy != 0 || sx != 1 || sy != 1) return std::nullopt;
    cairo_rectangle_list_t* clips = cairo_copy_clip_rectangle_list(cr);
    const bool whole = clips->status == CAIRO_STATUS_SUCCESS && clips->num_rectangles == 1 &&
                       clips->rectangles[0].x == 0 && clips->rectangles[0].y == 0 &&
                       clips->rectangles[0].width == width && clips->rectangles[0].height == height;
    cairo_rectangle_list_destroy(clips);
    if (!whole) return std::nullopt;

    BackdropKey k;
    k.format = format;
    k.width = width;
    k.height = height;
    k.stride = cairo_image_surface_get_stride(target);
    k.cx = v.cx, k.cy = v.cy, k.scale = v.scale, k.ox = v.ox, k.oy = v.oy;
    k.u = u, k.top = top, k.right = right;
    k.background = s.theme.background;
    k.turning_fill = s.theme.turning_fill;
    k.turning_space = s.theme.turning_space;
    k.turning_radius = s.turning_radius;
    for (const Scene::Guide& g : s.guides) {
        k.guides.push_back({g.path.get(), g.s0, g.s1, g.width_px, g.colour, g.dashed});
        k.paths.push_back(g.path);
    }
    return k;
}

bool copy_backdrop(cairo_t* cr, BackdropCache& cache, const BackdropKey& key) {
    const std::shared_ptr<const BackdropCache::Entry> e = cache.find(key);
    if (!e) return false;
    cairo_surface_t* target = cairo_get_target(cr);
    cairo_surface_flush(target);
    std::memcpy(cairo_image_surface_get_data(target), e->pixels.data(), e->pixels.size());
    cairo_surface_mark_dirty(target);
    return true;
}

void keep_backdrop(cairo_t* cr, BackdropCache& cache, BackdropKey key) {
    if (!cache.worth_keeping(key)) return;
    cairo_surface_t* target = cairo_get_target(cr);
    cairo_surface_flush(target);
    const unsigned char* data = cairo_image_surface_get_data(target);
    const std::size_t bytes = static_cast<std::size_t>(key.stride) * static_cast<std::size_t>(key.height);
    cache.keep(std::move(key), std::vector<unsigned char>(data, data + bytes));
}

}  // namespace dragon::render
