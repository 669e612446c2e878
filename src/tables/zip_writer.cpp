#include "zip_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>

#include <fmt/format.h>
#include <zlib.h>

namespace dragon::zip {

namespace {

constexpr std::uint16_t kVersion = 20;  // 2.0: deflate; made by MS-DOS (host 0), as needed to extract
constexpr std::uint16_t kStored = 0, kDeflated = 8;
// zlib takes at most 4 GiB - 1 at a time (uInt); pieces are fed in slices of 1 GiB.
constexpr std::size_t kSlice = std::size_t{1} << 30;

void put16(std::string& b, std::uint16_t v) {
    b.push_back(static_cast<char>(v & 0xFF));
    b.push_back(static_cast<char>(v >> 8));
}
void put32(std::string& b, std::uint32_t v) {
    put16(b, static_cast<std::uint16_t>(v & 0xFFFF));
    put16(b, static_cast<std::uint16_t>(v >> 16));
}

// APPNOTE 4.4.4, bits 1-2 of a deflated entry: how hard it was compressed (as minizip sets them).
std::uint16_t level_flags(int level) {
    if (level == 1) return 6;  // super fast
    if (level == 2) return 4;  // fast
    if (level == 8 || level == 9) return 2;  // maximum
    return 0;  // normal
}

std::string too_large(std::string_view what, std::uint64_t bytes) {
    return fmt::format("{} would be {} bytes: a zip archive without zip64 holds at most 4 GiB (4,294,967,295 bytes)",
                       what, bytes);
}

// Raw deflate (no zlib header: windowBits -15) of the pieces, one after the other.
std::string deflate_pieces(const std::string_view* pieces, std::size_t count, std::uint64_t total, int level) {
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw ZipError(fmt::format("zlib cannot start deflating at level {}", level), 0);
    struct End {
        z_stream* z;
        ~End() { deflateEnd(z); }
    } end{&z};
    std::string out(static_cast<std::size_t>(deflateBound(&z, static_cast<uLong>(total))) + 64, '\0');
    std::size_t produced = 0;
    const auto run = [&](const char* data, std::size_t size, int flush) {
        z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
        z.avail_in = static_cast<uInt>(size);
        do {
            if (produced == out.size()) out.resize(out.size() * 2);
            const std::size_t room = std::min(out.size() - produced, kSlice);
            z.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
            z.avail_out = static_cast<uInt>(room);
            const int rc = deflate(&z, flush);
            if (rc == Z_STREAM_ERROR) throw ZipError("zlib failed while deflating", 0);
            produced += room - z.avail_out;
            if (rc == Z_STREAM_END) return;
        } while (z.avail_out == 0 || z.avail_in > 0 || flush == Z_FINISH);
    };
    for (std::size_t k = 0; k < count; ++k)
        for (std::size_t at = 0; at < pieces[k].size(); at += kSlice)
            run(pieces[k].data() + at, std::min(kSlice, pieces[k].size() - at), Z_NO_FLUSH);
    run(nullptr, 0, Z_FINISH);
    out.resize(produced);
    return out;
}

}  // namespace

ZipWriter::ZipWriter() = default;

ZipWriter::ZipWriter(const std::string& path) : to_file_(true), path_(path) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) {
        const int err = errno;
        throw ZipError(fmt::format("cannot open '{}': {}", path, std::strerror(err)), err);
    }
}

ZipWriter::~ZipWriter() {
    if (fd_ >= 0) ::close(fd_);
}

void ZipWriter::close_file() {
    const int fd = fd_;
    fd_ = -1;
    if (fd >= 0 && ::close(fd) != 0) {
        const int err = errno;
        throw ZipError(fmt::format("cannot write '{}': {}", path_, std::strerror(err)), err);
    }
}

void ZipWriter::emit(std::string_view bytes) {
    if (written_ + bytes.size() > kMaxZipSize) throw ZipError(too_large("the archive", written_ + bytes.size()), 0);
    written_ += bytes.size();
    if (!to_file_) {
        memory_.append(bytes);
        return;
    }
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd_, bytes.data(), std::min(bytes.size(), kSlice));
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            throw ZipError(fmt::format("cannot write '{}': {}", path_, std::strerror(err)), err);
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
}

void ZipWriter::add(std::string_view name, std::initializer_list<std::string_view> pieces, int level) {
    add_pieces(name, pieces.begin(), pieces.size(), level);
}

void ZipWriter::add(std::string_view name, const std::vector<std::string_view>& pieces, int level) {
    add_pieces(name, pieces.data(), pieces.size(), level);
}

void ZipWriter::add_pieces(std::string_view name, const std::string_view* pieces, std::size_t count, int level) {
    if (finished_) throw std::logic_error("ZipWriter::add after finish()");
    if (level < -1 || level > 9) throw std::invalid_argument(fmt::format("zlib level {} is not -1..9", level));
    if (name.empty() || name.size() > 0xFFFF) throw ZipError(fmt::format("an entry name of {} bytes", name.size()), 0);
    if (entries_.size() == 0xFFFF) throw ZipError("a zip archive without zip64 holds at most 65,535 entries", 0);
    std::uint64_t total = 0;
    for (std::size_t k = 0; k < count; ++k) total += pieces[k].size();
    if (total > kMaxZipSize) throw ZipError(too_large(fmt::format("the entry '{}'", name), total), 0);
    uLong crc = crc32_z(0, nullptr, 0);
    for (std::size_t k = 0; k < count; ++k)
        crc = crc32_z(crc, reinterpret_cast<const Bytef*>(pieces[k].data()), pieces[k].size());

    Entry e{std::string(name), level == 0 ? kStored : kDeflated, 0, static_cast<std::uint32_t>(crc), 0,
            static_cast<std::uint32_t>(total), 0};
    std::string deflated;
    if (e.method == kDeflated) {
        deflated = deflate_pieces(pieces, count, total, level);
        if (deflated.size() > kMaxZipSize) throw ZipError(too_large(fmt::format("the entry '{}'", name), deflated.size()), 0);
        e.compressed = static_cast<std::uint32_t>(deflated.size());
        e.flags = level_flags(level);
    } else {
        e.compressed = e.size;
    }
    if (written_ > kMaxZipSize) throw ZipError(too_large("the archive", written_), 0);
    e.offset = static_cast<std::uint32_t>(written_);

    std::string header;
    header.reserve(30 + name.size());
    put32(header, 0x04034b50);
    put16(header, kVersion);
    put16(header, e.flags);
    put16(header, e.method);
    put16(header, kDosTime);
    put16(header, kDosDate);
    put32(header, e.crc);
    put32(header, e.compressed);
    put32(header, e.size);
    put16(header, static_cast<std::uint16_t>(name.size()));
    put16(header, 0);  // no extra field
    header.append(name);
    emit(header);
    if (e.method == kDeflated) {
        emit(deflated);
    } else {
        for (std::size_t k = 0; k < count; ++k) emit(pieces[k]);
    }
    entries_.push_back(std::move(e));
}

std::string ZipWriter::finish() {
    if (finished_) throw std::logic_error("ZipWriter::finish twice");
    finished_ = true;
    const std::uint64_t start = written_;
    std::string dir;
    for (const Entry& e : entries_) {
        put32(dir, 0x02014b50);
        put16(dir, kVersion);  // made by
        put16(dir, kVersion);  // needed to extract
        put16(dir, e.flags);
        put16(dir, e.method);
        put16(dir, kDosTime);
        put16(dir, kDosDate);
        put32(dir, e.crc);
        put32(dir, e.compressed);
        put32(dir, e.size);
        put16(dir, static_cast<std::uint16_t>(e.name.size()));
        put16(dir, 0);  // extra field
        put16(dir, 0);  // comment
        put16(dir, 0);  // disk
        put16(dir, 0);  // internal attributes
        put32(dir, 0);  // external attributes
        put32(dir, e.offset);
        dir.append(e.name);
    }
    const std::size_t dir_size = dir.size();
    if (start + dir_size > kMaxZipSize) throw ZipError(too_large("the archive", start + dir_size), 0);
    put32(dir, 0x06054b50);
    put16(dir, 0);  // this disk
    put16(dir, 0);  // the directory's disk
    put16(dir, static_cast<std::uint16_t>(entries_.size()));
    put16(dir, static_cast<std::uint16_t>(entries_.size()));
    put32(dir, static_cast<std::uint32_t>(dir_size));
    put32(dir, static_cast<std::uint32_t>(start));
    put16(dir, 0);  // comment
    emit(dir);
    if (to_file_) {
        close_file();
        return {};
    }
    return std::move(memory_);
}

}  // namespace dragon::zip
