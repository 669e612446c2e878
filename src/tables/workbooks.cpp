// The contest's workbooks (result1/2/4.xlsx), cell for cell as in its templates.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <xlsxwriter.h>

#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"

namespace dragon {

namespace {

// libxlsxwriter prints its own lines on stderr before it returns an error (three for a full
// disk, naming the hidden temporary file). The error comes back as one exception naming the
// target; an application that asks (WorkbookOptions) has file descriptor 2 point at /dev/null
// for the call. A process-wide effect, so only when asked: while any workbook closes (several
// may, on different threads: dragon solve writes its tables in parallel) the first to start
// mutes and the last to finish restores.
class StderrMuted {
public:
    explicit StderrMuted(bool mute) : mute_(mute) {
        if (!mute_) return;
        const std::lock_guard<std::mutex> hold(lock());
        if (depth()++ > 0) return;
        std::fflush(stderr);
        saved() = ::dup(STDERR_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved() >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
        if (null >= 0) ::close(null);
    }
    ~StderrMuted() {
        if (!mute_) return;
        const std::lock_guard<std::mutex> hold(lock());
        if (--depth() > 0 || saved() < 0) return;
        ::dup2(saved(), STDERR_FILENO);
        ::close(saved());
        saved() = -1;
    }
    StderrMuted(const StderrMuted&) = delete;
    StderrMuted& operator=(const StderrMuted&) = delete;

private:
    bool mute_;
    static std::mutex& lock() {
        static std::mutex m;
        return m;
    }
    static int& depth() {
        static int d = 0;
        return d;
    }
    static int& saved() {
        static int fd = -1;
        return fd;
    }
};

// libxlsxwriter's closing (it packs the sheets into the zip) stamps the document with gmtime(),
// whose one static result every thread shares in the C library: two workbooks closing at once
// race on it (ThreadSanitizer saw it in Workbooks.SeveralAtOnceOnThreads). That is its only
// state shared between workbooks, so an application that gives the process a gmtime() with a
// result of each thread's own (the tool does: cli/gmtime_per_thread.cpp) has its workbooks
// closed in parallel; otherwise one close at a time, the cells still going in parallel. Which
// gmtime() the process has is seen from what it does: one result for two threads, or two.
bool gmtime_is_per_thread() {
    static const bool per_thread = [] {
        const std::time_t epoch = 0;
        const std::tm* here = std::gmtime(&epoch);
        const std::tm* there = nullptr;
        std::thread([&] { there = std::gmtime(&epoch); }).join();
        return here != nullptr && there != nullptr && here != there;
    }();
    return per_thread;
}

std::mutex& close_lock() {
    static std::mutex m;
    return m;
}

std::unique_lock<std::mutex> one_close_at_a_time() {
    if (gmtime_is_per_thread()) return {};
    return std::unique_lock<std::mutex>(close_lock());
}

// Closing writes the file; also when an exception unwinds past an unfinished workbook.
struct WorkbookCloser {
    bool mute = false;
    void operator()(lxw_workbook* wb) const {
        const std::unique_lock<std::mutex> turn = one_close_at_a_time();
        const StderrMuted quiet(mute);
        workbook_close(wb);
    }
};
using WorkbookPtr = std::unique_ptr<lxw_workbook, WorkbookCloser>;

// The creation time written into every workbook: a fixed moment (the contest's opening,
// 2024-09-05 00:00 UTC) instead of now, so the same frames give the same bytes; libxlsxwriter
// also stamps the zip entries with it.
constexpr std::time_t kCreated = 1725494400;

// A write that failed for want of room. libxlsxwriter does not check its writes to its own
// temporary files (the sheets' rows, before they are zipped): a full disk or a file size limit
// there leaves a truncated sheet in a workbook it reports as written. The failed write leaves
// its errno behind, and no library call resets errno, so this is checked after the close.
bool out_of_room(int err) { return err == ENOSPC || err == EFBIG || err == EDQUOT || err == EIO; }

WorkbookPtr new_workbook(const AtomicFile& out, const WorkbookOptions& opt, bool row_by_row = false) {
    errno = 0;  // see out_of_room
    lxw_workbook_options options{};
    options.constant_memory = row_by_row ? LXW_TRUE : LXW_FALSE;
    WorkbookPtr wb(workbook_new_opt(out.temp_path().c_str(), &options), WorkbookCloser{opt.mute_library_stderr});
    if (!wb) throw out.write_error("libxlsxwriter cannot start a workbook");
    lxw_doc_properties properties{};
    properties.created = kCreated;
    if (workbook_set_properties(wb.get(), &properties) != LXW_NO_ERROR)
        throw out.write_error("libxlsxwriter cannot set the workbook's properties");
    return wb;
}

lxw_worksheet* add_sheet(lxw_workbook* wb, const char* name) {
    lxw_worksheet* ws = workbook_add_worksheet(wb, name);
    if (!ws) throw SolverError(fmt::format("libxlsxwriter cannot add the sheet '{}'", name));
    return ws;
}

void close_workbook(WorkbookPtr wb, const AtomicFile& out) {
    const int before = errno;
    const bool mute = wb.get_deleter().mute;
    lxw_error err;
    {
        const std::unique_lock<std::mutex> turn = one_close_at_a_time();
        const StderrMuted quiet(mute);
        err = workbook_close(wb.release());
    }
    if (out_of_room(before)) throw out.write_error(std::strerror(before));  // a sheet's rows were cut short
    const int sys = errno;
    // The system's reason ("No space left on device") says more than libxlsxwriter's own.
    if (err != LXW_NO_ERROR) throw out.write_error(sys != 0 ? std::string(std::strerror(sys)) : lxw_strerror(err));
    if (out_of_room(sys)) throw out.write_error(std::strerror(sys));
}

// Every cell write is checked: libxlsxwriter refuses a cell out of the sheet's range (a 16,385th
// column) or a string it cannot store, and says so only in its return value.
void put(lxw_error err, const AtomicFile& out, lxw_row_t row, lxw_col_t col) {
    if (err != LXW_NO_ERROR)
        throw out.write_error(fmt::format("libxlsxwriter cannot write the cell at row {}, column {}: {}", row + 1, col + 1,
                                          lxw_strerror(err)));
}

}  // namespace

void write_result_xlsx(const std::vector<Frame>& frames, const std::string& path, const WorkbookOptions& options) {
    AtomicFile out(path);
    write_result_xlsx(frames, out, options);
    out.commit();
}

void write_result2_xlsx(const Frame& frame, const std::string& path, const WorkbookOptions& options) {
    AtomicFile out(path);
    write_result2_xlsx(frame, out, options);
    out.commit();
}

void write_result_xlsx(const std::vector<Frame>& frames, AtomicFile& out, const WorkbookOptions& options) {
    // Streamed row by row (libxlsxwriter's constant-memory mode): each row goes to disk as it
    // is finished, which is what this layout needs anyway, and it is several times faster
    // than keeping the whole table of cells in memory.
    // A worksheet holds 16,384 columns: the labels' and one per frame.
    if (frames.size() > kMaxWorkbookFrames)
        throw InputError(Key::frame_count, std::to_string(frames.size()),
                         fmt::format("a worksheet holds at most {} frames (one column each)", kMaxWorkbookFrames));
    WorkbookPtr wb = new_workbook(out, options, true);
    lxw_worksheet* pos = add_sheet(wb.get(), "位置");
    lxw_worksheet* vel = add_sheet(wb.get(), "速度");
    const int n = frames.empty() ? 0 : static_cast<int>(frames.front().handles.size());
    for (size_t k = 0; k < frames.size(); ++k) {
        const auto col = static_cast<lxw_col_t>(k + 1);
        const std::string header = time_header(frames[k].time);
        put(worksheet_write_string(pos, 0, col, header.c_str(), nullptr), out, 0, col);
        put(worksheet_write_string(vel, 0, col, header.c_str(), nullptr), out, 0, col);
    }
    for (int i = 0; i < n; ++i) {
        const std::string label = handle_label(i, n);
        const auto x_row = static_cast<lxw_row_t>(1 + 2 * i), y_row = static_cast<lxw_row_t>(2 + 2 * i);
        const auto v_row = static_cast<lxw_row_t>(1 + i);
        put(worksheet_write_string(pos, x_row, 0, (label + "x (m)").c_str(), nullptr), out, x_row, 0);
        for (size_t k = 0; k < frames.size(); ++k)
            put(worksheet_write_number(pos, x_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].pos.x()), nullptr), out, x_row, static_cast<lxw_col_t>(k + 1));
        put(worksheet_write_string(pos, y_row, 0, (label + "y (m)").c_str(), nullptr), out, y_row, 0);
        for (size_t k = 0; k < frames.size(); ++k)
            put(worksheet_write_number(pos, y_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].pos.y()), nullptr), out, y_row, static_cast<lxw_col_t>(k + 1));
        // The template has two spaces before "(m/s)" for body and tail rows, one for the head
        // and the tail's rear handle.
        const bool one_space = (i == 0 || i == n - 1);
        put(worksheet_write_string(vel, v_row, 0, (label + (one_space ? " (m/s)" : "  (m/s)")).c_str(), nullptr), out, v_row, 0);
        for (size_t k = 0; k < frames.size(); ++k)
            put(worksheet_write_number(vel, v_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].speed), nullptr), out, v_row, static_cast<lxw_col_t>(k + 1));
    }
    close_workbook(std::move(wb), out);
}

void write_result2_xlsx(const Frame& frame, AtomicFile& out, const WorkbookOptions& options) {
    WorkbookPtr wb = new_workbook(out, options);
    lxw_worksheet* ws = add_sheet(wb.get(), "Sheet1");
    put(worksheet_write_string(ws, 0, 1, "横坐标x (m)", nullptr), out, 0, 1);
    put(worksheet_write_string(ws, 0, 2, "纵坐标y (m)", nullptr), out, 0, 2);
    put(worksheet_write_string(ws, 0, 3, "速度 (m/s)", nullptr), out, 0, 3);
    const int n = static_cast<int>(frame.handles.size());
    for (int i = 0; i < n; ++i) {
        const Handle& h = frame.handles[static_cast<size_t>(i)];
        const auto row = static_cast<lxw_row_t>(1 + i);
        put(worksheet_write_string(ws, row, 0, handle_label(i, n).c_str(), nullptr), out, row, 0);
        put(worksheet_write_number(ws, row, 1, round6(h.pos.x()), nullptr), out, row, 1);
        put(worksheet_write_number(ws, row, 2, round6(h.pos.y()), nullptr), out, row, 2);
        put(worksheet_write_number(ws, row, 3, round6(h.speed), nullptr), out, row, 3);
    }
    close_workbook(std::move(wb), out);
}

}  // namespace dragon
