// The entries of a zip file as its local file headers state them: name, compression method and
// the general-purpose flags, whose bits 1-2 say how hard a deflated entry was compressed
// (APPNOTE 4.4.4: 00 normal, 01 maximum, 10 fast, 11 super fast; minizip writes 11 for zlib's
// level 1). Enough to tell how a workbook was packed without unpacking it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/scratch.hpp"

namespace dragon_test {

struct ZipEntry {
    std::string name;
    int method = -1;  // 0 stored, 8 deflated
    int flags = 0;
};

inline std::vector<ZipEntry> zip_entries(const std::filesystem::path& path) {
    const std::string b = slurp(path);
    const auto u16 = [&](std::size_t at) {
        return static_cast<int>(static_cast<std::uint8_t>(b[at]) | static_cast<std::uint8_t>(b[at + 1]) << 8);
    };
    const auto u32 = [&](std::size_t at) {
        return static_cast<std::size_t>(u16(at)) | static_cast<std::size_t>(u16(at + 2)) << 16;
    };
    std::vector<ZipEntry> out;
    std::size_t at = 0;
    // Local headers follow one another (PK\3\4), each with its data; sizes are in the header
    // unless bit 3 defers them to a descriptor, which the workbooks' zip writer does not use.
    while (at + 30 <= b.size() && b.compare(at, 4, "PK\3\4") == 0) {
        ZipEntry e;
        e.flags = u16(at + 6);
        e.method = u16(at + 8);
        const std::size_t compressed = u32(at + 18), name_len = static_cast<std::size_t>(u16(at + 26)),
                          extra_len = static_cast<std::size_t>(u16(at + 28));
        if ((e.flags & 8) != 0 || at + 30 + name_len > b.size()) break;
        e.name = b.substr(at + 30, name_len);
        out.push_back(e);
        at += 30 + name_len + extra_len + compressed;
    }
    return out;
}

}  // namespace dragon_test
