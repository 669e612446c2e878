// The workbooks' own zip and xlsx writers, read back by independent readers: the zip by one
// written here on zlib's inflate (central directory, local headers, CRC-32), the XML parts by
// expat, a workbook by openpyxl.
#include <gtest/gtest.h>

#include "support/scratch.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <expat.h>
#include <fmt/format.h>
#include <zlib.h>

#include "dragon/analyses.hpp"
#include "dragon/tables.hpp"
#include "tables/xlsx_writer.hpp"
#include "tables/zip_writer.hpp"

namespace fs = std::filesystem;
using dragon::xlsx::Sheet;
using dragon::xlsx::Workbook;
using dragon::zip::ZipError;
using dragon::zip::ZipWriter;

namespace {

// ---- An independent zip reader ----------------------------------------------------------

struct ReadEntry {
    std::string name, data;
    int method = -1, flags = 0;
    unsigned date = 0, time = 0;
};

unsigned u16(const std::string& b, std::size_t at) {
    if (at + 2 > b.size()) throw std::runtime_error("past the end");
    return static_cast<unsigned>(static_cast<std::uint8_t>(b[at]) | static_cast<std::uint8_t>(b[at + 1]) << 8);
}
std::uint32_t u32(const std::string& b, std::size_t at) { return u16(b, at) | static_cast<std::uint32_t>(u16(b, at + 2)) << 16; }

std::string inflate_raw(const std::string& in, std::size_t size) {
    std::string out(size, '\0');
    z_stream z{};
    if (inflateInit2(&z, -15) != Z_OK) throw std::runtime_error("inflateInit2");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    z.avail_in = static_cast<uInt>(in.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int rc = inflate(&z, Z_FINISH);
    const bool whole = rc == Z_STREAM_END && z.avail_out == 0 && z.avail_in == 0;
    inflateEnd(&z);
    if (!whole) throw std::runtime_error(fmt::format("inflate: rc {}, {} bytes left out, {} in", rc, z.avail_out, z.avail_in));
    return out;
}

// Every entry through the end record and the central directory, each checked against its local
// header, unpacked and its CRC-32 and size checked. Throws std::runtime_error on any mismatch.
std::vector<ReadEntry> read_zip(const std::string& b) {
    if (b.size() < 22) throw std::runtime_error("too short for an end record");
    const std::size_t end = b.size() - 22;  // no archive comment is written
    if (u32(b, end) != 0x06054b50) throw std::runtime_error("no end record");
    if (u16(b, end + 20) != 0) throw std::runtime_error("a comment");
    const unsigned count = u16(b, end + 10);
    if (u16(b, end + 8) != count) throw std::runtime_error("entry counts differ");
    const std::size_t dir_size = u32(b, end + 12), dir_at = u32(b, end + 16);
    if (dir_at + dir_size != end) throw std::runtime_error("the directory does not end at the end record");
    std::vector<ReadEntry> out;
    std::size_t at = dir_at;
    for (unsigned k = 0; k < count; ++k) {
        if (u32(b, at) != 0x02014b50) throw std::runtime_error("a bad directory entry");
        ReadEntry e;
        e.flags = static_cast<int>(u16(b, at + 8));
        e.method = static_cast<int>(u16(b, at + 10));
        e.time = u16(b, at + 12);
        e.date = u16(b, at + 14);
        const std::uint32_t crc = u32(b, at + 16), compressed = u32(b, at + 20), size = u32(b, at + 24);
        const unsigned name_len = u16(b, at + 28), extra = u16(b, at + 30), comment = u16(b, at + 32);
        const std::size_t local = u32(b, at + 42);
        e.name = b.substr(at + 46, name_len);
        at += 46 + name_len + extra + comment;
        // The local header says the same.
        if (u32(b, local) != 0x04034b50) throw std::runtime_error("no local header for " + e.name);
        if (static_cast<int>(u16(b, local + 6)) != e.flags || static_cast<int>(u16(b, local + 8)) != e.method ||
            u16(b, local + 10) != e.time || u16(b, local + 12) != e.date || u32(b, local + 14) != crc ||
            u32(b, local + 18) != compressed || u32(b, local + 22) != size || u16(b, local + 26) != name_len ||
            b.compare(local + 30, name_len, e.name) != 0)
            throw std::runtime_error("the local header differs for " + e.name);
        const std::size_t data_at = local + 30 + name_len + u16(b, local + 28);
        if (data_at + compressed > dir_at) throw std::runtime_error("data past the directory for " + e.name);
        const std::string raw = b.substr(data_at, compressed);
        if (e.method == 0) {
            if (compressed != size) throw std::runtime_error("stored sizes differ for " + e.name);
            e.data = raw;
        } else if (e.method == 8) {
            e.data = inflate_raw(raw, size);
        } else {
            throw std::runtime_error("method " + std::to_string(e.method));
        }
        if (crc32(0, reinterpret_cast<const Bytef*>(e.data.data()), static_cast<uInt>(e.data.size())) != crc)
            throw std::runtime_error("CRC-32 differs for " + e.name);
        out.push_back(std::move(e));
    }
    if (at != end) throw std::runtime_error("the directory's size is wrong");
    return out;
}

std::map<std::string, std::string> parts_of(const std::string& zip) {
    std::map<std::string, std::string> parts;
    for (ReadEntry& e : read_zip(zip)) parts[e.name] = std::move(e.data);
    return parts;
}

// ---- The XML parts through expat --------------------------------------------------------

// OOXML's escapes in strings (_xHHHH_), undone as Excel undoes them.
std::string unescape_ooxml(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '_' && i + 7 <= s.size() && s[i + 1] == 'x' && s[i + 6] == '_' &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2])) && std::isxdigit(static_cast<unsigned char>(s[i + 3])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 4])) && std::isxdigit(static_cast<unsigned char>(s[i + 5]))) {
            out.push_back(static_cast<char>(std::stoi(s.substr(i + 2, 4), nullptr, 16)));  // ASCII only here
            i += 6;
        } else {
            out.push_back(s[i]);
        }
    }
    return out;
}

// What a part holds, as expat reads it: the elements' names in order, the text of each <t> and
// <v>, the attributes of each <c> and <sheet>. Throws if the XML is not well-formed.
struct Xml {
    std::vector<std::string> elements;
    std::vector<std::string> texts;  // <t> in sharedStrings, <v> in sheets
    std::vector<std::map<std::string, std::string>> cells, sheets;
    std::string text;
    bool in_text = false;
};

Xml parse(const std::string& xml) {
    Xml x;
    XML_Parser p = XML_ParserCreate("UTF-8");
    XML_SetUserData(p, &x);
    XML_SetElementHandler(
        p,
        [](void* d, const XML_Char* name, const XML_Char** attrs) {
            auto& x = *static_cast<Xml*>(d);
            const std::string n = name;
            x.elements.push_back(n);
            std::map<std::string, std::string> a;
            for (int i = 0; attrs[i]; i += 2) a[attrs[i]] = attrs[i + 1];
            if (n == "c") x.cells.push_back(a);
            if (n == "sheet") x.sheets.push_back(a);
            if (n == "t" || n == "v") x.in_text = true, x.text.clear();
        },
        [](void* d, const XML_Char* name) {
            auto& x = *static_cast<Xml*>(d);
            const std::string n = name;
            if (n == "t" || n == "v") x.in_text = false, x.texts.push_back(x.text);
        });
    XML_SetCharacterDataHandler(p, [](void* d, const XML_Char* s, int len) {
        auto& x = *static_cast<Xml*>(d);
        if (x.in_text) x.text.append(s, static_cast<std::size_t>(len));
    });
    const bool ok = XML_Parse(p, xml.data(), static_cast<int>(xml.size()), 1) == XML_STATUS_OK;
    const std::string why = ok ? "" : fmt::format("{} at line {}", XML_ErrorString(XML_GetErrorCode(p)),
                                                  XML_GetCurrentLineNumber(p));
    XML_ParserFree(p);
    if (!ok) throw std::runtime_error("not well-formed XML: " + why);
    return x;
}

// A sheet's cells read back: reference -> value (a shared string's text, a number's text).
std::map<std::string, std::string> cells_of(const std::map<std::string, std::string>& parts, int sheet) {
    const Xml strings = parse(parts.at("xl/sharedStrings.xml"));
    const Xml s = parse(parts.at(fmt::format("xl/worksheets/sheet{}.xml", sheet)));
    EXPECT_EQ(s.cells.size(), s.texts.size());
    std::map<std::string, std::string> out;
    for (std::size_t k = 0; k < s.cells.size(); ++k) {
        const auto t = s.cells[k].find("t");
        const std::string& v = s.texts.at(k);
        out[s.cells[k].at("r")] =
            t != s.cells[k].end() && t->second == "s" ? unescape_ooxml(strings.texts.at(std::stoul(v))) : v;
    }
    return out;
}

std::uint64_t bits(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

const std::vector<std::string> kParts = {"[Content_Types].xml", "_rels/.rels", "docProps/app.xml", "docProps/core.xml",
                                         "xl/workbook.xml", "xl/_rels/workbook.xml.rels", "xl/styles.xml",
                                         "xl/sharedStrings.xml", "xl/worksheets/sheet1.xml"};

// Strings with XML's special characters, CJK, spaces that must stay, and OOXML's own escape.
const std::vector<std::string> kStrings = {
    "<a & b> \"quoted\" 'single'", "龙头", "第221节龙身  (m/s)", "龙尾（后）", "  leading and trailing  ",
    "tab\there", "two\nlines", "cr\rhere", "_x0041_ is not A", "a control \x01 char", "]]> and &amp;", "😀 astral",
    ""};

}  // namespace

// ---- zip ----------------------------------------------------------------------------------

TEST(ZipWriter, EntriesReadBackAtEveryLevel) {
    std::mt19937 rng(7);
    std::string noise(100000, '\0');
    for (char& c : noise) c = static_cast<char>(rng());
    const std::string text = [] {
        std::string t;
        for (int k = 0; k < 20000; ++k) t += fmt::format("<c r=\"B{}\"><v>{}</v></c>", k, k * 0.1);
        return t;
    }();
    ZipWriter zip;
    zip.add("stored.bin", noise, 0);
    zip.add("fast.xml", text, 1);
    zip.add("default.xml", text, -1);
    zip.add("six.xml", text, 6);
    zip.add("best.bin", noise, 9);
    zip.add("empty", "", 1);
    zip.add("pieces.xml", {text.substr(0, 1000), "", text.substr(1000)}, 1);
    const std::string bytes = zip.finish();
    const std::vector<ReadEntry> e = read_zip(bytes);
    ASSERT_EQ(e.size(), 7u);
    const std::vector<std::pair<std::string, int>> expect = {
        {"stored.bin", 0}, {"fast.xml", 8}, {"default.xml", 8}, {"six.xml", 8}, {"best.bin", 8}, {"empty", 8}, {"pieces.xml", 8}};
    for (std::size_t k = 0; k < e.size(); ++k) {
        EXPECT_EQ(e[k].name, expect[k].first);
        EXPECT_EQ(e[k].method, expect[k].second) << e[k].name;
        // 2024-09-05 00:00:00 as MS-DOS writes it.
        EXPECT_EQ(e[k].date, (44u << 9) | (9u << 5) | 5u);
        EXPECT_EQ(e[k].time, 0u);
    }
    EXPECT_EQ(e[0].data, noise);
    EXPECT_EQ(e[1].data, text);
    EXPECT_EQ(e[2].data, text);
    EXPECT_EQ(e[4].data, noise);
    EXPECT_EQ(e[5].data, "");
    EXPECT_EQ(e[6].data, text);
    // APPNOTE's bits 1-2 say how hard each was deflated: 11 level 1, 00 normal, 01 maximum.
    EXPECT_EQ(e[1].flags & 6, 6);
    EXPECT_EQ(e[2].flags & 6, 0);
    EXPECT_EQ(e[3].flags & 6, 0);
    EXPECT_EQ(e[4].flags & 6, 2);
    EXPECT_EQ(e[1].data.size(), text.size());
}

TEST(ZipWriter, AFileHoldsTheSameBytesAsMemory) {
    const fs::path path = dragon_test::scratch_dir() / "a.zip";
    ZipWriter file(path.string());
    ZipWriter memory;
    for (ZipWriter* z : {&file, &memory}) {
        z->add("a.txt", "hello, world", 1);
        z->add("b/c.txt", std::string(5000, 'x'), 6);
    }
    EXPECT_EQ(file.finish(), "");
    const std::string bytes = memory.finish();
    EXPECT_EQ(dragon_test::slurp(path), bytes);
    // Python's own reader agrees.
    EXPECT_EQ(std::system(fmt::format("/usr/bin/python3 -m zipfile -t '{}' >/dev/null", path.string()).c_str()), 0);
}

TEST(ZipWriter, FailedWritesCarryTheSystemsReason) {
    try {
        ZipWriter zip("/nonexistent-folder/x.zip");
        ADD_FAILURE() << "opened a file in a missing folder";
    } catch (const ZipError& e) {
        EXPECT_EQ(e.sys_errno(), ENOENT);
    }
    try {
        ZipWriter zip("/dev/full");
        zip.add("a", std::string(200000, 'a'), 0);
        zip.finish();
        ADD_FAILURE() << "wrote to /dev/full";
    } catch (const ZipError& e) {
        EXPECT_EQ(e.sys_errno(), ENOSPC);
    }
}

// A file size limit (ulimit -f): the write fails with EFBIG, in a child process of its own so
// that the limit stays there.
TEST(ZipWriter, AFileSizeLimitIsEFBIG) {
    const fs::path path = dragon_test::scratch_dir() / "limited.zip";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        setrlimit(RLIMIT_FSIZE, &limit);
        try {
            ZipWriter zip(path.string());
            zip.add("a", std::string(100000, 'a'), 0);
            zip.finish();
        } catch (const ZipError& e) {
            _exit(e.sys_errno() == EFBIG ? 0 : 1);
        } catch (...) {
            _exit(2);
        }
        _exit(3);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(ZipWriter, RefusesAnEntryPastFourGiB) {
    // Pieces that add up past 4 GiB, one buffer seen many times: refused before any is read.
    const std::string mib(1 << 20, 'z');
    const std::vector<std::string_view> pieces(4097, mib);
    ZipWriter zip;
    try {
        zip.add("huge", pieces, 1);
        ADD_FAILURE() << "an entry of 4097 MiB was taken";
    } catch (const ZipError& e) {
        EXPECT_EQ(e.sys_errno(), 0);
        EXPECT_NE(std::string(e.what()).find("at most 4 GiB"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'huge'"), std::string::npos) << e.what();
    }
}

// ---- xlsx ---------------------------------------------------------------------------------

TEST(XlsxWriter, CellNames) {
    EXPECT_EQ(dragon::xlsx::cell_name(0, 0), "A1");
    EXPECT_EQ(dragon::xlsx::cell_name(1, 25), "Z2");
    EXPECT_EQ(dragon::xlsx::cell_name(2, 26), "AA3");
    EXPECT_EQ(dragon::xlsx::cell_name(0, 701), "ZZ1");
    EXPECT_EQ(dragon::xlsx::cell_name(0, 702), "AAA1");
    EXPECT_EQ(dragon::xlsx::cell_name(1048575, 16383), "XFD1048576");
}

TEST(XlsxWriter, EveryPartIsThereAndWellFormed) {
    Workbook book;
    Sheet& a = book.add_sheet("位置");
    book.add_sheet("a & <b>");  // an empty sheet, a name to escape
    a.write_string(0, 1, "0 s");
    a.write_number(1, 0, 1.5);
    const auto parts = parts_of(book.bytes(1));
    std::vector<std::string> expected = kParts;
    expected.push_back("xl/worksheets/sheet2.xml");
    std::vector<std::string> names;
    for (const auto& [name, data] : parts) names.push_back(name);
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(names, expected);
    for (const auto& [name, data] : parts) EXPECT_NO_THROW(parse(data)) << name << "\n" << data;
    const Xml workbook = parse(parts.at("xl/workbook.xml"));
    ASSERT_EQ(workbook.sheets.size(), 2u);
    EXPECT_EQ(workbook.sheets[0].at("name"), "位置");
    EXPECT_EQ(workbook.sheets[1].at("name"), "a & <b>");
    EXPECT_NE(parts.at("docProps/core.xml").find(">2024-09-05T00:00:00Z</dcterms:created>"), std::string::npos);
    EXPECT_NE(parts.at("xl/worksheets/sheet1.xml").find("<dimension ref=\"A1:B2\"/>"), std::string::npos);
    // Every part a content type names is there.
    const std::string types = parts.at("[Content_Types].xml");
    for (const auto& [name, data] : parts) {
        if (name.find(".rels") == std::string::npos && name != "[Content_Types].xml") {
            EXPECT_NE(types.find("PartName=\"/" + name + "\""), std::string::npos) << name;
        }
    }
}

TEST(XlsxWriter, NumbersRoundTripBitForBit) {
    std::mt19937_64 rng(11);
    std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 0.1 + 0.2, 1e-300, -1e300, 5e-324, 1.7976931348623157e308,
                                  8.8, -6.237722, 412.473837682146, 123456789012345678.0};
    std::uniform_real_distribution<double> unit(-1000.0, 1000.0);
    for (int k = 0; k < 3000; ++k) {
        double v;
        const std::uint64_t b = rng();
        std::memcpy(&v, &b, sizeof v);
        if (std::isfinite(v)) values.push_back(v);  // any bit pattern
        values.push_back(unit(rng));
        values.push_back(dragon::round6(unit(rng)));
    }
    Workbook book;
    Sheet& s = book.add_sheet("n");
    for (std::size_t k = 0; k < values.size(); ++k)
        s.write_number(static_cast<std::uint32_t>(k / 100), static_cast<std::uint32_t>(k % 100), values[k]);
    const auto cells = cells_of(parts_of(book.bytes(1)), 1);
    ASSERT_EQ(cells.size(), values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
        const std::string ref = dragon::xlsx::cell_name(static_cast<std::uint32_t>(k / 100), static_cast<std::uint32_t>(k % 100));
        const std::string& text = cells.at(ref);
        EXPECT_EQ(bits(std::strtod(text.c_str(), nullptr)), bits(values[k])) << ref << " " << text;
    }
}

TEST(XlsxWriter, NonFiniteNumbersAreErrorCells) {
    Workbook book;
    Sheet& s = book.add_sheet("n");
    s.write_number(0, 0, std::nan(""));
    s.write_number(0, 1, -HUGE_VAL);
    const auto parts = parts_of(book.bytes(1));
    const Xml x = parse(parts.at("xl/worksheets/sheet1.xml"));
    ASSERT_EQ(x.cells.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(x.cells[k].at("t"), "e");
        EXPECT_EQ(x.texts[k], "#NUM!");
    }
}

TEST(XlsxWriter, StringsRoundTrip) {
    Workbook book;
    Sheet& s = book.add_sheet("s");
    for (std::size_t k = 0; k < kStrings.size(); ++k) {
        s.write_string(static_cast<std::uint32_t>(k), 0, kStrings[k]);
        s.write_string(static_cast<std::uint32_t>(k), 1, kStrings[k]);  // shared: stored once
    }
    const auto parts = parts_of(book.bytes(6));
    const auto cells = cells_of(parts, 1);
    for (std::size_t k = 0; k < kStrings.size(); ++k) {
        EXPECT_EQ(cells.at(fmt::format("A{}", k + 1)), kStrings[k]) << k;
        EXPECT_EQ(cells.at(fmt::format("B{}", k + 1)), kStrings[k]) << k;
    }
    const Xml strings = parse(parts.at("xl/sharedStrings.xml"));
    EXPECT_EQ(strings.texts.size(), kStrings.size());
}

TEST(XlsxWriter, RefusesWhatASheetCannotHold) {
    Workbook book;
    Sheet& s = book.add_sheet("s");
    EXPECT_THROW(s.write_number(0, dragon::xlsx::kMaxColumns, 1.0), std::out_of_range);
    EXPECT_THROW(s.write_number(dragon::xlsx::kMaxRows, 0, 1.0), std::out_of_range);
    s.write_number(1, 1, 1.0);
    EXPECT_THROW(s.write_number(1, 1, 2.0), std::invalid_argument);  // the same cell again
    EXPECT_THROW(s.write_number(0, 5, 2.0), std::invalid_argument);  // a row before
    EXPECT_THROW(s.write_string(1, 2, "\xff bad UTF-8"), std::invalid_argument);
    EXPECT_THROW(s.write_string(1, 2, "\xe9\xbe"), std::invalid_argument);  // cut short
    EXPECT_THROW(s.write_string(0, 9, "kept?"), std::invalid_argument);  // a row before: the text is not kept
    s.write_number(1, 2, 3.0);  // still writable after the refusals
    s.write_string(1, 3, "ok");
    EXPECT_THROW(book.add_sheet(""), std::invalid_argument);
    EXPECT_THROW(book.add_sheet("S"), std::invalid_argument);  // names differ only in case
    EXPECT_THROW(book.add_sheet("a/b"), std::invalid_argument);
    EXPECT_THROW(book.add_sheet(std::string(32, 'x')), std::invalid_argument);
    EXPECT_NO_THROW(book.add_sheet(std::string(31, 'x')));
    EXPECT_NO_THROW(book.add_sheet("龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙头龙"));  // 31 characters
    const auto parts = parts_of(book.bytes(1));
    EXPECT_EQ(cells_of(parts, 1), (std::map<std::string, std::string>{{"B2", "1"}, {"C2", "3"}, {"D2", "ok"}}));
    EXPECT_NE(parts.at("xl/sharedStrings.xml").find("count=\"1\" uniqueCount=\"1\""), std::string::npos);
}

TEST(XlsxWriter, SameCellsSameBytes) {
    const auto make = [] {
        Workbook book;
        Sheet& s = book.add_sheet("Sheet1");
        for (std::uint32_t r = 0; r < 50; ++r) {
            s.write_string(r, 0, fmt::format("row {}", r % 7));
            s.write_number(r, 1, r * 0.37);
        }
        return book.bytes(1);
    };
    const std::string a = make();
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    EXPECT_EQ(make(), a);
}

// openpyxl, an independent reader, reads every string and the exact double of every number.
TEST(XlsxWriter, OpenpyxlReadsTheCells) {
    Workbook book;
    Sheet& s = book.add_sheet("位置");
    const fs::path dir = dragon_test::scratch_dir();
    std::ofstream expect(dir / "expected.tsv");
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(-500.0, 500.0);
    std::uint32_t row = 0;
    for (const std::string& t : kStrings) {
        // openpyxl keeps OOXML's _xHHHH_ escapes of control characters as text: those strings
        // are checked above with our own reader.
        if (t.find('\x01') != std::string::npos || t.empty()) continue;
        s.write_string(row, 0, t);
        std::string hex;
        for (const char c : t) hex += fmt::format("{:02x}", static_cast<unsigned char>(c));
        expect << fmt::format("s\t{}\t1\t{}\n", row + 1, hex);
        ++row;
    }
    for (int k = 0; k < 500; ++k, ++row) {
        const double v = k % 2 ? unit(rng) : dragon::round6(unit(rng));
        s.write_number(row, 3, v);
        expect << fmt::format("n\t{}\t4\t{:a}\n", row + 1, v);
    }
    expect.close();
    const fs::path path = dir / "cells.xlsx";
    book.save(path.string(), 1);
    const std::string script = R"(
import sys, openpyxl
ws = openpyxl.load_workbook(sys.argv[1])["位置"]
bad = 0
for line in open(sys.argv[2], encoding="utf-8"):
    kind, row, col, value = line.rstrip("\n").split("\t")
    want = bytes.fromhex(value).decode("utf-8") if kind == "s" else float.fromhex(value)
    got = ws.cell(int(row), int(col)).value
    if kind == "s" and got != want or kind == "n" and (not isinstance(got, float) and not isinstance(got, int) or got != want):
        print(row, col, repr(got), repr(want)); bad += 1
sys.exit(1 if bad else 0)
)";
    std::ofstream(dir / "check.py") << script;
    EXPECT_EQ(std::system(fmt::format("/usr/bin/python3 '{}' '{}' '{}'", (dir / "check.py").string(), path.string(),
                                      (dir / "expected.tsv").string())
                              .c_str()),
              0);
}

// Two workbooks written at once from two threads: both valid, both as written alone.
TEST(XlsxWriter, TwoWorkbooksAtOnceFromTwoThreads) {
    const dragon::Simulation sim(dragon::Scenario{});
    const std::vector<dragon::Frame> frames = dragon::simulate_table(sim, 0.0, 60.0, 1.0);
    const fs::path dir = dragon_test::scratch_dir();
    const fs::path alone1 = dir / "alone1.xlsx", alone2 = dir / "alone2.xlsx";
    dragon::write_result_xlsx(frames, alone1.string());
    dragon::write_result2_xlsx(frames.back(), alone2.string());
    for (int round = 0; round < 3; ++round) {
        const fs::path a = dir / "a.xlsx", b = dir / "b.xlsx";
        std::thread one([&] { dragon::write_result_xlsx(frames, a.string()); });
        std::thread two([&] { dragon::write_result2_xlsx(frames.back(), b.string()); });
        one.join();
        two.join();
        const std::string ab = dragon_test::slurp(a), bb = dragon_test::slurp(b);
        EXPECT_EQ(ab, dragon_test::slurp(alone1));
        EXPECT_EQ(bb, dragon_test::slurp(alone2));
        for (const std::string* bytes : {&ab, &bb}) {
            const auto parts = parts_of(*bytes);
            for (const auto& [name, data] : parts) EXPECT_NO_THROW(parse(data)) << name;
        }
    }
    // The contest's layout, read back by our reader: labels, headers, numbers as round6 gives them.
    const auto parts = parts_of(dragon_test::slurp(alone1));
    const auto pos = cells_of(parts, 1), vel = cells_of(parts, 2);
    EXPECT_EQ(pos.at("B1"), "0 s");
    EXPECT_EQ(pos.at("BJ1"), "60 s");
    EXPECT_EQ(pos.at("A2"), "龙头x (m)");
    EXPECT_EQ(pos.at("A5"), "第1节龙身y (m)");
    EXPECT_EQ(vel.at("A2"), "龙头 (m/s)");
    EXPECT_EQ(vel.at("A3"), "第1节龙身  (m/s)");
    EXPECT_EQ(vel.at("A225"), "龙尾（后） (m/s)");
    EXPECT_EQ(pos.size(), 61u + 448u * 62u);  // the headers, then a label and 61 numbers a row
    EXPECT_EQ(bits(std::strtod(pos.at("B2").c_str(), nullptr)), bits(dragon::round6(frames[0].handles[0].pos.x())));
    EXPECT_EQ(bits(std::strtod(vel.at("C3").c_str(), nullptr)), bits(dragon::round6(frames[1].handles[1].speed)));
}

// The level asked for is the level the parts are packed at; a level zlib does not have is refused.
TEST(XlsxWriter, TheWorkbooksLevelIsTheOneAsked) {
    const dragon::Frame f = dragon::Simulation(dragon::Scenario{}).frame(10.0);
    const fs::path dir = dragon_test::scratch_dir();
    std::map<int, std::string> by_level;
    for (const int level : {0, 1, 6, 9}) {
        const fs::path p = dir / fmt::format("l{}.xlsx", level);
        dragon::write_result2_xlsx(f, p.string(), dragon::WorkbookOptions{level});
        by_level[level] = dragon_test::slurp(p);
        for (const ReadEntry& e : read_zip(by_level[level])) EXPECT_EQ(e.method, level == 0 ? 0 : 8) << level;
    }
    EXPECT_EQ(parts_of(by_level[0]), parts_of(by_level[9]));  // the same parts, packed differently
    EXPECT_GT(by_level[0].size(), by_level[1].size());
    EXPECT_GE(by_level[1].size(), by_level[9].size());
    EXPECT_THROW(dragon::write_result2_xlsx(f, (dir / "bad.xlsx").string(), dragon::WorkbookOptions{10}), dragon::InputError);
    EXPECT_THROW(dragon::write_result2_xlsx(f, (dir / "bad.xlsx").string(), dragon::WorkbookOptions{-1}), dragon::InputError);
    EXPECT_FALSE(fs::exists(dir / "bad.xlsx"));
}
