// Paper-style summary tables on stdout, and how the CLI prints answers and numbers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dragon/analyses.hpp"
#include "dragon/answers.hpp"
#include "dragon/json.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

// The tool's workbooks: the library's defaults (zlib level 1, see WorkbookOptions).
inline constexpr WorkbookOptions kWorkbooks{};

// The handles the paper-style tables show: 0, 1, 51, 101, 151, 201 and the tail's rear handle
// (those that exist for a shorter chain).
std::vector<int> summary_handles(int handle_count);
std::string handle_name(int handle, int handle_count);

// Rows x and y for each summary handle, then its speed, one column per frame.
void print_frame_table(const std::string& title, const std::vector<const Frame*>& frames);
// One frame: a row per summary handle with x, y and speed.
void print_single_frame(const std::string& title, const Frame& frame);


// --digits: the decimals of CSV and JSON tables, kDefaultDigits if not given; throws InputError
// outside 0..kMaxDigits.
int checked_digits(const std::optional<int>& digits);

// A quantity for the text answers: `decimals` decimals in the usual range (1.246266; at 6
// decimals from 0.001 up to 1e9), else as many significant digits as they show at 1
// (6.231332e-10, 6.231332e+307): never hundreds of digits, never 0.000000 for a value that is
// not zero.
std::string format_amount(double v, int decimals = 6);

// A --json answer: one object, keys in the order written, printed on one line.
void print_json(const Json& answer);
// Where the end of the valid motion cut a window: "  {what} starts there: the dragon can follow
// its path only from ...\n" and the same for its end, or "" when neither did.
std::string window_cuts(const Searched& w, const std::string& what);

}  // namespace dragon::cli
