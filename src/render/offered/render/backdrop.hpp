// A film's backdrop, drawn once: while the camera holds still, the background, the turning
// space and the path's guides are the same in every frame, and stroking the guides costs a
// third of a 720p frame's drawing. draw_reusing_backdrop() keeps the pixels the scene's backdrop
// left and, for a later frame with the same backdrop at the same size, copies them in instead of
// drawing them again: the same operations from the same opaque start, so the same pixels,
// byte for byte (tests/render/test_backdrop.cpp holds it to that).
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <cairo.h>

#include "dragon/render.hpp"

namespace dragon::render {

// What a backdrop is drawn from; two equal keys draw the same pixels.
struct BackdropKey {
    cairo_format_t format = CAIRO_FORMAT_INVALID;
    int width = 0, height = 0, stride = 0;  // the target surface's
    // The view (View's world centre, scale and picture origin) and the drawing's clip.
    double cx = 0, cy = 0, scale = 0, ox = 0, oy = 0, u = 0, top = 0, right = 0;
    Rgba background, turning_fill, turning_space;
    std::optional<double> turning_radius;
    struct Guide {
        const Path* path = nullptr;  // compared by identity: the scene shares its path
        double s0 = 0, s1 = 0, width_px = 0;
        Rgba colour;
        bool dashed = false;
    };
    std::vector<Guide> guides;
    // The guides' paths, held so that an address stays that path's while the key lives.
    std::vector<std::shared_ptr<const Path>> paths;

    bool operator==(const BackdropKey& o) const;
};

// The last two backdrops kept (a crossfade shows two shots at once), safe to share between the
// threads that draw a film's frames: a frame takes a copy of the pixels it needs under a lock,
// never a Cairo object another thread also uses. A backdrop is kept once a second frame has
// drawn it, so a camera that moves (a new backdrop every frame) costs no copies. Frames larger
// than 4K UHD are not kept (they would hold tens of megabytes each for a film whose memory is
// otherwise a few frames).
class BackdropCache {
public:
    struct Entry {
        BackdropKey key;
        std::vector<unsigned char> pixels;  // stride x height bytes
    };
    std::shared_ptr<const Entry> find(const BackdropKey& key) const;
    // Whether a frame that has just drawn this backdrop should keep it: true if the frame before
    // that missed drew the same one (and none is kept yet); else it is remembered as that frame.
    bool worth_keeping(const BackdropKey& key);
    void keep(BackdropKey key, std::vector<unsigned char> pixels);
    long hits() const;  // frames whose backdrop was copied, for tests and benchmarks

private:
    mutable std::mutex mutex_;
    std::vector<std::shared_ptr<const Entry>> entries_;  // most recent last
    std::optional<BackdropKey> last_missed_;  // the backdrop the last frame that missed drew
    mutable long hits_ = 0;
};

// The largest frame a BackdropCache keeps, pixels.
inline constexpr long kMaxBackdropPixels = 3840L * 2160L;

// draw(), reusing `cache`'s backdrop where the target allows it: an image surface (ARGB32 or
// RGB24) of exactly width_px x height_px, drawn through an identity transform with no clip.
// Anything else is drawn as draw() draws it.
void draw_reusing_backdrop(cairo_t* cr, const Scene& scene, int width_px, int height_px, BackdropCache& cache);

}  // namespace dragon::render
