// Drawing and encoding on two threads: a render thread paints into a small ring of reusable
// surfaces while this thread converts and encodes the previous ones. Memory stays at a few
// frames whatever the clip's length.
#include <atomic>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "dragon/scenario.hpp"
#include "dragon/video.hpp"
#include "video/bounded_queue.hpp"
#include "video/cairo_handles.hpp"

namespace dragon {

namespace {

// Three surfaces: one being drawn, one being encoded, one ready in between so neither side
// waits on the other's jitter.
constexpr int ring_size = 3;

video::CairoSurface make_surface(int width, int height) {
    video::CairoSurface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(fmt::format("cannot allocate a {}x{} frame", width, height));
    return s;
}

void paint_into(cairo_surface_t* surface, int index, const PaintFn& paint) {
    video::Cairo cr(cairo_create(surface));
    paint(index, cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(fmt::format("drawing frame {} failed: {}", index,
                                             cairo_status_to_string(cairo_status(cr.get()))));
    cairo_surface_flush(surface);
}

struct Ready {
    int slot;
    int index;
};

}  // namespace

EncodeStats encode_frames(const std::string& path, const VideoOptions& opt, int frame_count,
                          const PaintFn& paint, const ProgressFn& progress) {
    if (frame_count < 1) throw InputError(fmt::format("a video needs at least one frame, not {}", frame_count));
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    VideoWriter writer(path, opt);

    std::vector<video::CairoSurface> ring;
    for (int i = 0; i < ring_size; ++i) ring.push_back(make_surface(opt.width, opt.height));

    if (writer.format() == VideoFormat::gif) {
        // One palette for the whole clip, from its start, middle and end (the end is where a
        // collision's highlight colour shows up).
        for (int index : {0, frame_count / 2, frame_count - 1}) {
            paint_into(ring[0].get(), index, paint);
            writer.add_palette_sample(cairo_image_surface_get_data(ring[0].get()),
                                      cairo_image_surface_get_stride(ring[0].get()));
        }
    }

    video::BoundedQueue<int> free_slots(ring_size);
    video::BoundedQueue<Ready> ready(ring_size);
    for (int i = 0; i < ring_size; ++i) free_slots.push(i);
    std::exception_ptr render_error;

    std::thread renderer([&] {
        try {
            for (int index = 0; index < frame_count; ++index) {
                const std::optional<int> slot = free_slots.pop();
                if (!slot) break;  // the encoder gave up
                paint_into(ring[static_cast<size_t>(*slot)].get(), index, paint);
                if (!ready.push({*slot, index})) break;
            }
        } catch (...) {
            render_error = std::current_exception();
        }
        ready.close();
    });

    try {
        while (const std::optional<Ready> item = ready.pop()) {
            writer.write(ring[static_cast<size_t>(item->slot)].get());
            free_slots.push(item->slot);
            if (progress) progress({item->index + 1, frame_count, elapsed()});
        }
    } catch (...) {
        free_slots.close();
        ready.close();
        renderer.join();
        throw;
    }
    renderer.join();
    if (render_error) std::rethrow_exception(render_error);
    if (writer.frames_written() != frame_count)
        throw std::logic_error("encode_frames: the render thread stopped early");
    writer.finish();
    return {frame_count, elapsed()};
}

}  // namespace dragon
