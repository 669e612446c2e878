// Our ARGB32 -> yuv420p against libswscale's BT.709 limited-range conversion.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "video/av_handles.hpp"
#include "video/yuv_convert.hpp"

namespace {

using namespace dragon;

TEST(YuvConvert, AgreesWithSwscaleOnSmoothPictures) {
    const int w = 64, h = 48, stride = w * 4;
    std::vector<std::uint32_t> argb(static_cast<size_t>(w) * h);
    // Gradients in each channel, plus a few flat patches of theme-like colours.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            argb[static_cast<size_t>(y) * w + x] = 0xff000000u | (static_cast<std::uint32_t>(x * 4) << 16) |
                                                    (static_cast<std::uint32_t>(y * 5) << 8) |
                                                    static_cast<std::uint32_t>((x + y) * 2);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) argb[static_cast<size_t>(y) * w + x] = 0xfff5b84cu;  // the body colour
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(argb.data());

    av::Frame ours(av_frame_alloc()), ref(av_frame_alloc());
    for (AVFrame* f : {ours.get(), ref.get()}) {
        f->format = AV_PIX_FMT_YUV420P;
        f->width = w;
        f->height = h;
        ASSERT_GE(av_frame_get_buffer(f, 0), 0);
    }
    video::argb32_to_yuv420p(bytes, stride, w, h,
                             {ours->data[0], ours->linesize[0], ours->data[1], ours->linesize[1], ours->data[2],
                              ours->linesize[2]});
    av::Sws sws(sws_getContext(w, h, AV_PIX_FMT_RGB32, w, h, AV_PIX_FMT_YUV420P,
                               SWS_BILINEAR | SWS_ACCURATE_RND, nullptr, nullptr, nullptr));
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(sws.get(), bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    const std::uint8_t* src[1] = {bytes};
    sws_scale(sws.get(), src, &stride, 0, h, ref->data, ref->linesize);

    for (int plane = 0; plane < 3; ++plane) {
        const int pw = plane ? w / 2 : w, ph = plane ? h / 2 : h;
        int worst = 0;
        const int patch = plane ? 10 : 20;  // the flat patch and a margin: swscale blurs its edge
        for (int y = 0; y < ph; ++y)
            for (int x = 0; x < pw; ++x)
                if (x >= patch || y >= patch)
                    worst = std::max(worst, std::abs(ours->data[plane][y * ours->linesize[plane] + x] -
                                                 ref->data[plane][y * ref->linesize[plane] + x]));
        // Luma: rounding only. Chroma: swscale's filter reaches a little beyond each 2x2 block.
        EXPECT_LE(worst, plane ? 3 : 1) << "plane " << plane;
    }
    // Exact values on the flat patch: Y = 16 + 219 * (0.2126 R + 0.7152 G + 0.0722 B) / 255.
    const double r = 0xf5, g = 0xb8, b = 0x4c;
    const double y709 = 16 + 219 * (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;
    EXPECT_NEAR(ours->data[0][0], y709, 0.51);
    EXPECT_NEAR(ours->data[1][0], 128 + 224 * (b - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.8556 / 255, 0.51);
    EXPECT_NEAR(ours->data[2][0], 128 + 224 * (r - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.5748 / 255, 0.51);
}

}  // namespace
