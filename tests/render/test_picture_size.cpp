// The one WIDTHxHEIGHT parser: what it reads, and what it refuses (with the text and the rule).
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "dragon/errors.hpp"
#include "dragon/picture_size.hpp"

using namespace dragon;

namespace {

// The allowed text of the InputError parsing `text` throws ("" if none).
std::string refusal(const std::string& text, int max_side = kMaxPictureSide) {
    try {
        parse_picture_size(text, max_side);
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "picture size");
        EXPECT_EQ(e.value(), text);
        return e.allowed();
    }
    return "";
}

const std::string malformed = "use WIDTHxHEIGHT in pixels, e.g. 1280x720";
const std::string out_of_range = "each side must be 16..16384 px";

TEST(PictureSize, ReadsWidthAndHeight) {
    for (const auto& [text, w, h] : {std::tuple{"1280x720", 1280, 720}, std::tuple{"16x16", 16, 16},
                                     std::tuple{"16384x16384", 16384, 16384}, std::tuple{"1920X1080", 1920, 1080},
                                     std::tuple{"0640x0480", 640, 480}}) {
        const PictureSize s = parse_picture_size(text);
        EXPECT_EQ(s.width, w) << text;
        EXPECT_EQ(s.height, h) << text;
    }
}

TEST(PictureSize, RefusesWhatIsNotWidthByHeight) {
    for (const char* text : {"abc", "", "x", "12x", "x12", "1920x1080x3", "1920 x 1080", " 640x480", "640x480 ",
                             "+640x480", "-640x480", "640x-480", "640*480", "1e3x480", "640x480px", "640xx480"})
        EXPECT_EQ(refusal(text), malformed) << text;
}

TEST(PictureSize, RefusesSidesOutOfRange) {
    for (const char* text : {"0x5", "0x0", "15x100", "100x15", "16385x100", "100x16385",
                             // far past any int: read as too large, not wrapped round
                             "99999999999999999999x100", "100x4294967312"})
        EXPECT_EQ(refusal(text), out_of_range) << text;
}

TEST(PictureSize, TakesTheCallersLargestSide) {
    EXPECT_EQ(parse_picture_size("8192x8192", 8192).width, 8192);
    EXPECT_EQ(refusal("8193x100", 8192), "each side must be 16..8192 px");
}

}  // namespace
