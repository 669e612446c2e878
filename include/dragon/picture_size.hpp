// A picture's size as people write it, "1280x720": one parser for every place that reads one
// (the CLI's --size for render, video and film, a storyboard's [film] size), so they all accept
// and refuse the same texts with the same words.
#pragma once

#include <string_view>

namespace dragon {

struct PictureSize {
    int width = 0;   // pixels
    int height = 0;  // pixels
};

// The sides a picture may have. Below 16 px nothing of the dragon, its clock or legend can be
// made out; 16384 px a side is already a 1 GiB image: more is a typo, not a picture.
inline constexpr int kMinPictureSide = 16;
inline constexpr int kMaxPictureSide = 16384;

// "1280x720" (or "1280X720") -> {1280, 720}: digits, x, digits, nothing else. Throws
// InputError with field "picture size", the text as value and what is allowed: the form, or
// each side kMinPictureSide..max_side px. Callers whose output allows less (a video's codecs:
// kMaxVideoSide) pass their own largest side.
PictureSize parse_picture_size(std::string_view text, int max_side = kMaxPictureSide);

}  // namespace dragon
