// Drawing and encoding at once, on the caller's executor: its workers paint frames into a small
// ring of reusable surfaces, and whichever worker finds the next frame in order drawn hands it
// (and the ones after it that are ready) to the encoder, whose codec runs threads of its own.
// Drawing a frame costs more than encoding it, so every worker draws, and the encoding moves to
// whoever is free, rather than one thread waiting on the others. Memory stays at a few frames
// whatever the clip's length.
//
// The executor runs one item per worker, each drawing frames until none are left. No item ever
// waits on one that has not started: a worker waits only for a slot of the ring to be encoded,
// and the frame holding it up was claimed (so is being drawn) by a running item, whose worker
// then encodes it. So any executor works, an InlineExecutor or a nested parallel_for too (one
// worker draws and encodes in turn), and a failure on one worker stops the others.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "render/cairo_handles.hpp"
#include "dragon/executor.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"

namespace dragon {

namespace {

cairo::Surface make_surface(int width, int height) {
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS)
        throw SolverError(fmt::format("cannot allocate a {}x{} frame", width, height));
    return s;
}

void paint_into(cairo_surface_t* surface, int index, const PaintFn& paint) {
    cairo::Context cr(cairo_create(surface));
    paint(index, cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
        throw SolverError(fmt::format("drawing frame {} failed: {}", index,
                                             cairo_status_to_string(cairo_status(cr.get()))));
    cairo_surface_flush(surface);
}

// Frame i is drawn into slot i % size. A worker may start frame i once frame i - size has been
// encoded (its slot is free). Workers claim frames in order, so at most `size` exist at once,
// and the frame the encoder waits for is always claimed by a running worker. The encoder is a
// role, not a thread: the worker that draws the next frame to encode takes it, if nobody holds
// it, and encodes frames in order as long as they are drawn.
class FrameRing {
public:
    using EncodeFn = std::function<void(int index, cairo_surface_t* surface)>;

    FrameRing(int size, int width, int height, int frame_count)
        : drawn_(static_cast<size_t>(size), -1), frame_count_(frame_count) {
        for (int i = 0; i < size; ++i) surfaces_.push_back(make_surface(width, height));
    }
    int size() const { return static_cast<int>(surfaces_.size()); }
    cairo_surface_t* surface(int index) { return surfaces_[static_cast<size_t>(index % size())].get(); }
    int encoded() const { return encoded_; }  // once the workers are done

    // One worker's share: draws frames until none are left, encoding in turn. On an error it
    // stops every worker and rethrows.
    void work(const PaintFn& paint, const EncodeFn& encode) {
        try {
            while (const std::optional<int> index = claim()) {
                paint_into(surface(*index), *index, paint);
                if (mark_drawn(*index)) encode_in_order(encode);
            }
        } catch (...) {
            stop();
            throw;
        }
    }

private:
    // The next frame to draw, once its slot is free; nullopt when all are taken or on stop.
    std::optional<int> claim() {
        std::unique_lock lock(mutex_);
        if (stopped_ || next_ >= frame_count_) return std::nullopt;
        const int index = next_++;
        encoded_changed_.wait(lock, [&] { return stopped_ || encoded_ > index - size(); });
        if (stopped_) return std::nullopt;
        return index;
    }
    bool ready_locked() const {
        return encoded_ < frame_count_ && drawn_[static_cast<size_t>(encoded_ % size())] == encoded_;
    }
    // Records the frame drawn; true if this worker is to encode now (the role was free and the
    // next frame to encode is drawn).
    bool mark_drawn(int index) {
        std::lock_guard lock(mutex_);
        drawn_[static_cast<size_t>(index % size())] = index;
        if (encoding_ || stopped_ || !ready_locked()) return false;
        encoding_ = true;
        return true;
    }
    // Holding the role: encodes frames while the next one is drawn, then gives the role up
    // (checked under the lock that mark_drawn takes, so no drawn frame is left behind).
    void encode_in_order(const EncodeFn& encode) {
        for (;;) {
            int index = 0;
            {
                std::lock_guard lock(mutex_);
                if (stopped_ || !ready_locked()) {
                    encoding_ = false;
                    return;
                }
                index = encoded_;
            }
            encode(index, surface(index));
            std::lock_guard lock(mutex_);
            encoded_ = index + 1;
            encoded_changed_.notify_all();
        }
    }
    void stop() {
        std::lock_guard lock(mutex_);
        stopped_ = true;
        encoded_changed_.notify_all();
    }

    std::vector<cairo::Surface> surfaces_;
    std::vector<int> drawn_;  // per slot: the frame it holds, -1 if none yet
    const int frame_count_;
    std::mutex mutex_;
    std::condition_variable encoded_changed_;
    int next_ = 0;     // next frame to hand to a worker
    int encoded_ = 0;  // frames 0 .. encoded_ - 1 are encoded (their slots are free)
    bool encoding_ = false;  // a worker holds the encoder role
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

    InlineExecutor serial;
    Executor& executor = executor_or(opt.executor, serial);
    // At most 8 workers draw: more would hold more frames than they gain (the encoder is one);
    // and no more than kMaxFrameRingBytes of frames: large frames get fewer workers.
    const long frame_bytes = 4L * opt.width * opt.height;
    const int by_memory = static_cast<int>(std::max(1L, kMaxFrameRingBytes / (2 * frame_bytes)));
    const int workers = std::clamp(std::min(executor.workers(), by_memory), 1, 8);
    // Two slots per worker: one being drawn, one done and waiting for the encoder.
    FrameRing ring(2 * workers, opt.width, opt.height, painted);

    if (writer.format() == VideoFormat::gif) {
        // One palette for the whole clip, from its start, middle and end (the end is where a
        // collision's highlight colour shows up).
        for (int index : {0, painted / 2, painted - 1}) {
            paint_into(ring.surface(0), index, paint);
            writer.add_palette_sample(cairo_image_surface_get_data(ring.surface(0)),
                                      cairo_image_surface_get_stride(ring.surface(0)));
        }
    }

    // Called by one worker at a time, in frame order (the encoder role passes under the ring's lock).
    // A caller that asks the executor to stop (Ctrl-C in Python) stops the film within a frame:
    // Cancelled stops every worker, and the unfinished file is never put in place.
    const FrameRing::EncodeFn encode = [&](int index, cairo_surface_t* surface) {
        check_stop(executor);
        writer.write(surface);
        if (progress) progress({index + 1, frame_count, elapsed()});
    };
    executor.parallel_for(static_cast<std::size_t>(workers),
                          [&](std::size_t, int) { ring.work(paint, encode); });
    if (ring.encoded() != painted) throw std::logic_error("encode_frames: frames went missing");
    // The held frames: nothing draws over the last painted frame's slot now; the writer sends
    // its converted picture again.
    for (int index = painted; index < frame_count; ++index) {
        check_stop(executor);
        writer.repeat();
        if (progress) progress({index + 1, frame_count, elapsed()});
    }
    if (writer.frames_written() != frame_count) throw std::logic_error("encode_frames: frames went missing");
    writer.finish();
    return {frame_count, elapsed()};
}

}  // namespace dragon
