// The contest's files in one folder, as `dragon solve -o DIR` and Python's solve(out=DIR) both
// write them: result1.xlsx (Q1), result2.xlsx (Q2), result4.xlsx (Q4), summary.json, and with a
// table format the paper's tables (table_q1_positions.tex, ...). Every target is checked and its
// temporary file made before any work, so a bad folder or name fails with nothing touched; the
// long workbooks are written as soon as their tables are ready (hooked into ContestOptions);
// the rest when the answers are, and the set is put in place together: all new or all as it was.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dragon/atomic_file.hpp"
#include "dragon/contest.hpp"
#include "dragon/language.hpp"
#include "dragon/paper_tables.hpp"
#include "dragon/tables.hpp"

namespace dragon {

// The targets of one contest run in one folder, checked at construction and put in place
// together by finish(); see the file's head for what each holds.
class ContestFiles {
public:
    // Makes `dir` (and its parents) if missing, and the temporary file of each target for the
    // questions `asked` asks; throws InputError (Key::out) for a folder that cannot be made,
    // and as AtomicFile does for a target in the way. The files are outputs of `outputs`' run.
    ContestFiles(const std::string& dir, const ContestOptions& asked, std::optional<TableFormat> tables = {},
                 Language language = Language::en, WorkbookOptions workbook = {}, RunOutputs* outputs = nullptr);
    ContestFiles(const ContestFiles&) = delete;
    ContestFiles& operator=(const ContestFiles&) = delete;

    // Hooks the Q1 and Q4 workbooks into `options` (on_q1_table, on_q4_table), so that each is
    // written while the other questions are answered.
    void attach(ContestOptions& options) const;
    // Writes result2.xlsx (with no contact: the layout with no rows, so that no older answer is
    // left looking like this one's), `summary_json` and the tables, then puts every file in
    // place together (commit_together). Throws FileError naming the file that failed.
    void finish(const ContestAnswers& answers, const std::string& summary_json);
    // The files' names, in the order they are written ("result1.xlsx", ..., "summary.json", ...).
    const std::vector<std::string>& names() const { return names_; }

private:
    AtomicFile* add(const std::string& dir, const std::string& name, RunOutputs* outputs);
    std::vector<std::unique_ptr<AtomicFile>> files_;
    std::vector<std::string> names_;
    AtomicFile *result1_ = nullptr, *result2_ = nullptr, *result4_ = nullptr, *summary_ = nullptr;
    std::vector<std::pair<std::string, AtomicFile*>> tables_;  // a paper table's id, its file
    std::optional<TableFormat> format_;
    Language language_;
    WorkbookOptions workbook_;
};

}  // namespace dragon
