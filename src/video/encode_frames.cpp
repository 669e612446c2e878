// Drawing and encoding at once: render threads paint frames into a small ring of reusable
// surfaces while this thread hands the finished ones, in order, to the encoder (whose codec
// runs its own threads). Drawing a frame costs more than encoding it, so there is one render
// thread per core: whichever core the encoder leaves idle draws. Memory stays at a few frames
// whatever the clip's length.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"

namespace dragon {

namespace {

cairo::Surface make_surface(int width, int height) {
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(fmt::format("cannot allocate a {}x{} frame", width, height));
    return s;
}

void paint_into(cairo_surface_t* surface, int index, const PaintFn& paint) {
    cairo::Context cr(cairo_create(surface));
    paint(index, cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(fmt::format("drawing frame {} failed: {}", index,
                                             cairo_status_to_string(cairo_status(cr.get()))));
    cairo_surface_flush(surface);
}

// Frame i is drawn into slot i % size. A render thread may start frame i once frame i - size
// has been encoded (its slot is free); the encoder takes frame i once it is drawn. Workers take
// the next index in order, so at most `size` frames exist at any time.
class FrameRing {
public:
    FrameRing(int size, int width, int height) : drawn_(static_cast<size_t>(size), -1) {
        for (int i = 0; i < size; ++i) surfaces_.push_back(make_surface(width, height));
    }
    int size() const { return static_cast<int>(surfaces_.size()); }
    cairo_surface_t* surface(int index) { return surfaces_[static_cast<size_t>(index % size())].get(); }

    // The next frame to draw, once its slot is free; nullopt when all are taken or on stop.
    std::optional<int> claim(int frame_count) {
        std::unique_lock lock(mutex_);
        if (stopped_ || next_ >= frame_count) return std::nullopt;
        const int index = next_++;
        changed_.wait(lock, [&] { return stopped_ || encoded_ > index - size(); });
        if (stopped_) return std::nullopt;
        return index;
    }
    void mark_drawn(int index) {
        std::lock_guard lock(mutex_);
        drawn_[static_cast<size_t>(index % size())] = index;
        changed_.notify_all();
    }
    // Waits until frame `index` is drawn; false on stop.
    bool wait_drawn(int index) {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return stopped_ || drawn_[static_cast<size_t>(index % size())] == index; });
        return drawn_[static_cast<size_t>(index % size())] == index;
    }
    void mark_encoded(int index) {
        std::lock_guard lock(mutex_);
        encoded_ = index + 1;
        changed_.notify_all();
    }
    void stop() {
        std::lock_guard lock(mutex_);
        stopped_ = true;
        changed_.notify_all();
    }

private:
    std::vector<cairo::Surface> surfaces_;
    std::vector<int> drawn_;  // per slot: the frame it holds, -1 if none yet
    std::mutex mutex_;
    std::condition_variable changed_;
    int next_ = 0;     // next frame to hand to a render thread
    int encoded_ = 0;  // frames 0 .. encoded_ - 1 are encoded (their slots are free)
    bool stopped_ = false;
};

}  // namespace

EncodeStats encode_frames(const std::string& path, const VideoOptions& opt, int frame_count,
                          const PaintFn& paint, const ProgressFn& progress, int painted) {
    if (frame_count < 1) throw InputError(fmt::format("a video needs at least one frame, not {}", frame_count));
    if (painted < 0 || painted > frame_count)
        throw std::invalid_argument(fmt::format("encode_frames: {} painted frames of {}", painted, frame_count));
    if (painted == 0) painted = frame_count;
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    VideoWriter writer(path, opt);

    const int workers = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
    // Two slots per render thread: one being drawn, one done and waiting for the encoder.
    FrameRing ring(2 * workers, opt.width, opt.height);

    if (writer.format() == VideoFormat::gif) {
        // One palette for the whole clip, from its start, middle and end (the end is where a
        // collision's highlight colour shows up).
        for (int index : {0, painted / 2, painted - 1}) {
            paint_into(ring.surface(0), index, paint);
            writer.add_palette_sample(cairo_image_surface_get_data(ring.surface(0)),
                                      cairo_image_surface_get_stride(ring.surface(0)));
        }
    }

    std::mutex error_mutex;
    std::exception_ptr render_error;
    std::vector<std::thread> renderers;
    for (int w = 0; w < workers; ++w) {
        renderers.emplace_back([&] {
            try {
                while (const std::optional<int> index = ring.claim(painted)) {
                    paint_into(ring.surface(*index), *index, paint);
                    ring.mark_drawn(*index);
                }
            } catch (...) {
                std::lock_guard lock(error_mutex);
                if (!render_error) render_error = std::current_exception();
                ring.stop();
            }
        });
    }
    const auto join_all = [&] {
        for (auto& t : renderers) t.join();
    };

    try {
        for (int index = 0; index < painted; ++index) {
            if (!ring.wait_drawn(index)) break;  // a render thread failed
            writer.write(ring.surface(index));
            ring.mark_encoded(index);
            if (progress) progress({index + 1, frame_count, elapsed()});
        }
        // The held frames: no render thread claims past `painted`, so nothing draws over the
        // last painted frame's slot; the writer sends its converted picture again.
        if (writer.frames_written() == painted)
            for (int index = painted; index < frame_count; ++index) {
                writer.repeat();
                if (progress) progress({index + 1, frame_count, elapsed()});
            }
    } catch (...) {
        ring.stop();
        join_all();
        throw;
    }
    join_all();
    if (render_error) std::rethrow_exception(render_error);
    if (writer.frames_written() != frame_count) throw std::logic_error("encode_frames: frames went missing");
    writer.finish();
    return {frame_count, elapsed()};
}

}  // namespace dragon
