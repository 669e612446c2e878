// The streaming encoder: frames in, packets straight out to the muxer.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "av_handles.hpp"
#include "dragon/scenario.hpp"
#include "dragon/video.hpp"
#include "av_error.hpp"
#include "palette.hpp"
#include "yuv_convert.hpp"
#include "mp4_index_first.hpp"

namespace dragon {

namespace {

struct CodecChoice {
    const char* encoder;
    AVPixelFormat pix_fmt;
    int default_crf;  // -1: no crf
};

CodecChoice codec_for(VideoFormat f) {
    switch (f) {
        case VideoFormat::mp4: return {"libx264", AV_PIX_FMT_YUV420P, kDefaultCrf.h264};
        case VideoFormat::webm: return {"libvpx-vp9", AV_PIX_FMT_YUV420P, kDefaultCrf.vp9};
        case VideoFormat::gif: return {"gif", AV_PIX_FMT_PAL8, -1};
    }
    throw std::logic_error("unknown video format");
}

// Frames above 4K UHD (3840x2160, 8.3 million pixels): the encoders are held to a few frames
// in flight, so that every size a video accepts stays under 2 GB resident
// (scripts/limits.sh measures it).
constexpr long kLargeFramePixels = 3840L * 2160L;
bool large_frame(const VideoOptions& opt) { return static_cast<long>(opt.width) * opt.height > kLargeFramePixels; }

// The encoder's threads: the caller's (0: the codec's choice, ~1.5 a core), at most 2 for
// H.264 and 8 for VP9 at large frames, where each frame thread holds frames of its own.
int encoder_threads(VideoFormat f, const VideoOptions& opt) {
    if (!large_frame(opt) || f == VideoFormat::gif) return opt.threads;
    const int most = f == VideoFormat::mp4 ? 2 : 8;
    return opt.threads == 0 ? most : std::min(opt.threads, most);
}

// Over the default preset and tune, settings that suit a dragon's films, measured against
// lossless encodes of four (the coil-in at 10 and at 20 simulated seconds a second, the
// turnaround, the contest's storyboard film; scripts/bench-video.sh shows the first): the chain
// moves along its own path, so a few frames later each bench lies where another lay, and 8
// reference frames (the tune's 4, doubled) find it: the coil-in at speedup 10, which repeats
// every 5 frames, takes half the bits. Sub-pixel refinement at level 2 rather than 4 costs a
// few per cent of bits for a third less time. Each of the four came out the same size or
// smaller at the same PSNR (within 0.15 dB) for two thirds of the encoder's CPU. (Fewer
// B-frames suited some of them and not others, so the tune's 5 stay.)
constexpr const char* kDragonX264Settings = "subme=2:ref=8";

// Encoder-private options: speed first (this runs on two cores), quality by crf.
av::Dictionary encoder_options(VideoFormat f, const VideoOptions& opt, const CodecChoice& c) {
    AVDictionary* d = nullptr;
    const int crf = opt.crf.value_or(c.default_crf);
    if (f == VideoFormat::mp4) {
        av_dict_set(&d, "preset", opt.preset.c_str(), 0);
        if (opt.tune != "none") av_dict_set(&d, "tune", opt.tune.c_str(), 0);
        av_dict_set_int(&d, "crf", crf, 0);
        // A frame larger than 4K UHD: one reference frame, no B-frames, no look-ahead. Each frame
        // x264 keeps costs ~5.5 bytes a pixel with its half-pel planes (200 MB at 8192x4352),
        // and "faster" with tune animation keeps 4 references, 5 B-frames and 20 look-ahead
        // frames: 1.9 GB resident at that size on one thread, 2.7 GB on 64.
        const bool dragon_settings = opt.preset == VideoOptions{}.preset && opt.tune == VideoOptions{}.tune;
        std::string params = dragon_settings ? kDragonX264Settings : "";
        if (large_frame(opt)) params = (dragon_settings ? "subme=2:" : "") + std::string("ref=1:bframes=0:rc-lookahead=0");
        if (!params.empty()) av_dict_set(&d, "x264-params", params.c_str(), 0);
    } else if (f == VideoFormat::webm) {
        // Realtime mode, rows in parallel. Measured on the coil-in film (scripts/bench-video.sh):
        // offline VP9 ("good", cpu-used 5) makes a third of the bits at the same PSNR but costs
        // ~6x the CPU (8 frames/s); speed 6 costs 25 % more CPU than 8 for 35 % fewer bits.
        av_dict_set(&d, "deadline", "realtime", 0);
        av_dict_set_int(&d, "cpu-used", 6, 0);
        av_dict_set_int(&d, "row-mt", 1, 0);
        // No look-ahead: realtime mode makes no alt-ref frames from it, yet libvpx would keep
        // 25 frames for it (700 MB at 4096x4096).
        av_dict_set_int(&d, "lag-in-frames", 0, 0);
        av_dict_set_int(&d, "crf", crf, 0);
    }
    return av::Dictionary(d);
}

VideoOptions checked(const VideoOptions& opt, VideoFormat format) {
    validate(opt, format);
    return opt;
}

// Complains about the first option the encoder did not take (a typo would otherwise be silent).
void require_all_used(const av::Dictionary& left, const char* encoder) {
    if (const AVDictionaryEntry* e = av_dict_get(left.get(), "", nullptr, AV_DICT_IGNORE_SUFFIX))
        throw SolverError(fmt::format("encoder {} does not take option {}={}", encoder, e->key, e->value));
}

}  // namespace

struct VideoWriter::Impl {
    VideoFormat format;
    VideoOptions opt;
    AtomicFile file;  // declared before the muxer: destroyed after it has closed the file
    av::OutputFormatContext mux;
    AVStream* stream = nullptr;
    av::CodecContext enc;
    av::Frame frame;
    av::Packet packet;
    video::PaletteBuilder palette_samples;  // gif
    std::optional<video::Palette> palette;  // gif, fixed at the first frame
    std::int64_t next_pts = 0;
    bool finished = false;

    Impl(const std::string& path, const VideoOptions& o)
        : format(video_format_for(path)), opt(checked(o, format)), file(path, o.outputs) {
        const CodecChoice choice = codec_for(format);
        // The muxer by the target's name: the temporary file's name is not the user's choice.
        const AVOutputFormat* oformat = av_guess_format(nullptr, path.c_str(), nullptr);
        if (!oformat) throw SolverError(fmt::format("this FFmpeg has no muxer for '{}'", path));
        AVFormatContext* raw_mux = nullptr;
        av::check(avformat_alloc_output_context2(&raw_mux, oformat, nullptr, file.temp_path().c_str()),
                  "cannot set up the muxer");
        mux.reset(raw_mux);

        const AVCodec* codec = avcodec_find_encoder_by_name(choice.encoder);
        if (!codec)
            throw SolverError(fmt::format("this FFmpeg has no {} encoder (needed for .{} files)",
                                                 choice.encoder, to_string(format)));
        enc.reset(avcodec_alloc_context3(codec));
        if (!enc) throw std::bad_alloc();
        // The encoders' chatter (x264's statistics, libvpx's version) demoted below libav's
        // default level, for this context only: no global setting is touched, and a failure
        // still reaches the caller as an exception from its return code.
        enc->log_level_offset = AV_LOG_DEBUG - AV_LOG_ERROR;
        const AVRational rate = av_d2q(opt.fps, 100000);
        enc->width = opt.width;
        enc->height = opt.height;
        enc->pix_fmt = choice.pix_fmt;
        enc->time_base = av_inv_q(rate);
        enc->framerate = rate;
        enc->thread_count = encoder_threads(format, opt);
        if (format != VideoFormat::gif) {
            enc->gop_size = std::max(1, static_cast<int>(std::lround(opt.keyframe_seconds * opt.fps)));
            enc->bit_rate = 0;  // quality by crf alone
            // Tag what argb32_to_yuv420p produces: BT.709, limited range.
            enc->colorspace = AVCOL_SPC_BT709;
            enc->color_primaries = AVCOL_PRI_BT709;
            enc->color_trc = AVCOL_TRC_BT709;
            enc->color_range = AVCOL_RANGE_MPEG;
        }
        if (mux->oformat->flags & AVFMT_GLOBALHEADER) enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        av::Dictionary codec_opts = encoder_options(format, opt, choice);
        {
            AVDictionary* d = codec_opts.release();
            const int ret = avcodec_open2(enc.get(), codec, &d);
            codec_opts.reset(d);
            av::check(ret, fmt::format("cannot open the {} encoder", choice.encoder));
        }
        require_all_used(codec_opts, choice.encoder);

        stream = avformat_new_stream(mux.get(), nullptr);
        if (!stream) throw std::bad_alloc();
        stream->time_base = enc->time_base;
        stream->avg_frame_rate = rate;
        av::check(avcodec_parameters_from_context(stream->codecpar, enc.get()), "cannot set the stream up");

        frame.reset(av_frame_alloc());
        packet.reset(av_packet_alloc());
        if (!frame || !packet) throw std::bad_alloc();
        frame->format = enc->pix_fmt;
        frame->width = enc->width;
        frame->height = enc->height;
        av::check(av_frame_get_buffer(frame.get(), 0), "cannot allocate a video frame");

        av::check_file(avio_open(&mux->pb, file.temp_path().c_str(), AVIO_FLAG_WRITE), file.target(), "write");
        // An MP4's index is moved to the front when it is finished (move_index_first).
        av::check_file(avformat_write_header(mux.get(), nullptr), file.target(), "write the header of");
    }

    void write(const std::uint8_t* argb, int stride) {
        if (finished) throw std::logic_error("VideoWriter::write after finish");
        av::check(av_frame_make_writable(frame.get()), "cannot reuse the video frame");
        if (format == VideoFormat::gif) {
            if (!palette) {
                if (palette_samples.empty()) palette_samples.add(argb, opt.width, opt.height, stride);
                palette = palette_samples.build(opt.colours);
            }
            palette->map(argb, opt.width, opt.height, stride, frame->data[0], frame->linesize[0]);
            std::memcpy(frame->data[1], palette->colours.data(), 256 * sizeof(std::uint32_t));
        } else {
            video::argb32_to_yuv420p(argb, stride, opt.width, opt.height,
                                     {frame->data[0], frame->linesize[0], frame->data[1], frame->linesize[1],
                                      frame->data[2], frame->linesize[2]});
        }
        frame->pts = next_pts++;
        av::check(avcodec_send_frame(enc.get(), frame.get()), "cannot encode a frame");
        drain();
    }

    void repeat() {
        if (finished) throw std::logic_error("VideoWriter::repeat after finish");
        if (next_pts == 0) throw std::logic_error("VideoWriter::repeat before the first frame");
        // The encoder may still hold the frame's buffers: writable means a copy of the same
        // picture if so.
        av::check(av_frame_make_writable(frame.get()), "cannot reuse the video frame");
        frame->pts = next_pts++;
        av::check(avcodec_send_frame(enc.get(), frame.get()), "cannot encode a frame");
        drain();
    }

    // Moves every packet the encoder has ready to the muxer.
    void drain() {
        for (;;) {
            const int ret = avcodec_receive_packet(enc.get(), packet.get());
            if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
            av::check(ret, "cannot encode a frame");
            av_packet_rescale_ts(packet.get(), enc->time_base, stream->time_base);
            packet->stream_index = stream->index;
            av::check_file(av_interleaved_write_frame(mux.get(), packet.get()), file.target(), "write");
        }
    }

    void finish() {
        if (finished) return;
        if (next_pts == 0) throw InputError(Key::frame_count, "0", "a video needs at least one frame");
        av::check(avcodec_send_frame(enc.get(), nullptr), "cannot flush the encoder");
        drain();
        av::check_file(av_write_trailer(mux.get()), file.target(), "finish");
        av::check_file(avio_closep(&mux->pb), file.target(), "close");
        // The index at the front: browsers start playing before the download ends.
        if (format == VideoFormat::mp4) video::move_index_first(file.temp_path(), file.target());
        file.commit();
        finished = true;
    }
};

VideoWriter::VideoWriter(const std::string& path, const VideoOptions& opt)
    : impl_(std::make_unique<Impl>(path, opt)) {}

VideoWriter::~VideoWriter() = default;

VideoFormat VideoWriter::format() const { return impl_->format; }
const VideoOptions& VideoWriter::options() const { return impl_->opt; }
int VideoWriter::frames_written() const { return static_cast<int>(impl_->next_pts); }

void VideoWriter::add_palette_sample(const std::uint8_t* argb32, int stride) {
    if (impl_->format != VideoFormat::gif || impl_->palette) return;
    impl_->palette_samples.add(argb32, impl_->opt.width, impl_->opt.height, stride);
}

void VideoWriter::write(const std::uint8_t* argb32, int stride) { impl_->write(argb32, stride); }

void VideoWriter::write(cairo_surface_t* surface) {
    if (cairo_surface_get_type(surface) != CAIRO_SURFACE_TYPE_IMAGE ||
        (cairo_image_surface_get_format(surface) != CAIRO_FORMAT_ARGB32 &&
         cairo_image_surface_get_format(surface) != CAIRO_FORMAT_RGB24))
        throw std::logic_error("VideoWriter::write needs an ARGB32 or RGB24 image surface");
    if (cairo_image_surface_get_width(surface) != impl_->opt.width ||
        cairo_image_surface_get_height(surface) != impl_->opt.height)
        throw std::logic_error("VideoWriter::write: the surface is not the video's size");
    cairo_surface_flush(surface);
    write(cairo_image_surface_get_data(surface), cairo_image_surface_get_stride(surface));
}

void VideoWriter::repeat() { impl_->repeat(); }

void VideoWriter::finish() { impl_->finish(); }


}  // namespace dragon
