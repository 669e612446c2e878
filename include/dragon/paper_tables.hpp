// The contest's tables for a paper: Q1's and Q4's handles at the moments the problem names
// (positions, then speeds), Q2's handles at the first contact, and the answers of Q2-Q5, each
// as a LaTeX table (booktabs rules, siunitx S columns aligned on the decimal point, a caption
// and a label), a pandoc Markdown table, or CSV. The numbers are the workbooks' (6 decimals,
// rounded as format_fixed rounds); the headers are in English or in Chinese (the workbooks'
// own words: 龙头x (m), 第1节龙身 (m/s), 横坐标x (m)).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dragon/chain.hpp"
#include "dragon/contest.hpp"
#include "dragon/language.hpp"

namespace dragon {

// The forms a table is written in.
enum class TableFormat { latex, markdown, csv };
// "latex", "markdown" (or "md") or "csv"; throws InputError (field "table format") otherwise.
TableFormat parse_table_format(std::string_view name);
// ".tex", ".md", ".csv".
std::string table_extension(TableFormat format);

// A table as data: a caption, a label (LaTeX's \label, "tab:dragon-q1-positions"), the header
// and the rows. The first column holds the rows' names; the others numbers as they print
// (a cell that is not a number, "--", is set as text).
struct PaperTable {
    std::string id;       // the file name's stem: "q1_positions", "answers"
    std::string caption;  // a sentence, no final full stop
    std::string label;    // "tab:dragon-q1-positions"
    std::vector<std::string> header;               // the column headings, first the rows' labels'
    std::vector<std::vector<std::string>> rows;    // each row's cells, as many as the header
};

// The handles the paper-style tables show: 0, 1, 51, 101, 151, 201 and the tail's rear handle
// (those of them a shorter chain has).
std::vector<int> paper_handles(int handle_count);

// Rows x and y of each paper handle, one column per frame ("0 s", "60 s").
PaperTable positions_table(const std::vector<Frame>& frames, Language language);
// A row of speeds for each paper handle, one column per frame.
PaperTable speeds_table(const std::vector<Frame>& frames, Language language);
// One frame: a row per paper handle with x, y and speed (result2.xlsx's columns).
PaperTable frame_table(const Frame& frame, Language language);

// The frames of a contest table the paper shows: every `every_travel` metres of head travel
// from its first frame (Q1: 60 m, 0..300 s at 1 m/s; Q4: 50 m, -100..100 s).
std::vector<Frame> every_travel(const std::vector<Frame>& frames, double head_speed, double every_travel);

// Every table of the questions answered: q1_positions, q1_speeds, q2_contact, q4_positions,
// q4_speeds and answers (Q2's time, Q3's pitch, Q4's S-curve, Q5's speed), in that order,
// each present when its question was asked (q2_contact with no rows when no benches touch).
std::vector<PaperTable> contest_tables(const ContestAnswers& answers, Language language);

// The table as a whole file in `format`: LaTeX a `table` float (needs booktabs and siunitx;
// xeCJK or ctex for Chinese), Markdown a pipe table with pandoc's "Table: caption", CSV the
// header and the rows. Ends with a newline.
std::string format_table(const PaperTable& table, TableFormat format);

}  // namespace dragon
