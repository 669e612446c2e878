// Checking a row read back from a sweep's file (dragon/sweep_row_check.hpp).
#include "dragon/sweep_row_check.hpp"

#include <fmt/format.h>

#include "dragon/input_file.hpp"

namespace dragon {

namespace {

// Cells a sweep writes as compact JSON (numbers, lists, objects, booleans) start so; text cells
// (a jam's kind, a guarantee, the status) start with a letter.
bool looks_like_json(const std::string& cell) {
    const char c = cell.front();
    return c == '-' || c == '[' || c == '{' || (c >= '0' && c <= '9') || cell == "true" || cell == "false";
}

bool noted(const std::string& status, const std::string& kind, const char* measure) {
    return status.find(fmt::format("{} ({}): ", kind, measure)) != std::string::npos;
}

}  // namespace

RowFileLimits row_limits(const SweepSetup& setup, const std::string& what) {
    RowFileLimits limits;
    limits.what = what;
    limits.row_bytes = header(setup).size() * (kMaxCellBytes + 3);  // a quoted cell and its comma
    return limits;
}

RowCheck check_row(const SweepSetup& setup, const std::string& line) {
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if (c < 0x20 || c == 0x7f)
            return {std::nullopt, fmt::format("it holds a control character ({}) at byte {}",
                                              shown_text(std::string(1, line[i])), i + 1)};
    }
    std::vector<std::string> cells;
    try {
        cells = split_csv(line);
    } catch (const InputError&) {
        return {std::nullopt, "it has an unclosed quote"};
    }
    const std::vector<std::string> columns = header(setup);
    if (cells.size() != columns.size())
        return {std::nullopt, fmt::format("it has {} cell{}, and a row of this sweep has {}", cells.size(),
                                          cells.size() == 1 ? "" : "s", columns.size())};
    const std::size_t naxes = setup.grid.axes().size();
    const std::optional<std::size_t> index =
        setup.grid.index_of(std::vector<std::string>(cells.begin(), cells.begin() + static_cast<long>(naxes)));
    if (!index) return {std::nullopt, "its varied values are no scenario of this sweep"};
    if (!setup.shard.holds(*index))
        return {std::nullopt, fmt::format("its scenario is not in this sweep's part {}/{}", setup.shard.index,
                                          setup.shard.count)};
    for (std::size_t k = 0; k < cells.size(); ++k)
        if (cells[k].size() > kMaxCellBytes)
            return {std::nullopt, fmt::format("its {} cell has {} characters, more than a sweep writes ({})",
                                              columns[k], cells[k].size(), kMaxCellBytes)};
    const std::string& status = cells.back();
    std::size_t column = naxes;
    bool any_note = false, failed = false;
    for (const MeasureInfo* m : setup.measures) {
        bool answered = false;
        for (std::size_t k = 0; k < m->columns.size(); ++k, ++column) {
            const std::string& cell = cells[column];
            if (cell.empty()) continue;
            answered = true;
            if (looks_like_json(cell) && !Json::accept(cell))
                return {std::nullopt, fmt::format("its {} cell '{}' does not read as the number, list or object a "
                                                  "sweep writes", columns[column], shown_text(cell, 40))};
        }
        failed = failed || noted(status, "failed", m->name);
        const bool refused = noted(status, "refused", m->name) || noted(status, "failed", m->name);
        any_note = any_note || refused || noted(status, "jam", m->name);
        if (!answered && !refused)
            return {std::nullopt, fmt::format("its {} cells are empty, and its status does not say {} was refused or "
                                              "failed", m->name, m->name)};
        if (answered && refused)
            return {std::nullopt, fmt::format("its status says {} was refused or failed, and its {} cells hold an "
                                              "answer", m->name, m->name)};
    }
    if (status != "ok" && !any_note)
        return {std::nullopt, fmt::format("its status '{}' is neither ok nor a measure's note (\"jam (NAME): ...\", "
                                          "\"refused (NAME): ...\", \"failed (NAME): ...\")", shown_text(status, 40))};
    return {index, "", failed};
}

}  // namespace dragon
