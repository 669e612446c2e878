// A minimal xlsx (Office Open XML spreadsheet) writer: a workbook of sheets of cells, strings
// and numbers, packed by zip::ZipWriter. Enough for the contest's workbooks and nothing more:
// no styles beyond the default, no formulas, no dates.
//
// Cells go into a sheet row by row, left to right (each after the one before it), as they are
// written to the sheet's XML at once. Strings go to the workbook's shared strings table, each
// distinct string once; numbers are written as the shortest decimal that reads back as the same
// double (Excel, LibreOffice and openpyxl read exactly the double given); a NaN or an infinity,
// which a cell cannot hold, is the error #NUM!. The parts are fixed but for the cells and the
// sheet names, and the document's creation time is the contest's opening (2024-09-05T00:00:00Z):
// the same cells give the same bytes. No state is shared between workbooks.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace dragon::xlsx {

inline constexpr std::uint32_t kMaxRows = 1048576;  // a worksheet's rows and columns (Excel's)
inline constexpr std::uint32_t kMaxColumns = 16384;
inline constexpr const char* kCreated = "2024-09-05T00:00:00Z";

// "A1" for (0, 0); column letters as Excel names them (Z, AA, ..., XFD).
std::string cell_name(std::uint32_t row, std::uint32_t col);

class Workbook;

class Sheet {
public:
    // Throw std::out_of_range for a cell past the sheet's size, std::invalid_argument for a cell
    // not after the last one written or a string that is not valid UTF-8 or holds a character
    // XML cannot (a control character other than tab, line feed and carriage return).
    void write_string(std::uint32_t row, std::uint32_t col, std::string_view text);
    void write_number(std::uint32_t row, std::uint32_t col, double value);

    const std::string& name() const { return name_; }

private:
    friend class Workbook;
    Sheet(std::string name, Workbook& book) : name_(std::move(name)), book_(&book) {}
    void check_cell(std::uint32_t row, std::uint32_t col) const;  // throws unless the cell may come next
    void open_cell(std::uint32_t row, std::uint32_t col);
    std::string head() const;  // the XML before the rows (with the sheet's dimension)
    std::string_view tail() const;

    std::string name_;
    Workbook* book_;
    std::string rows_;  // <row>...</row> elements
    bool any_ = false, row_open_ = false;
    std::uint32_t row_ = 0, col_ = 0;  // the last cell written
    std::uint32_t min_row_ = 0, min_col_ = 0, max_row_ = 0, max_col_ = 0;  // the dimension
};

class Workbook {
public:
    Workbook() = default;
    Workbook(const Workbook&) = delete;
    Workbook& operator=(const Workbook&) = delete;

    // A new sheet after the others. Its name as Excel allows: 1..31 characters, none of
    // []:*?/\, not starting or ending with ', unique regardless of case (ASCII); else
    // std::invalid_argument. The reference stays valid as long as the workbook.
    Sheet& add_sheet(std::string_view name);

    // The workbook packed at zlib's `level` (0 stored, 1 fastest .. 9 smallest): into the file at
    // `path` (zip::ZipError when a write fails, with the system's errno), or into memory.
    void save(const std::string& path, int level) const;
    std::string bytes(int level) const;

private:
    friend class Sheet;
    std::uint32_t string_index(std::string_view text);
    template <class Zip>
    void pack(Zip& zip, int level) const;

    std::vector<std::unique_ptr<Sheet>> sheets_;
    std::unordered_map<std::string, std::uint32_t> string_ids_;
    std::string strings_;  // <si> elements, in order of first use
    std::uint64_t string_uses_ = 0;
};

}  // namespace dragon::xlsx
