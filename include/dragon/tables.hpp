// Tables of frames: long-form CSV and JSON, and the contest's own workbooks (result1/2/4.xlsx).
// Every writer is all-or-nothing (temporary file, then rename).
#pragma once

#include <cstdio>
#include <cstddef>
#include <string>
#include <vector>

#include "dragon/chain.hpp"
#include "dragon/decimals.hpp"

namespace dragon {

class AtomicFile;
class RunOutputs;  // dragon/atomic_file.hpp: every file below is one of its run's outputs, if given

// The contest's row label of a handle (0..N): 龙头, 第k节龙身, 龙尾, 龙尾（后）.
std::string handle_label(int handle, int handle_count);
// A time to at most `digits` decimals (0..17) as a table with that many decimals prints it:
// rounded as format_fixed rounds, trailing zeros dropped ("300", "0.1", "12.821187").
std::string format_time(double t, int digits);
// A time header as the contest writes it: "0 s", "-100 s", "0.5 s".
std::string time_header(double t);
// Throws InputError (Key::step) when two successive frames' times would read alike in a table
// (a step finer than the times it prints: format_time(t, digits), or time_header in a workbook,
// `workbook`), naming the decimals that would tell them apart, so that no table has two rows or
// columns labelled with one moment.
void require_distinct_times(const std::vector<Frame>& frames, int digits, bool workbook);

// Decimals of the CSV and JSON tables: 6 by default (the contest's), at most 17 (every bit of a
// double of 0.1 or more, for a reader who wants the value itself; smaller values keep 17
// decimals, fewer significant digits).
inline constexpr int kDefaultDigits = 6;
inline constexpr int kMaxDigits = 17;
// v with `digits` decimals (0..17) as the tables print it, never "-0.000": by round6's rule
// (v * 10^digits to the nearest integer, halves away from zero) while that product is below
// 2^52, so that 6 digits print what the workbooks hold; beyond, v's exact decimal expansion.
std::string format_fixed(double v, int digits);

// Long form, header t,handle,x,y,speed; one row per handle per frame; `digits` decimals for
// every number (the time's trailing zeros dropped: format_time(t, digits)).
void write_csv(const std::vector<Frame>& frames, const std::string& path, int digits = kDefaultDigits,
               RunOutputs* outputs = nullptr);
// The same CSV on an open stream (stdout, say); throws std::runtime_error if it cannot be written.
void print_csv(const std::vector<Frame>& frames, std::FILE* out, int digits = kDefaultDigits);
// {"handles": N, "frames": [{"t", "x": [...], "y": [...], "speed": [...]}]}, `digits` decimals
// as write_csv.
void write_json(const std::vector<Frame>& frames, const std::string& path, int digits = kDefaultDigits,
                RunOutputs* outputs = nullptr);
// How a workbook is written (by the library's own xlsx writer on zlib: it prints nothing, shares
// nothing between workbooks and touches nothing of the process). compression_level is zlib's:
// 0 stores the parts, 1 (the default) is the fastest, 9 the smallest. Level 1 because deflating
// is most of a workbook's cost: measured on dragon solve's result1.xlsx and result4.xlsx
// together, 0.12 s of CPU at level 1 (1.62 + 1.14 MB) against 0.27 s at zlib's default level 6
// (1.36 + 0.97 MB, a sixth smaller) and 0.08 s stored (6.5 + 4.4 MB).
struct WorkbookOptions {
    int compression_level = 1;  // 0..9; anything else is an InputError
};

// The most frames one worksheet holds: 16,384 columns, one for the labels.
inline constexpr std::size_t kMaxWorkbookFrames = 16383;
// result1.xlsx / result4.xlsx layout: sheets 位置 and 速度, one column per frame (at most
// kMaxWorkbookFrames; InputError beyond).
void write_result_xlsx(const std::vector<Frame>& frames, const std::string& path, const WorkbookOptions& options = {},
                       RunOutputs* outputs = nullptr);
// result2.xlsx layout: Sheet1, one row per handle with x, y and speed.
void write_result2_xlsx(const Frame& frame, const std::string& path, const WorkbookOptions& options = {},
                        RunOutputs* outputs = nullptr);
// The two workbooks into an AtomicFile the caller commits: several files made all new or all
// old together (see commit_together). Workbooks hold 6 decimals, as the contest's templates,
// and are the same bytes for the same frames (their creation time is fixed).
void write_result_xlsx(const std::vector<Frame>& frames, AtomicFile& out, const WorkbookOptions& options = {});
void write_result2_xlsx(const Frame& frame, AtomicFile& out, const WorkbookOptions& options = {});
// Picks CSV, JSON or XLSX by the extension; throws InputError for any other. `digits` is for
// CSV and JSON.
void write_table(const std::vector<Frame>& frames, const std::string& path, int digits = kDefaultDigits,
                 const WorkbookOptions& workbook = {}, RunOutputs* outputs = nullptr);



}  // namespace dragon
