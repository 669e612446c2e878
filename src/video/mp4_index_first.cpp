#include "mp4_index_first.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string_view>

#include "dragon/errors.hpp"

namespace dragon::video {

namespace {

std::uint64_t read_be(const std::uint8_t* p, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
    return v;
}

void write_be(std::uint8_t* p, int bytes, std::uint64_t v) {
    for (int i = bytes - 1; i >= 0; --i, v >>= 8) p[i] = static_cast<std::uint8_t>(v & 0xff);
}

// One box: where its payload starts and where the box ends, within a buffer or a file.
struct Box {
    std::string_view type;
    std::uint64_t payload = 0, end = 0;
};

// The box whose header starts at `at` of `bytes` (size, type, and a 64-bit size when the size
// says 1; 0 means "to the end"), or false if it does not fit inside [at, end).
bool box_at(const std::vector<std::uint8_t>& bytes, std::uint64_t at, std::uint64_t end, Box& box) {
    if (end - at < 8) return false;
    const std::uint8_t* p = bytes.data() + at;
    std::uint64_t size = read_be(p, 4), header = 8;
    if (size == 1) {
        if (end - at < 16) return false;
        size = read_be(p + 8, 8), header = 16;
    } else if (size == 0) {
        size = end - at;
    }
    if (size < header || size > end - at) return false;
    box = {std::string_view(reinterpret_cast<const char*>(p + 4), 4), at + header, at + size};
    return true;
}

// Every chunk offset table under the container [from, end) of `moov` (moov, trak, mdia, minf,
// stbl hold them), checked whole; each as (first entry's place, entry count, entry bytes).
struct Table {
    std::uint64_t at, count;
    int bytes;
};
bool find_tables(const std::vector<std::uint8_t>& moov, std::uint64_t from, std::uint64_t end,
                 std::vector<Table>& tables) {
    for (std::uint64_t at = from; at < end;) {
        Box box;
        if (!box_at(moov, at, end, box)) return false;
        if (box.type == "trak" || box.type == "mdia" || box.type == "minf" || box.type == "stbl") {
            if (!find_tables(moov, box.payload, box.end, tables)) return false;
        } else if (box.type == "stco" || box.type == "co64") {
            // A full box: version and flags, the entry count, then the entries.
            const int bytes = box.type == "stco" ? 4 : 8;
            if (box.end - box.payload < 8) return false;
            const std::uint64_t count = read_be(moov.data() + box.payload + 4, 4);
            if (count > (box.end - box.payload - 8) / bytes) return false;
            tables.push_back({box.payload + 8, count, bytes});
        }
        at = box.end;
    }
    return true;
}

[[noreturn]] void fail(const std::string& target, int err) {
    throw FileError(target, "finish", std::strerror(err != 0 ? err : EIO));
}

struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

// Reads or writes `n` bytes at `at` of `f`, or throws naming `target`.
void read_at(std::FILE* f, std::uint64_t at, std::uint8_t* into, std::size_t n, const std::string& target) {
    if (fseeko(f, static_cast<off_t>(at), SEEK_SET) != 0 || std::fread(into, 1, n, f) != n) fail(target, errno);
}
void write_at(std::FILE* f, std::uint64_t at, const std::uint8_t* from, std::size_t n, const std::string& target) {
    if (fseeko(f, static_cast<off_t>(at), SEEK_SET) != 0 || std::fwrite(from, 1, n, f) != n) fail(target, errno);
}

}  // namespace

bool shift_chunk_offsets(std::vector<std::uint8_t>& moov, std::uint64_t by) {
    Box root;
    if (!box_at(moov, 0, moov.size(), root) || root.type != "moov" || root.end != moov.size()) return false;
    std::vector<Table> tables;
    if (!find_tables(moov, root.payload, root.end, tables)) return false;
    for (const Table& t : tables)
        for (std::uint64_t i = 0; i < t.count; ++i) {
            const std::uint64_t v = read_be(moov.data() + t.at + i * t.bytes, t.bytes);
            const std::uint64_t most = t.bytes == 4 ? std::numeric_limits<std::uint32_t>::max()
                                                    : std::numeric_limits<std::uint64_t>::max();
            if (v > most - by) return false;
        }
    for (const Table& t : tables)
        for (std::uint64_t i = 0; i < t.count; ++i) {
            std::uint8_t* p = moov.data() + t.at + i * t.bytes;
            write_be(p, t.bytes, read_be(p, t.bytes) + by);
        }
    return true;
}

void move_index_first(const std::string& path, const std::string& target) {
    std::unique_ptr<std::FILE, CloseFile> f(std::fopen(path.c_str(), "r+b"));
    if (!f) fail(target, errno);
    if (fseeko(f.get(), 0, SEEK_END) != 0) fail(target, errno);
    const off_t length = ftello(f.get());
    if (length < 0) fail(target, errno);
    const auto file_size = static_cast<std::uint64_t>(length);

    // The top-level boxes, by their headers: the first must be ftyp, the last moov.
    std::uint64_t ftyp_end = 0, moov_at = 0;
    bool moov_last = false;
    for (std::uint64_t at = 0; at < file_size;) {
        std::uint8_t header[16];
        const auto have = static_cast<std::size_t>(std::min<std::uint64_t>(sizeof header, file_size - at));
        if (have < 8) return;  // not a file this knows: left as it is
        read_at(f.get(), at, header, have, target);
        std::uint64_t size = read_be(header, 4);
        if (size == 1) {
            if (have < 16) return;
            size = read_be(header + 8, 8);
        } else if (size == 0) {
            size = file_size - at;  // to the end
        }
        if (size < 8 || size > file_size - at) return;
        const std::string_view type(reinterpret_cast<const char*>(header + 4), 4);
        if (at == 0 && type != "ftyp") return;
        if (at == 0) ftyp_end = size;
        moov_last = type == "moov" && at + size == file_size;
        if (moov_last) moov_at = at;
        at += size;
    }
    if (!moov_last || moov_at == ftyp_end) return;  // nothing to move

    std::vector<std::uint8_t> moov(static_cast<std::size_t>(file_size - moov_at));
    read_at(f.get(), moov_at, moov.data(), moov.size(), target);
    const std::uint64_t by = moov.size();
    if (!shift_chunk_offsets(moov, by)) return;

    // Everything between ftyp and moov moves back by the moov's size, from its end first so that
    // no byte is overwritten before it has been read; then the moov goes where it began.
    std::vector<std::uint8_t> buffer(std::size_t{1} << 20);
    for (std::uint64_t end = moov_at; end > ftyp_end;) {
        const std::uint64_t n = std::min<std::uint64_t>(buffer.size(), end - ftyp_end);
        const std::uint64_t at = end - n;
        read_at(f.get(), at, buffer.data(), static_cast<std::size_t>(n), target);
        write_at(f.get(), at + by, buffer.data(), static_cast<std::size_t>(n), target);
        end = at;
    }
    write_at(f.get(), ftyp_end, moov.data(), moov.size(), target);
    if (std::fclose(f.release()) != 0) fail(target, errno);
}

}  // namespace dragon::video
