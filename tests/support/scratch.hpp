// A scratch folder of the test that is running, its own (and a file read whole): ctest runs tests in parallel, one
// process each, so folders shared between tests would race (one test's output counted as
// another's stray file).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace dragon_test {

inline std::filesystem::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
    for (char& c : name)
        if (c == '/') c = '_';  // parameterised names are Prefix/Suite.Name/Index
    const auto dir = std::filesystem::path(DRAGON_TEST_TMP) / name;
    std::filesystem::create_directories(dir);
    return dir;
}

// A folder `name` inside the test's scratch folder, made empty.
inline std::filesystem::path fresh_dir(const std::string& name) {
    const std::filesystem::path d = scratch_dir() / name;
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

// A file's whole contents, bytes as they are ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

}  // namespace dragon_test
