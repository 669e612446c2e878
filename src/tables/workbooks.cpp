// The contest's workbooks (result1/2/4.xlsx), cell for cell as in its templates.
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <xlsxwriter.h>

#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"

namespace dragon {

namespace {

struct WorkbookCloser {
    void operator()(lxw_workbook* wb) const { workbook_close(wb); }
};
using WorkbookPtr = std::unique_ptr<lxw_workbook, WorkbookCloser>;

WorkbookPtr new_workbook(const std::string& path, bool row_by_row = false) {
    lxw_workbook_options options{};
    options.constant_memory = row_by_row ? LXW_TRUE : LXW_FALSE;
    WorkbookPtr wb(workbook_new_opt(path.c_str(), &options));
    if (!wb) throw std::runtime_error(fmt::format("cannot create workbook '{}'", path));
    return wb;
}

lxw_worksheet* add_sheet(lxw_workbook* wb, const char* name) {
    lxw_worksheet* ws = workbook_add_worksheet(wb, name);
    if (!ws) throw std::runtime_error(fmt::format("cannot add sheet '{}'", name));
    return ws;
}

void close_workbook(WorkbookPtr wb, const std::string& target) {
    const lxw_error err = workbook_close(wb.release());
    if (err != LXW_NO_ERROR)
        throw std::runtime_error(fmt::format("cannot write '{}': {}", target, lxw_strerror(err)));
}

}  // namespace

void write_result_xlsx(const std::vector<Frame>& frames, const std::string& path) {
    AtomicFile out(path);
    // Streamed row by row (libxlsxwriter's constant-memory mode): each row goes to disk as it
    // is finished, which is what this layout needs anyway, and it is several times faster
    // than keeping the whole table of cells in memory.
    WorkbookPtr wb = new_workbook(out.temp_path(), true);
    lxw_worksheet* pos = add_sheet(wb.get(), "位置");
    lxw_worksheet* vel = add_sheet(wb.get(), "速度");
    const int n = frames.empty() ? 0 : static_cast<int>(frames.front().handles.size());
    for (size_t k = 0; k < frames.size(); ++k) {
        const auto col = static_cast<lxw_col_t>(k + 1);
        const std::string header = time_header(frames[k].time);
        worksheet_write_string(pos, 0, col, header.c_str(), nullptr);
        worksheet_write_string(vel, 0, col, header.c_str(), nullptr);
    }
    for (int i = 0; i < n; ++i) {
        const std::string label = handle_label(i, n);
        const auto x_row = static_cast<lxw_row_t>(1 + 2 * i), y_row = static_cast<lxw_row_t>(2 + 2 * i);
        const auto v_row = static_cast<lxw_row_t>(1 + i);
        worksheet_write_string(pos, x_row, 0, (label + "x (m)").c_str(), nullptr);
        for (size_t k = 0; k < frames.size(); ++k)
            worksheet_write_number(pos, x_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].pos.x), nullptr);
        worksheet_write_string(pos, y_row, 0, (label + "y (m)").c_str(), nullptr);
        for (size_t k = 0; k < frames.size(); ++k)
            worksheet_write_number(pos, y_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].pos.y), nullptr);
        // The template has two spaces before "(m/s)" for body and tail rows, one for the head
        // and the tail's rear handle.
        const bool one_space = (i == 0 || i == n - 1);
        worksheet_write_string(vel, v_row, 0, (label + (one_space ? " (m/s)" : "  (m/s)")).c_str(), nullptr);
        for (size_t k = 0; k < frames.size(); ++k)
            worksheet_write_number(vel, v_row, static_cast<lxw_col_t>(k + 1),
                                   round6(frames[k].handles[static_cast<size_t>(i)].speed), nullptr);
    }
    close_workbook(std::move(wb), path);
    out.commit();
}

void write_result2_xlsx(const Frame& frame, const std::string& path) {
    AtomicFile out(path);
    WorkbookPtr wb = new_workbook(out.temp_path());
    lxw_worksheet* ws = add_sheet(wb.get(), "Sheet1");
    worksheet_write_string(ws, 0, 1, "横坐标x (m)", nullptr);
    worksheet_write_string(ws, 0, 2, "纵坐标y (m)", nullptr);
    worksheet_write_string(ws, 0, 3, "速度 (m/s)", nullptr);
    const int n = static_cast<int>(frame.handles.size());
    for (int i = 0; i < n; ++i) {
        const Handle& h = frame.handles[static_cast<size_t>(i)];
        const auto row = static_cast<lxw_row_t>(1 + i);
        worksheet_write_string(ws, row, 0, handle_label(i, n).c_str(), nullptr);
        worksheet_write_number(ws, row, 1, round6(h.pos.x), nullptr);
        worksheet_write_number(ws, row, 2, round6(h.pos.y), nullptr);
        worksheet_write_number(ws, row, 3, round6(h.speed), nullptr);
    }
    close_workbook(std::move(wb), path);
    out.commit();
}

}  // namespace dragon
