#include "video/decode.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "video/av_handles.hpp"
#include "video/av_error.hpp"

namespace dragon::test {

namespace {

Rgb to_rgb(const AVFrame* f, av::Sws& sws) {
    Rgb out{f->width, f->height, std::vector<std::uint8_t>(static_cast<size_t>(f->width) * f->height * 3)};
    sws.reset(sws_getContext(f->width, f->height, static_cast<AVPixelFormat>(f->format), f->width, f->height,
                             AV_PIX_FMT_RGB24, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                             nullptr, nullptr));
    if (!sws) throw std::runtime_error("no converter to RGB24");
    if (f->format == AV_PIX_FMT_YUV420P) {
        // Decode with the matrix and range the file is tagged with, as a player would.
        const int space = f->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
        sws_setColorspaceDetails(sws.get(), sws_getCoefficients(space), f->color_range == AVCOL_RANGE_JPEG,
                                 sws_getCoefficients(SWS_CS_DEFAULT), 1, 0, 1 << 16, 1 << 16);
    }
    std::uint8_t* dst[1] = {out.pixels.data()};
    const int dst_stride[1] = {out.width * 3};
    sws_scale(sws.get(), f->data, f->linesize, 0, f->height, dst, dst_stride);
    return out;
}

}  // namespace

DecodedVideo decode_video(const std::string& path, int keep) {
    DecodedVideo out;
    AVFormatContext* raw = nullptr;
    av::check(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), "open " + path);
    av::InputFormatContext demux(raw);
    av::check(avformat_find_stream_info(demux.get(), nullptr), "stream info");
    const AVCodec* codec = nullptr;
    const int index = av::check(av_find_best_stream(demux.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0), "video stream");
    const AVStream* stream = demux->streams[index];
    av::CodecContext dec(avcodec_alloc_context3(codec));
    av::check(avcodec_parameters_to_context(dec.get(), stream->codecpar), "decoder parameters");
    av::check(avcodec_open2(dec.get(), codec, nullptr), "open decoder");

    out.codec = codec->name;
    out.container = demux->iformat->name;
    out.width = stream->codecpar->width;
    out.height = stream->codecpar->height;
    out.fps = av_q2d(stream->avg_frame_rate);
    if (stream->duration != AV_NOPTS_VALUE) out.duration = static_cast<double>(stream->duration) * av_q2d(stream->time_base);
    else if (demux->duration != AV_NOPTS_VALUE) out.duration = static_cast<double>(demux->duration) / AV_TIME_BASE;

    av::Packet packet(av_packet_alloc());
    av::Frame frame(av_frame_alloc());
    av::Sws sws;
    const auto receive_all = [&] {
        for (;;) {
            const int ret = avcodec_receive_frame(dec.get(), frame.get());
            if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
            av::check(ret, "decode");
            if (out.frames == keep) out.kept = to_rgb(frame.get(), sws);
            ++out.frames;
            av_frame_unref(frame.get());
        }
    };
    while (av_read_frame(demux.get(), packet.get()) >= 0) {
        if (packet->stream_index == index) av::check(avcodec_send_packet(dec.get(), packet.get()), "send packet");
        av_packet_unref(packet.get());
        receive_all();
    }
    av::check(avcodec_send_packet(dec.get(), nullptr), "flush decoder");
    receive_all();
    return out;
}

Rgb rgb_from_argb32(const std::uint8_t* argb, int width, int height, int stride) {
    Rgb out{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 3)};
    for (int y = 0; y < height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(argb + static_cast<std::ptrdiff_t>(y) * stride);
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &out.pixels[(static_cast<size_t>(y) * width + x) * 3];
            p[0] = static_cast<std::uint8_t>(row[x] >> 16);
            p[1] = static_cast<std::uint8_t>(row[x] >> 8);
            p[2] = static_cast<std::uint8_t>(row[x]);
        }
    }
    return out;
}

double psnr(const Rgb& a, const Rgb& b) {
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size())
        throw std::invalid_argument("psnr: pictures differ in size");
    double sum = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = static_cast<double>(a.pixels[i]) - b.pixels[i];
        sum += d * d;
    }
    const double mse = sum / static_cast<double>(a.pixels.size());
    if (mse == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace dragon::test
