// The contest's workbooks (result1/2/4.xlsx), cell for cell as in its templates.
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"
#include "xlsx_writer.hpp"
#include "zip_writer.hpp"

namespace dragon {

namespace {

int checked_level(const WorkbookOptions& options) {
    if (options.compression_level < 0 || options.compression_level > 9)
        throw InputError(Key::compression_level, std::to_string(options.compression_level),
                         "0 (stored) to 9 (smallest), zlib's levels");
    return options.compression_level;
}

// The workbook into the AtomicFile's temporary file. A failed write (a full disk, a file size
// limit) is the one error "cannot write '<target>': <the system's reason>"; nothing is printed.
void save(const xlsx::Workbook& book, const AtomicFile& out, int level) {
    try {
        book.save(out.temp_path(), level);
    } catch (const zip::ZipError& e) {
        throw out.write_error(e.sys_errno() != 0 ? std::string(std::strerror(e.sys_errno())) : std::string(e.what()));
    }
}

}  // namespace

void write_result_xlsx(const std::vector<Frame>& frames, const std::string& path, const WorkbookOptions& options,
                       RunOutputs* outputs) {
    AtomicFile out(path, outputs);
    write_result_xlsx(frames, out, options);
    out.commit();
}

void write_result2_xlsx(const Frame& frame, const std::string& path, const WorkbookOptions& options,
                        RunOutputs* outputs) {
    AtomicFile out(path, outputs);
    write_result2_xlsx(frame, out, options);
    out.commit();
}

void write_result_xlsx(const std::vector<Frame>& frames, AtomicFile& out, const WorkbookOptions& options) {
    // A worksheet holds 16,384 columns: the labels' and one per frame.
    if (frames.size() > kMaxWorkbookFrames)
        throw InputError(Key::frame_count, std::to_string(frames.size()),
                         fmt::format("a worksheet holds at most {} frames (one column each)", kMaxWorkbookFrames));
    const int level = checked_level(options);
    xlsx::Workbook book;
    xlsx::Sheet& pos = book.add_sheet("位置");
    xlsx::Sheet& vel = book.add_sheet("速度");
    const auto n = static_cast<std::uint32_t>(frames.empty() ? 0 : frames.front().handles.size());
    const auto columns = static_cast<std::uint32_t>(frames.size());
    for (std::uint32_t k = 0; k < columns; ++k) {
        const std::string header = time_header(frames[k].time);
        pos.write_string(0, k + 1, header);
        vel.write_string(0, k + 1, header);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::string label = handle_label(static_cast<int>(i), static_cast<int>(n));
        pos.write_string(1 + 2 * i, 0, label + "x (m)");
        for (std::uint32_t k = 0; k < columns; ++k) pos.write_number(1 + 2 * i, k + 1, round6(frames[k].handles[i].pos.x()));
        pos.write_string(2 + 2 * i, 0, label + "y (m)");
        for (std::uint32_t k = 0; k < columns; ++k) pos.write_number(2 + 2 * i, k + 1, round6(frames[k].handles[i].pos.y()));
        // The template has two spaces before "(m/s)" for body and tail rows, one for the head
        // and the tail's rear handle.
        const bool one_space = (i == 0 || i == n - 1);
        vel.write_string(1 + i, 0, label + (one_space ? " (m/s)" : "  (m/s)"));
        for (std::uint32_t k = 0; k < columns; ++k) vel.write_number(1 + i, k + 1, round6(frames[k].handles[i].speed));
    }
    save(book, out, level);
}

void write_result2_xlsx(const Frame& frame, AtomicFile& out, const WorkbookOptions& options) {
    const int level = checked_level(options);
    xlsx::Workbook book;
    xlsx::Sheet& ws = book.add_sheet("Sheet1");
    ws.write_string(0, 1, "横坐标x (m)");
    ws.write_string(0, 2, "纵坐标y (m)");
    ws.write_string(0, 3, "速度 (m/s)");
    const auto n = static_cast<std::uint32_t>(frame.handles.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        const Handle& h = frame.handles[i];
        ws.write_string(1 + i, 0, handle_label(static_cast<int>(i), static_cast<int>(n)));
        ws.write_number(1 + i, 1, round6(h.pos.x()));
        ws.write_number(1 + i, 2, round6(h.pos.y()));
        ws.write_number(1 + i, 3, round6(h.speed));
    }
    save(book, out, level);
}

}  // namespace dragon
