// Tables of frames: long-form CSV and JSON, and the contest's own workbooks (result1/2/4.xlsx).
// Every writer is all-or-nothing (temporary file, then rename).
#pragma once

#include <string>
#include <vector>

#include "dragon/chain.hpp"

namespace dragon {

// The contest's row label of a handle (0..N): 龙头, 第k节龙身, 龙尾, 龙尾（后）.
std::string handle_label(int handle, int handle_count);
// A time without binary noise: "300", "-100", "0.1", "412.4738".
std::string format_time(double t);
// A time header as the contest writes it: "0 s", "-100 s", "0.5 s".
std::string time_header(double t);

// Long form, header t,handle,x,y,speed; one row per handle per frame; 6 decimals.
void write_csv(const std::vector<Frame>& frames, const std::string& path);
// {"times": [...], "handles": N, "frames": [{"t", "x": [...], "y": [...], "speed": [...]}]}
void write_json(const std::vector<Frame>& frames, const std::string& path);
// result1.xlsx / result4.xlsx layout: sheets 位置 and 速度, one column per frame.
void write_result_xlsx(const std::vector<Frame>& frames, const std::string& path);
// result2.xlsx layout: Sheet1, one row per handle with x, y and speed.
void write_result2_xlsx(const Frame& frame, const std::string& path);
// Picks CSV, JSON or XLSX by the extension; throws InputError for any other.
void write_table(const std::vector<Frame>& frames, const std::string& path);

// Rounds to 6 decimals the way the tables print, without a negative zero.
double round6(double v);

}  // namespace dragon
