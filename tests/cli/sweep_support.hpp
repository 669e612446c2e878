// Reading a sweep's CSV in the tests, on their own (a CSV reader and a flattener of --json
// answers of their own, not the program's), to compare its rows with the single commands.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace sweep_test {

// RFC 4180 fields of one line.
inline std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
        else if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (std::size_t end; (end = text.find('\n', from)) != std::string::npos; from = end + 1)
        out.push_back(text.substr(from, end - from));
    return out;
}

// A sweep file: its spec line, header and rows (each a map from column to cell).
struct Table {
    std::string spec;
    std::vector<std::string> header;
    std::vector<std::string> raw;  // the rows as written
    std::vector<std::map<std::string, std::string>> rows;
};
inline Table read_table(const std::string& text) {
    Table t;
    const std::vector<std::string> ls = lines(text);
    if (ls.size() < 2) return t;
    t.spec = ls[0];
    t.header = fields(ls[1]);
    for (std::size_t k = 2; k < ls.size(); ++k) {
        t.raw.push_back(ls[k]);
        const std::vector<std::string> f = fields(ls[k]);
        std::map<std::string, std::string> row;
        for (std::size_t c = 0; c < f.size() && c < t.header.size(); ++c) row[t.header[c]] = f[c];
        t.rows.push_back(row);
    }
    return t;
}
inline std::multiset<std::string> row_set(const Table& t) { return {t.raw.begin(), t.raw.end()}; }

// An answer flattened as the README says a sweep writes it: objects' keys joined by dots,
// anything else one cell (text as it is, null as nothing, the rest compact JSON).
inline void flatten(const nlohmann::ordered_json& v, const std::string& key, std::map<std::string, std::string>& out) {
    if (v.is_object() && !v.empty()) {
        for (const auto& [k, item] : v.items()) flatten(item, key.empty() ? k : key + "." + k, out);
        return;
    }
    out[key] = v.is_null() ? "" : v.is_string() ? v.get<std::string>() : v.dump();
}

}  // namespace sweep_test
