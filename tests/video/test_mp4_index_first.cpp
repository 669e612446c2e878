// An MP4's index moved to the front by the library itself (video/mp4_index_first.hpp), not by
// FFmpeg's +faststart, whose "Starting second pass" line only a process-wide log level hides:
// the chunk offsets shifted exactly, a table that would overflow left alone, and a film written
// with nothing said on stderr and FFmpeg's log level as the caller left it.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

extern "C" {
#include <libavutil/log.h>
}

#include "support/scratch.hpp"

#include "dragon/video.hpp"
#include "video/decode.hpp"
#include "video/mp4_index_first.hpp"
#include "video/synthetic.hpp"

using namespace dragon;

namespace {

void put_be(std::vector<std::uint8_t>& out, std::uint64_t v, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) out.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xff));
}

std::uint64_t get_be(const std::vector<std::uint8_t>& in, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | in[at + i];
    return v;
}

// A box of `type` around `payload`.
std::vector<std::uint8_t> box(const std::string& type, const std::vector<std::uint8_t>& payload) {
    std::vector<std::uint8_t> out;
    put_be(out, 8 + payload.size(), 4);
    for (const char c : type) out.push_back(static_cast<std::uint8_t>(c));
    for (const std::uint8_t b : payload) out.push_back(b);
    return out;
}

// A chunk offset table (stco: 4-byte entries, co64: 8-byte) holding `offsets`.
std::vector<std::uint8_t> offsets_table(const char* type, const std::vector<std::uint64_t>& offsets) {
    const int bytes = std::string(type) == "stco" ? 4 : 8;
    std::vector<std::uint8_t> payload;
    put_be(payload, 0, 4);  // version and flags
    put_be(payload, offsets.size(), 4);
    for (const std::uint64_t o : offsets) put_be(payload, o, bytes);
    return box(type, payload);
}

std::vector<std::uint8_t> concat(std::vector<std::vector<std::uint8_t>> parts) {
    std::vector<std::uint8_t> out;
    for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

// moov > trak > mdia > minf > stbl > `table`, with a sibling box the search must step over.
std::vector<std::uint8_t> moov_with(const std::vector<std::uint8_t>& table) {
    const auto stbl = box("stbl", concat({box("stsz", std::vector<std::uint8_t>(12, 0)), table}));
    return box("moov", box("trak", box("mdia", box("minf", stbl))));
}

// Where the table's first entry lies in moov_with's bytes: five box headers and the table's own
// header, version and count (the stsz box before it: 20 bytes).
constexpr std::size_t kFirstEntry = 5 * 8 + 20 + 8 + 8;

}  // namespace

TEST(Mp4IndexFirst, EveryChunkOffsetIsShiftedByTheIndexSize) {
    std::vector<std::uint8_t> moov = moov_with(offsets_table("stco", {40, 1000, 70000}));
    ASSERT_TRUE(video::shift_chunk_offsets(moov, 500));
    EXPECT_EQ(get_be(moov, kFirstEntry, 4), 540u);
    EXPECT_EQ(get_be(moov, kFirstEntry + 4, 4), 1500u);
    EXPECT_EQ(get_be(moov, kFirstEntry + 8, 4), 70500u);

    std::vector<std::uint8_t> wide = moov_with(offsets_table("co64", {40, 5'000'000'000}));
    ASSERT_TRUE(video::shift_chunk_offsets(wide, 500));
    EXPECT_EQ(get_be(wide, kFirstEntry, 8), 540u);
    EXPECT_EQ(get_be(wide, kFirstEntry + 8, 8), 5'000'000'500u);
}

TEST(Mp4IndexFirst, AnOffsetThatWouldOverflowLeavesTheIndexAsItWas) {
    const std::vector<std::uint8_t> moov = moov_with(offsets_table("stco", {40, 0xFFFFFF00u}));
    std::vector<std::uint8_t> copy = moov;
    EXPECT_FALSE(video::shift_chunk_offsets(copy, 0x100));  // 0xFFFFFF00 + 0x100 = 2^32
    EXPECT_EQ(copy, moov);
    EXPECT_TRUE(video::shift_chunk_offsets(copy, 0xFF));  // 2^32 - 1 still fits
}

TEST(Mp4IndexFirst, AMalformedIndexIsLeftAlone) {
    std::vector<std::uint8_t> moov = moov_with(offsets_table("stco", {40, 1000}));
    moov[kFirstEntry - 1] = 9;  // the count says 9 entries where there are 2
    const std::vector<std::uint8_t> before = moov;
    EXPECT_FALSE(video::shift_chunk_offsets(moov, 500));
    EXPECT_EQ(moov, before);
    std::vector<std::uint8_t> not_moov = box("free", {1, 2, 3});
    EXPECT_FALSE(video::shift_chunk_offsets(not_moov, 500));
}

// A film written by the library: its index at the front (ftyp, then moov), every frame decoded
// back, nothing said on stderr, and FFmpeg's log level what it was.
TEST(Mp4IndexFirst, AFilmHasItsIndexFirstAndSaysNothing) {
    const int level = av_log_get_level();
    for (const char* name : {"quiet.mp4", "quiet.webm", "quiet.gif"}) {
        const std::string path = (dragon_test::scratch_dir() / name).string();
        VideoOptions opt;
        opt.width = 160;
        opt.height = 120;
        opt.fps = 25;
        testing::internal::CaptureStderr();
        encode_frames(path, opt, 20, [&](int i, cairo_t* cr) { test::paint_synthetic(i, cr, opt.width, opt.height); });
        EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << name;
        EXPECT_EQ(av_log_get_level(), level);
        EXPECT_EQ(test::decode_video(path, 0).frames, 20) << name;
        if (std::string(name) != "quiet.mp4") continue;
        const std::string bytes = dragon_test::slurp(path);
        ASSERT_GE(bytes.size(), 16u);
        EXPECT_EQ(bytes.substr(4, 4), "ftyp");
        const std::size_t ftyp = get_be(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 4), 0, 4);
        EXPECT_EQ(bytes.substr(ftyp + 4, 4), "moov");
        EXPECT_LT(bytes.find("moov"), bytes.find("mdat"));
    }
}
