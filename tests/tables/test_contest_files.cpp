// The contest's files in a folder (dragon/contest_files.hpp), as the tool's solve and Python's
// solve(out=) both write them: the targets of the questions asked, none in place before the
// answers are, all together after; a target in the way fails before any work.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "dragon/contest_files.hpp"
#include "support/scratch.hpp"

namespace dragon {
namespace {

namespace fs = std::filesystem;

TEST(ContestFiles, TheQuestionsAskedTheirFilesAllTogether) {
    const fs::path dir = dragon_test::scratch_dir() / "out" / "q2";
    fs::remove_all(dir.parent_path());  // a run before this one's files, and the folder it made
    ContestOptions asked;
    asked.questions = {Question::q2};
    ContestFiles files(dir.string(), asked, TableFormat::markdown);
    EXPECT_EQ(files.names(), (std::vector<std::string>{"result2.xlsx", "summary.json", "table_q2_contact.md",
                                                       "table_answers.md"}));
    files.attach(asked);
    EXPECT_FALSE(asked.on_q1_table);  // no Q1 asked: no workbook of it
    const ContestAnswers answers = solve_contest(Scenario{}, asked);
    for (const std::string& name : files.names()) EXPECT_FALSE(fs::exists(dir / name)) << name;
    files.finish(answers, "{}\n");
    for (const std::string& name : files.names()) EXPECT_GT(fs::file_size(dir / name), 0u) << name;
    EXPECT_EQ(dragon_test::slurp(dir / "summary.json"), "{}\n");
    EXPECT_NE(dragon_test::slurp(dir / "table_q2_contact.md").find("412.47"), std::string::npos);
}

TEST(ContestFiles, ATargetInTheWayFailsBeforeAnyWork) {
    const fs::path dir = dragon_test::scratch_dir() / "blocked";
    fs::remove_all(dir);
    fs::create_directories(dir / "summary.json");  // a folder where the summary goes
    ContestOptions asked;
    EXPECT_THROW(ContestFiles(dir.string(), asked), InputError);
    for (const char* name : {"result1.xlsx", "result2.xlsx", "result4.xlsx"}) EXPECT_FALSE(fs::exists(dir / name)) << name;
    const fs::path file = dragon_test::scratch_dir() / "a-file";
    std::ofstream(file) << "x";
    try {
        ContestFiles(file.string() + "/sub", asked);
        ADD_FAILURE() << "a folder under a file was made";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), Key::out);
    }
}

}  // namespace
}  // namespace dragon
