// Long-form CSV and JSON tables.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/scenario.hpp"
#include "dragon/tables.hpp"

namespace dragon {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

void check_digits(int digits) {
    if (digits < 0 || digits > kMaxDigits)
        throw InputError(Key::digits, std::to_string(digits), fmt::format("use 0 to {} decimals", kMaxDigits));
}

// Writes the buffer out and empties it; false (errno set) if the stream took less.
bool flush_to(fmt::memory_buffer& buf, std::FILE* f) {
    const bool ok = std::fwrite(buf.data(), 1, buf.size(), f) == buf.size();
    buf.clear();
    return ok;
}

// The CSV rows of `frames`, a megabyte at a time; false (errno set) on a failed write.
bool put_csv(const std::vector<Frame>& frames, std::FILE* f, int digits) {
    fmt::memory_buffer buf;
    fmt::format_to(std::back_inserter(buf), "t,handle,x,y,speed\n");
    for (const Frame& fr : frames) {
        const std::string t = format_time(fr.time, digits);
        for (size_t i = 0; i < fr.handles.size(); ++i) {
            const Handle& h = fr.handles[i];
            fmt::format_to(std::back_inserter(buf), "{},{},{},{},{}\n", t, i, format_fixed(h.pos.x(), digits),
                           format_fixed(h.pos.y(), digits), format_fixed(h.speed, digits));
        }
        if (buf.size() > (1u << 20) && !flush_to(buf, f)) return false;
    }
    return flush_to(buf, f);
}

// Opens the temporary file, runs `put` on it and closes it; a failure names the target and why.
template <typename Put>
void write_through(AtomicFile& out, Put&& put) {
    errno = 0;
    FilePtr f(std::fopen(out.temp_path().c_str(), "wb"));
    if (!f) throw out.write_error(std::strerror(errno));
    const bool ok = put(f.get());
    const int err = errno;
    if (std::fclose(f.release()) != 0 || !ok) throw out.write_error(std::strerror(ok ? errno : err));
}

}  // namespace

void write_csv(const std::vector<Frame>& frames, const std::string& path, int digits, RunOutputs* outputs) {
    check_digits(digits);
    AtomicFile out(path, outputs);
    write_through(out, [&](std::FILE* f) { return put_csv(frames, f, digits); });
    out.commit();
}

void print_csv(const std::vector<Frame>& frames, std::FILE* out, int digits) {
    check_digits(digits);
    if (!put_csv(frames, out, digits))
        throw FileError("standard output", "write the table to", std::strerror(errno));
}

void write_json(const std::vector<Frame>& frames, const std::string& path, int digits, RunOutputs* outputs) {
    check_digits(digits);
    AtomicFile out(path, outputs);
    fmt::memory_buffer buf;
    auto put = [&buf]<typename... A>(fmt::format_string<A...> f, A&&... a) {
        fmt::format_to(std::back_inserter(buf), f, std::forward<A>(a)...);
    };
    const size_t n = frames.empty() ? 0 : frames.front().handles.size();
    put("{{\"handles\": {}, \"frames\": [\n", n);
    for (size_t k = 0; k < frames.size(); ++k) {
        const Frame& fr = frames[k];
        const auto list = [&](auto value) {
            for (size_t i = 0; i < fr.handles.size(); ++i)
                put("{}{}", i ? ", " : "", format_fixed(value(fr.handles[i]), digits));
        };
        put("  {{\"t\": {}, \"x\": [", format_time(fr.time, digits));
        list([](const Handle& h) { return h.pos.x(); });
        put("], \"y\": [");
        list([](const Handle& h) { return h.pos.y(); });
        put("], \"speed\": [");
        list([](const Handle& h) { return h.speed; });
        put("]}}{}\n", k + 1 < frames.size() ? "," : "");
    }
    put("]}}\n");
    write_through(out, [&](std::FILE* f) { return flush_to(buf, f); });
    out.commit();
}

void write_table(const std::vector<Frame>& frames, const std::string& path, int digits, const WorkbookOptions& workbook,
                 RunOutputs* outputs) {
    const std::string ext = extension_of(path);
    if (ext == ".csv") return write_csv(frames, path, digits, outputs);
    if (ext == ".json") return write_json(frames, path, digits, outputs);
    if (ext == ".xlsx") return write_result_xlsx(frames, path, workbook, outputs);
    throw InputError(fmt::format("output '{}' has extension '{}': use .csv, .json or .xlsx", path, ext));
}

}  // namespace dragon
