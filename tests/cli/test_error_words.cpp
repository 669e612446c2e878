// The library's typed errors for pictures and films: each names its value in the library's
// terms (field, value, what is allowed, no flag), and the CLI's one line names the flag that set
// it, as it always has.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "cli/error_words.hpp"
#include "dragon/film.hpp"
#include "dragon/picture_size.hpp"
#include "dragon/sweep_map.hpp"
#include "dragon/video.hpp"

using namespace dragon;

namespace {

struct Words {
    std::string field, value, allowed;
    std::string line;  // the CLI's, after "dragon: error: "
};

// The InputError `f` throws, as its parts and the CLI's line.
Words words_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return {std::string(e.field()), e.value(), e.allowed(), cli::word(e)};
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

void expect(const Words& got, const Words& want) {
    EXPECT_EQ(got.field, want.field);
    EXPECT_EQ(got.value, want.value);
    EXPECT_EQ(got.allowed, want.allowed);
    EXPECT_EQ(got.line, want.line);
    for (const std::string& s : {got.field, got.value, got.allowed}) EXPECT_EQ(s.find("--"), std::string::npos) << s;
}

void validate_mp4(const std::function<void(VideoOptions&)>& change, VideoFormat format = VideoFormat::mp4) {
    VideoOptions o;
    o.width = 64;
    o.height = 48;
    change(o);
    validate(o, format);
}

TEST(ErrorWords, VideoOptions) {
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.fps = 0; }); }),
           {"frame rate", "0", "use a rate from 0.01 to 240 frames per second",
            "--fps 0 is not allowed: use a rate from 0.01 to 240 frames per second"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.crf = -1; }); }),
           {"H.264 quality (crf)", "-1", "use 0 (lossless) to 51", "--crf -1 is not allowed for H.264: use 0 (lossless) to 51"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.crf = 64; }, VideoFormat::webm); }),
           {"VP9 quality (crf)", "64", "use 0 to 63", "--crf 64 is not allowed for VP9: use 0 to 63"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.crf = 20; }, VideoFormat::gif); }),
           {"GIF quality (crf)", "20", "a GIF has no quality setting (VideoOptions::colours sets its palette)",
            "--crf 20 is not allowed for .gif: a GIF has no quality setting (--colours sets its palette)"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.preset = "glacial"; }); }),
           {"encoder preset", "glacial",
            "use one of ultrafast, superfast, veryfast, faster, fast, medium, slow, slower, veryslow",
            "--preset glacial is not allowed: use one of ultrafast, superfast, veryfast, faster, fast, medium, slow, "
            "slower, veryslow"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.tune = "cartoon"; }); }),
           {"encoder tune", "cartoon", "use one of animation, film, stillimage, grain, psnr, ssim, fastdecode, "
                                       "zerolatency or none",
            "--tune cartoon is not allowed: use one of animation, film, stillimage, grain, psnr, ssim, fastdecode, "
            "zerolatency or none"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.colours = 1; }, VideoFormat::gif); }),
           {"palette colours", "1", "a GIF palette has 2 to 256 colours",
            "--colours 1 is not allowed: a GIF palette has 2 to 256 colours"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.threads = 65; }); }),
           {"encoder threads", "65", "use 0 (automatic) to 64", "--threads 65 is not allowed: use 0 (automatic) to 64"});
    // Values no flag sets as such: the library's own words.
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.width = 1; }); }),
           {"video size", "1x48", "each side must be 2 to 8192 pixels",
            "video size 1x48 is not allowed: each side must be 2 to 8192 pixels"});
    expect(words_of([] { validate_mp4([](VideoOptions& o) { o.keyframe_seconds = 0; }); }),
           {"key frame interval", "0 s", "use more than 0, up to 3600 s",
            "key frame interval 0 s is not allowed: use more than 0, up to 3600 s"});
}

TEST(ErrorWords, Animation) {
    const Simulation sim{Scenario{}};
    const auto animate = [&sim](Clip clip, double fps) { return [&sim, clip, fps] { Animation(sim, clip, fps, {}); }; };
    expect(words_of(animate({0, 1, -1}, 5)),
           {"speedup", "-1", "use simulated seconds per video second above 0",
            "--speedup -1 is not allowed: use simulated seconds per video second above 0"});
    expect(words_of(animate({0, 1, 1, 3601}, 5)),
           {"hold", "3601", "use 0..3600 seconds", "--hold 3601 is not allowed: use 0..3600 seconds"});
    expect(words_of(animate({0, 1, 1}, 0)),
           {"frame rate", "0", "use a rate above 0", "--fps 0 is not allowed: use a rate above 0"});
    // Two flags in one sentence: the CLI's own.
    expect(words_of(animate({0, 1, 1e-300}, 30)),
           {"film frame count", "3e+301",
            "a film has at most 1000000 frames; use fewer frames per second or more simulated seconds per second of "
            "film",
            "the film would have 3e+301 frames, more than 1000000: raise --speedup or lower --fps"});
    // (dragon video words an empty range itself, naming both flags: tests/cli/test_cli_video.cpp.)
    expect(words_of(animate({5, 2, 1}, 30)),
           {"time range", "5..2 s", "its end must come after its start",
            "--from/--to 5..2 s is not allowed: its end must come after its start"});
}

TEST(ErrorWords, FilmMoment) {
    const Storyboard board = parse_storyboard("[film]\nsize = \"96x64\"\nfps = 5\n[[shot]]\nfrom = 10\nto = 12\nrate = 2\n",
                                              "s.toml", DRAGON_SOURCE_DIR, std::string(DRAGON_SOURCE_DIR) + "/assets");
    const Film film(board);
    expect(words_of([&] { write_film_frame(film, 99, "never-written.png"); }),
           {"film moment", "99", "the film lasts 1.200 s; give 0 up to that",
            "--at 99 is not allowed: the film lasts 1.200 s; give 0 up to that"});
}

TEST(ErrorWords, MapFile) {
    expect(words_of([] { require_map_format("x.jpg"); }),
           {"map file", "x.jpg", "use .png, .svg or .pdf", "--plot x.jpg has extension '.jpg': use .png, .svg or .pdf"});
}

TEST(ErrorWords, PictureSize) {
    expect(words_of([] { parse_picture_size("big"); }),
           {"picture size", "big", "use WIDTHxHEIGHT in pixels, e.g. 1280x720",
            "--size big is not allowed: use WIDTHxHEIGHT in pixels, e.g. 1280x720"});
    expect(words_of([] { parse_picture_size("10x10"); }),
           {"picture size", "10x10", "each side must be 16..16384 px",
            "--size 10x10 is not allowed: each side must be 16..16384 px"});
}

}  // namespace
