// RAII for every FFmpeg handle the video layer touches: unique_ptr aliases whose deleters call
// the matching libav free function. One place, so no code path can leak a context or a frame
// (or free one with the wrong function).
//
// This header pulls in the libav headers; the public video API (video.hpp) does not, so users
// of the library need FFmpeg's headers only if they include this file.
#pragma once

#include <memory>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
#include <libswscale/swscale.h>
}

namespace dragon::av {

// A muxing context: closes its file (if the muxer opened one) before freeing.
struct OutputFormatDeleter {
    void operator()(AVFormatContext* c) const noexcept {
        if (c->oformat && !(c->oformat->flags & AVFMT_NOFILE)) avio_closep(&c->pb);
        avformat_free_context(c);
    }
};
// A demuxing context opened by avformat_open_input.
struct InputFormatDeleter {
    void operator()(AVFormatContext* c) const noexcept { avformat_close_input(&c); }
};
struct CodecContextDeleter {
    void operator()(AVCodecContext* c) const noexcept { avcodec_free_context(&c); }
};
struct FrameDeleter {
    void operator()(AVFrame* f) const noexcept { av_frame_free(&f); }
};
struct PacketDeleter {
    void operator()(AVPacket* p) const noexcept { av_packet_free(&p); }
};
struct SwsDeleter {
    void operator()(SwsContext* s) const noexcept { sws_freeContext(s); }
};
struct DictionaryDeleter {
    void operator()(AVDictionary* d) const noexcept { av_dict_free(&d); }
};

using OutputFormatContext = std::unique_ptr<AVFormatContext, OutputFormatDeleter>;
using InputFormatContext = std::unique_ptr<AVFormatContext, InputFormatDeleter>;
using CodecContext = std::unique_ptr<AVCodecContext, CodecContextDeleter>;
using Frame = std::unique_ptr<AVFrame, FrameDeleter>;
using Packet = std::unique_ptr<AVPacket, PacketDeleter>;
using Sws = std::unique_ptr<SwsContext, SwsDeleter>;
using Dictionary = std::unique_ptr<AVDictionary, DictionaryDeleter>;

}  // namespace dragon::av
