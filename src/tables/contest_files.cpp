#include "dragon/contest_files.hpp"

#include <algorithm>
#include <filesystem>

#include "dragon/errors.hpp"

namespace dragon {

AtomicFile* ContestFiles::add(const std::string& dir, const std::string& name, RunOutputs* outputs) {
    files_.push_back(std::make_unique<AtomicFile>((std::filesystem::path(dir) / name).string(), outputs));
    names_.push_back(name);
    return files_.back().get();
}

ContestFiles::ContestFiles(const std::string& dir, const ContestOptions& asked, std::optional<TableFormat> tables,
                           Language language, WorkbookOptions workbook, RunOutputs* outputs)
    : format_(tables), language_(language), workbook_(workbook) {
    if (!make_output_folder(dir, outputs)) throw InputError(Key::out, dir, "the folder cannot be created");
    if (asked.asks(Question::q1)) result1_ = add(dir, "result1.xlsx", outputs);
    if (asked.asks(Question::q2)) result2_ = add(dir, "result2.xlsx", outputs);
    if (asked.asks(Question::q4)) result4_ = add(dir, "result4.xlsx", outputs);
    summary_ = add(dir, "summary.json", outputs);
    if (!format_) return;
    const auto table = [&](bool needed, const std::string& id) {
        if (needed) tables_.emplace_back(id, add(dir, "table_" + id + table_extension(*format_), outputs));
    };
    table(asked.asks(Question::q1), "q1_positions");
    table(asked.asks(Question::q1), "q1_speeds");
    table(asked.asks(Question::q2), "q2_contact");
    table(asked.asks(Question::q4), "q4_positions");
    table(asked.asks(Question::q4), "q4_speeds");
    table(asked.asks(Question::q2) || asked.asks(Question::q3) || asked.asks(Question::q4) || asked.asks(Question::q5),
          "answers");
}

void ContestFiles::attach(ContestOptions& options) const {
    if (result1_)
        options.on_q1_table = [file = result1_, w = workbook_](const std::vector<Frame>& t) { write_result_xlsx(t, *file, w); };
    if (result4_)
        options.on_q4_table = [file = result4_, w = workbook_](const std::vector<Frame>& t) { write_result_xlsx(t, *file, w); };
}

void ContestFiles::finish(const ContestAnswers& answers, const std::string& summary_json) {
    if (result2_) {
        const bool contact = answers.q2 && answers.q2->contact;
        write_result2_xlsx(contact ? answers.q2->contact->frame : Frame{}, *result2_, workbook_);
    }
    write_text_file(*summary_, summary_json);
    if (format_) {
        const std::vector<PaperTable> tables = contest_tables(answers, language_);
        for (auto& [id, file] : tables_) {
            // (The binding captured by name: clang before 16, the fuzzers' compiler, refuses a
            // structured binding captured by a lambda's default capture.)
            const auto t =
                std::find_if(tables.begin(), tables.end(), [&key = id](const PaperTable& p) { return p.id == key; });
            write_text_file(*file, t != tables.end() ? format_table(*t, *format_) : "");
        }
    }
    std::vector<AtomicFile*> set;
    for (const auto& f : files_) set.push_back(f.get());
    commit_together(set);
}

}  // namespace dragon
