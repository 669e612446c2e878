// Paper-style summary tables on stdout, and JSON fragments for --json answers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dragon/analyses.hpp"

namespace dragon::cli {

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

// v with as many decimals as `resolution` (how closely v is known) supports, at most 9: 9 for 1e-10.
std::string format_resolved(double v, double resolution);

// A quantity for the text answers: `decimals` decimals in the usual range (1.246266; at 6
// decimals from 0.001 up to 1e9), else as many significant digits as they show at 1
// (6.231332e-10, 6.231332e+307): never hundreds of digits, never 0.000000 for a value that is
// not zero.
std::string format_amount(double v, int decimals = 6);

// --json answers: one object, keys in the order written, printed on one line.
using Json = nlohmann::ordered_json;
// The value a computed double stands for: rounded to 15 significant digits (0.0025, not
// 0.002500000000000001; 0.979435, not 0.9794349999999999), never -0.
double meant(double v);
// `v` as JSON text with every number the shortest decimal of the value meant, whole numbers
// without ".0" ("times":[0,300]), NaN and infinities as null; on one line, or indented by
// `indent` spaces a level.
std::string json_text(const Json& v, int indent = -1);
void print_json(const Json& answer);
// The end of the valid motion as an answer's "jam" key: {"time", "travel", "handle", "kind",
// "ahead", "point", "tolerance"}, or null. "kind" is what happens as time runs forward; "ahead":
// the motion is valid until the jam (else from it).
Json jam_json(const std::optional<Jam>& j);
// "the dragon can follow its path only until t = 432.917924228 s, where handle 1 can no longer
// follow handle 0: ..." (from instead of until for a jam behind t = 0). Every command words a
// jam with this one sentence.
std::string jam_sentence(const Jam& j);
// Where the end of the valid motion cut a window: "  {what} starts there: the dragon can follow
// its path only from ...\n" and the same for its end, or "" when neither did.
std::string window_cuts(const Searched& w, const std::string& what);
// The window an answer searched, both ways: "from", "to" (s) and "from_travel", "to_travel" (m of
// head travel), added to `answer`.
void add_window(Json& answer, const Searched& w);

}  // namespace dragon::cli
