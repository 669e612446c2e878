// A zip archive (APPNOTE 6.3) written to a file or to memory, for the workbooks: each entry is
// deflated by zlib (raw deflate, at the level the caller chooses; level 0 stores it), with its
// CRC-32 and sizes in its local header (no data descriptors), then the central directory and its
// end record. Every entry is stamped with one fixed DOS time, the contest's opening
// (2024-09-05 00:00), so that the same entries give the same bytes from run to run. No zip64: an
// entry, an offset or the archive past 4 GiB (or more than 65,535 entries) is refused with a
// ZipError. No state is shared between writers; a writer itself is for one thread.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dragon::zip {

// Why an archive could not be written: a failed write or close of its file (sys_errno() is the
// system's errno: EFBIG, ENOSPC...), or an archive that cannot be written without zip64 or by
// zlib (sys_errno() 0; what() says why).
class ZipError : public std::runtime_error {
public:
    ZipError(const std::string& what, int sys_errno) : std::runtime_error(what), errno_(sys_errno) {}
    int sys_errno() const { return errno_; }

private:
    int errno_;
};

// The DOS date and time every entry carries: 2024-09-05 00:00:00.
inline constexpr std::uint16_t kDosDate = ((2024 - 1980) << 9) | (9 << 5) | 5;
inline constexpr std::uint16_t kDosTime = 0;
// The most an entry, an offset or the archive may reach without zip64.
inline constexpr std::uint64_t kMaxZipSize = 0xFFFFFFFFu;

class ZipWriter {
public:
    // Into memory: finish() returns the archive.
    ZipWriter();
    // Into the file at `path`, created or truncated now (its mode kept if it exists); throws
    // ZipError if it cannot be opened.
    explicit ZipWriter(const std::string& path);
    // Closes the file if finish() did not (an unfinished archive: the caller discards it).
    ~ZipWriter();
    ZipWriter(const ZipWriter&) = delete;
    ZipWriter& operator=(const ZipWriter&) = delete;

    // One entry whose data is the pieces one after the other (no copy of them is made), deflated
    // at zlib's `level` (1 fastest .. 9 smallest, -1 zlib's default 6) or stored for level 0.
    // Names are ASCII paths with '/' (not checked beyond length). Throws ZipError.
    void add(std::string_view name, std::initializer_list<std::string_view> pieces, int level);
    void add(std::string_view name, const std::vector<std::string_view>& pieces, int level);
    void add(std::string_view name, std::string_view data, int level) { add(name, {data}, level); }

    // Writes the central directory and its end record; closes the file (the close is checked).
    // Returns the archive when writing to memory, an empty string for a file. No entry may be
    // added afterwards.
    std::string finish();

private:
    struct Entry {
        std::string name;
        std::uint16_t method, flags;
        std::uint32_t crc, compressed, size, offset;
    };
    void add_pieces(std::string_view name, const std::string_view* pieces, std::size_t count, int level);
    void emit(std::string_view bytes);
    void close_file();

    int fd_ = -1;
    bool to_file_ = false, finished_ = false;
    std::string path_;
    std::string memory_;
    std::uint64_t written_ = 0;
    std::vector<Entry> entries_;
};

}  // namespace dragon::zip
