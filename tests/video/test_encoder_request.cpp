// What a caller asks of the encoder (EncoderRequest): defaults per format, and an option of
// another format's encoder refused with its key rather than ignored.
#include <gtest/gtest.h>

#include "dragon/video.hpp"

namespace dragon {
namespace {

Key refused_key(const EncoderRequest& r, VideoFormat f) {
    try {
        encoder_options(r, f);
    } catch (const InputError& e) {
        return e.key();
    }
    return Key::none;
}

// A request with one value set.
template <class Set>
EncoderRequest asking(Set set) {
    EncoderRequest r;
    set(r);
    return r;
}

TEST(EncoderRequest, UnsetValuesAreTheOptionsDefaults) {
    const VideoOptions vo = encoder_options({}, VideoFormat::mp4);
    const VideoOptions defaults;
    EXPECT_EQ(vo.preset, defaults.preset);
    EXPECT_EQ(vo.tune, defaults.tune);
    EXPECT_EQ(vo.colours, defaults.colours);
    EXPECT_EQ(vo.threads, defaults.threads);
    EXPECT_FALSE(vo.crf);
}

TEST(EncoderRequest, AGifOfSpeedColoursGetsTheFullPalette) {
    EncoderRequest r;
    r.speed_colours = true;
    EXPECT_EQ(encoder_options(r, VideoFormat::gif).colours, kSpeedColoursPalette);
    r.colours = 32;  // what is asked wins
    EXPECT_EQ(encoder_options(r, VideoFormat::gif).colours, 32);
    r.speed_colours = false;
    r.colours.reset();
    EXPECT_EQ(encoder_options(r, VideoFormat::gif).colours, VideoOptions{}.colours);
}

TEST(EncoderRequest, AnotherFormatsOptionIsRefusedByItsKey) {
    const EncoderRequest preset = asking([](EncoderRequest& r) { r.preset = "fast"; });
    EXPECT_EQ(refused_key(preset, VideoFormat::mp4), Key::none);
    EXPECT_EQ(refused_key(preset, VideoFormat::webm), Key::preset);
    EXPECT_EQ(refused_key(preset, VideoFormat::gif), Key::preset);
    const EncoderRequest tune = asking([](EncoderRequest& r) { r.tune = "film"; });
    EXPECT_EQ(refused_key(tune, VideoFormat::webm), Key::tune);
    const EncoderRequest colours = asking([](EncoderRequest& r) { r.colours = 64; });
    EXPECT_EQ(refused_key(colours, VideoFormat::gif), Key::none);
    EXPECT_EQ(refused_key(colours, VideoFormat::mp4), Key::colours);
    EXPECT_EQ(refused_key(colours, VideoFormat::webm), Key::colours);
    const EncoderRequest odd = asking([](EncoderRequest& r) { r.width = 641; });
    EXPECT_EQ(refused_key(odd, VideoFormat::mp4), Key::video_size);  // validate()'s rules still hold
    EXPECT_EQ(refused_key(odd, VideoFormat::gif), Key::none);
}

}  // namespace
}  // namespace dragon
