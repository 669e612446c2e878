// An MP4 file's index (its moov box) moved from the end to the front, so that a browser plays
// the film before the download ends. FFmpeg's muxer does this itself with movflags +faststart,
// but then logs a line on stderr ("Starting second pass") that only a process-wide log level
// silences; done here instead, the library leaves FFmpeg's logging as the caller set it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dragon::video {

// Adds `by` to every chunk offset (stco, co64) in the moov box `moov` (its bytes, header
// included). Returns false, changing nothing, if an offset of a 32-bit table would pass 2^32 - 1
// (the file is then left with its index at the end, valid all the same) or the box is malformed.
bool shift_chunk_offsets(std::vector<std::uint8_t>& moov, std::uint64_t by);

// Rewrites the MP4 at `path` in place with its moov box, found last, moved in front of every
// box after the first (ftyp): ftyp, moov, then the rest as they were, the chunk offsets shifted
// by the moov's size. Leaves the file as it is when the moov is not last or the offsets cannot
// be shifted (shift_chunk_offsets). Throws FileError naming `target` (the name the user gave)
// if the file cannot be read or written.
void move_index_first(const std::string& path, const std::string& target);

}  // namespace dragon::video
