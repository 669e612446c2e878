// The encoder round trip: write synthetic frames, decode the file back, compare.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/scratch.hpp"

#include "dragon/scenario.hpp"
#include "dragon/video.hpp"
#include "render/cairo_handles.hpp"
#include "video/decode.hpp"
#include "video/synthetic.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::string scratch(const std::string& name) {
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path p = dir / name;
    fs::remove(p);
    return p.string();
}

// Leftover temporary files of the AtomicFile in the target's folder.
int temp_files_beside(const std::string& target) {
    int n = 0;
    const std::string stem = "." + fs::path(target).stem().string() + ".tmp";
    for (const auto& e : fs::directory_iterator(fs::path(target).parent_path()))
        n += e.path().filename().string().rfind(stem, 0) == 0;
    return n;
}

test::Rgb reference(int index, int width, int height) {
    cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    cairo::Context cr(cairo_create(s.get()));
    test::paint_synthetic(index, cr.get(), width, height);
    cairo_surface_flush(s.get());
    return test::rgb_from_argb32(cairo_image_surface_get_data(s.get()), width, height,
                                 cairo_image_surface_get_stride(s.get()));
}

struct Case {
    const char* file;
    const char* codec;
    double min_psnr;  // dB
};
// Shown by gtest in failures, instead of the object's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }

class RoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(RoundTrip, FrameCountSizeDurationAndPicture) {
    const Case c = GetParam();
    const std::string path = scratch(c.file);
    VideoOptions opt;
    opt.width = 320;
    opt.height = 240;
    opt.fps = 25;
    const int frames = 30;
    const auto paint = [&](int i, cairo_t* cr) { test::paint_synthetic(i, cr, opt.width, opt.height); };
    int last_done = 0;
    const EncodeStats stats = encode_frames(path, opt, frames, paint, [&](const Progress& p) {
        EXPECT_EQ(p.total, frames);
        EXPECT_EQ(p.done, last_done + 1);
        last_done = p.done;
    });
    EXPECT_EQ(stats.frames, frames);
    EXPECT_EQ(last_done, frames);
    ASSERT_TRUE(fs::exists(path));
    EXPECT_EQ(temp_files_beside(path), 0);

    const int keep = 17;
    const test::DecodedVideo v = test::decode_video(path, keep);
    EXPECT_EQ(v.codec, c.codec);
    EXPECT_EQ(v.frames, frames);
    EXPECT_EQ(v.width, opt.width);
    EXPECT_EQ(v.height, opt.height);
    EXPECT_NEAR(v.duration, frames / opt.fps, 0.5 / opt.fps + 0.011);  // GIF delays are centiseconds
    const double db = test::psnr(v.kept, reference(keep, opt.width, opt.height));
    EXPECT_GT(db, c.min_psnr) << c.file;
    RecordProperty("psnr_db", std::to_string(db));
    std::printf("PSNR %s %.2f dB\n", c.file, db);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip,
                         ::testing::Values(Case{"round.mp4", "h264", 30.0}, Case{"round.webm", "vp9", 30.0},
                                           Case{"round.gif", "gif", 25.0}),
                         [](const auto& info) { return std::string(fs::path(info.param.file).extension()).substr(1); });

// x264 writes the settings it encoded with into the stream (its SEI text): "ref=8 ... ".
std::string x264_setting(const std::string& path, const std::string& key) {
    const std::string bytes = dragon_test::slurp(path);
    const std::size_t at = bytes.find(" " + key + "=", bytes.find("x264 - core"));
    if (at == std::string::npos) return "";
    const std::size_t from = at + key.size() + 2;
    return bytes.substr(from, bytes.find(' ', from) - from);
}

std::string encoded_with(const VideoOptions& opt, const std::string& name) {
    const std::string path = scratch(name);
    encode_frames(path, opt, 3, [&](int i, cairo_t* cr) { test::paint_synthetic(i, cr, opt.width, opt.height); });
    return path;
}

// The defaults are "faster" with tune animation and the dragon's settings over them (8 reference
// frames, sub-pixel level 2); with any other preset or tune, x264's own.
TEST(VideoWriter, TheDragonsSettingsGoWithTheDefaultPresetOnly) {
    VideoOptions opt;
    opt.width = 160;
    opt.height = 120;
    const std::string dflt = encoded_with(opt, "defaults.mp4");
    EXPECT_EQ(x264_setting(dflt, "ref"), "8");
    EXPECT_EQ(x264_setting(dflt, "bframes"), "5");  // faster's 3 and 2 more for tune animation
    EXPECT_EQ(x264_setting(dflt, "subme"), "2");
    EXPECT_EQ(x264_setting(dflt, "crf"), fmt::format("{}.0", kDefaultCrf.h264));
    EXPECT_EQ(x264_setting(dflt, "psy_rd"), "0.40:0.00");  // tune animation's
    VideoOptions medium = opt;
    medium.preset = "medium";
    const std::string m = encoded_with(medium, "medium.mp4");
    EXPECT_EQ(x264_setting(m, "subme"), "7");  // medium's own
    EXPECT_EQ(x264_setting(m, "ref"), "6");    // medium's 3, doubled by tune animation
    VideoOptions film = opt;
    film.tune = "film";
    EXPECT_EQ(x264_setting(encoded_with(film, "film.mp4"), "subme"), "4");  // faster's own
}

TEST(VideoWriter, DestroyedWithoutFinishLeavesNothing) {
    const std::string path = scratch("unfinished.mp4");
    {
        VideoOptions opt;
        opt.width = 64;
        opt.height = 48;
        VideoWriter w(path, opt);
        cairo::Surface s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, opt.width, opt.height));
        cairo::Context cr(cairo_create(s.get()));
        test::paint_synthetic(0, cr.get(), opt.width, opt.height);
        w.write(s.get());
        EXPECT_EQ(temp_files_beside(path), 1);
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(temp_files_beside(path), 0);
}

TEST(VideoWriter, PaintErrorStopsBothThreadsAndLeavesNothing) {
    const std::string path = scratch("paint-error.mp4");
    VideoOptions opt;
    opt.width = 64;
    opt.height = 48;
    const auto paint = [&](int i, cairo_t* cr) {
        if (i == 7) throw std::runtime_error("boom");
        test::paint_synthetic(i, cr, opt.width, opt.height);
    };
    EXPECT_THROW(encode_frames(path, opt, 20, paint), std::runtime_error);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(temp_files_beside(path), 0);
}

TEST(VideoWriter, BadOptionsAreInputErrors) {
    VideoOptions odd;
    odd.width = 321;
    EXPECT_THROW(validate(odd, VideoFormat::mp4), InputError);
    EXPECT_NO_THROW(validate(odd, VideoFormat::gif));  // GIF has no chroma planes to halve
    VideoOptions still;
    still.fps = 0;
    EXPECT_THROW(validate(still, VideoFormat::webm), InputError);
    VideoOptions slow;
    slow.preset = "glacial";
    EXPECT_THROW(validate(slow, VideoFormat::mp4), InputError);
    VideoOptions cartoon;
    cartoon.tune = "cartoon";
    EXPECT_THROW(validate(cartoon, VideoFormat::mp4), InputError);
    cartoon.tune = "none";  // x264's own tuning
    EXPECT_NO_THROW(validate(cartoon, VideoFormat::mp4));
    VideoOptions no_keys;
    no_keys.keyframe_seconds = 0;
    EXPECT_THROW(validate(no_keys, VideoFormat::webm), InputError);
    // H.264's largest level holds 139,264 macroblocks: 8192x4352 is the widest 16:8.5 frame it
    // takes, 8192x4368 one row of macroblocks too many. VP9 takes at most 4096x4096 pixels (its
    // encoder's memory grows with them: 7.7 GB at 8192x8192), in any shape; GIF any size.
    VideoOptions big;
    big.width = 8192;
    big.height = 4352;
    EXPECT_NO_THROW(validate(big, VideoFormat::mp4));
    big.height = 4368;
    EXPECT_THROW(validate(big, VideoFormat::mp4), InputError);
    EXPECT_THROW(validate(big, VideoFormat::webm), InputError);
    EXPECT_NO_THROW(validate(big, VideoFormat::gif));
    big.width = big.height = 4096;
    EXPECT_NO_THROW(validate(big, VideoFormat::webm));
    big.width = 8192, big.height = 2048;
    EXPECT_NO_THROW(validate(big, VideoFormat::webm));
    big.height = 2050;
    try {
        validate(big, VideoFormat::webm);
        ADD_FAILURE() << "8192x2050 taken for webm";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("video size 8192x2050 is not allowed for webm: a VP9 frame has at most "
                                              "16777216 pixels (4096x4096, say), this size has 16793600", 0), 0u)
            << e.what();
    }
    EXPECT_THROW(video_format_for("film.avi"), InputError);
    EXPECT_THROW(video_format_for("film"), InputError);
    EXPECT_EQ(video_format_for("Film.MP4"), VideoFormat::mp4);
    EXPECT_THROW(VideoWriter(scratch("no-such-dir") + "/x/film.mp4", VideoOptions{}), InputError);
}

}  // namespace
