// Long-form CSV and JSON tables.
#include <cstdio>
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

FilePtr open_for_write(const std::string& path) {
    FilePtr f(std::fopen(path.c_str(), "wb"));
    if (!f) throw std::runtime_error(fmt::format("cannot create '{}'", path));
    return f;
}

void close_checked(FilePtr f, const std::string& path) {
    std::FILE* raw = f.release();
    const bool bad = std::ferror(raw) != 0;
    if (std::fclose(raw) != 0 || bad) throw std::runtime_error(fmt::format("cannot write '{}'", path));
}

}  // namespace

void write_csv(const std::vector<Frame>& frames, const std::string& path) {
    AtomicFile out(path);
    FilePtr f = open_for_write(out.temp_path());
    fmt::memory_buffer buf;
    fmt::format_to(std::back_inserter(buf), "t,handle,x,y,speed\n");
    for (const Frame& fr : frames) {
        for (size_t i = 0; i < fr.handles.size(); ++i) {
            const Handle& h = fr.handles[i];
            fmt::format_to(std::back_inserter(buf), "{},{},{:.6f},{:.6f},{:.6f}\n", format_time(fr.time), i,
                           round6(h.pos.x), round6(h.pos.y), round6(h.speed));
        }
        if (buf.size() > (1u << 20)) {
            std::fwrite(buf.data(), 1, buf.size(), f.get());
            buf.clear();
        }
    }
    std::fwrite(buf.data(), 1, buf.size(), f.get());
    close_checked(std::move(f), path);
    out.commit();
}

void write_json(const std::vector<Frame>& frames, const std::string& path) {
    AtomicFile out(path);
    FilePtr f = open_for_write(out.temp_path());
    fmt::memory_buffer buf;
    auto put = [&buf]<typename... A>(fmt::format_string<A...> f, A&&... a) {
        fmt::format_to(std::back_inserter(buf), f, std::forward<A>(a)...);
    };
    const size_t n = frames.empty() ? 0 : frames.front().handles.size();
    put("{{\"handles\": {}, \"frames\": [\n", n);
    for (size_t k = 0; k < frames.size(); ++k) {
        const Frame& fr = frames[k];
        put("  {{\"t\": {}, \"x\": [", format_time(fr.time));
        for (size_t i = 0; i < fr.handles.size(); ++i) put("{}{:.6f}", i ? ", " : "", round6(fr.handles[i].pos.x));
        put("], \"y\": [");
        for (size_t i = 0; i < fr.handles.size(); ++i) put("{}{:.6f}", i ? ", " : "", round6(fr.handles[i].pos.y));
        put("], \"speed\": [");
        for (size_t i = 0; i < fr.handles.size(); ++i) put("{}{:.6f}", i ? ", " : "", round6(fr.handles[i].speed));
        put("]}}{}\n", k + 1 < frames.size() ? "," : "");
    }
    put("]}}\n");
    std::fwrite(buf.data(), 1, buf.size(), f.get());
    close_checked(std::move(f), path);
    out.commit();
}

void write_table(const std::vector<Frame>& frames, const std::string& path) {
    const std::string ext = extension_of(path);
    if (ext == ".csv") return write_csv(frames, path);
    if (ext == ".json") return write_json(frames, path);
    if (ext == ".xlsx") return write_result_xlsx(frames, path);
    throw InputError(fmt::format("output '{}' has extension '{}': use .csv, .json or .xlsx", path, ext));
}

}  // namespace dragon
