// The contest's tables for a paper: LaTeX (booktabs, siunitx), pandoc Markdown and CSV.
#include "dragon/paper_tables.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dragon/errors.hpp"
#include "dragon/tables.hpp"

namespace dragon {

TableFormat parse_table_format(std::string_view name) {
    if (name == "latex" || name == "tex") return TableFormat::latex;
    if (name == "markdown" || name == "md") return TableFormat::markdown;
    if (name == "csv") return TableFormat::csv;
    throw InputError(Key::tables, std::string(name), "use latex, markdown or csv");
}

std::string table_extension(TableFormat format) {
    switch (format) {
        case TableFormat::latex: return ".tex";
        case TableFormat::markdown: return ".md";
        case TableFormat::csv: return ".csv";
    }
    return ".csv";
}

std::vector<int> paper_handles(int handle_count) {
    std::vector<int> out;
    if (handle_count <= 0) return out;
    for (int h : {0, 1, 51, 101, 151, 201})
        if (h < handle_count - 1) out.push_back(h);
    out.push_back(handle_count - 1);
    return out;
}

namespace {

// A handle's name: the workbooks' row label in Chinese, the CLI's words in English.
std::string handle_name(int h, int n, Language lang) {
    if (lang == Language::zh) return handle_label(h, n);
    if (h == 0) return "head";
    if (h == n - 1) return "tail (rear)";
    if (h == n - 2) return "tail";
    return fmt::format("body {}", h);
}

std::string number(double v) { return format_fixed(v, kDefaultDigits); }

std::string times_caption(const std::vector<Frame>& frames) {
    if (frames.empty()) return "";
    return fmt::format(" at t = {}", [&] {
        std::string s;
        for (size_t i = 0; i < frames.size(); ++i) s += (i ? ", " : "") + format_time(frames[i].time, kDefaultDigits);
        return s + " s";
    }());
}

std::string zh_times(const std::vector<Frame>& frames) {
    std::string s;
    for (size_t i = 0; i < frames.size(); ++i) s += (i ? "、" : "") + format_time(frames[i].time, kDefaultDigits);
    return frames.empty() ? "" : s + " s 时";
}

std::vector<std::string> time_headers(const std::vector<Frame>& frames, const std::string& first) {
    std::vector<std::string> h{first};
    for (const Frame& f : frames) h.push_back(time_header(f.time));
    return h;
}

}  // namespace

PaperTable positions_table(const std::vector<Frame>& frames, Language lang) {
    PaperTable t;
    t.header = time_headers(frames, "");
    const int n = frames.empty() ? 0 : static_cast<int>(frames.front().handles.size());
    for (int h : paper_handles(n)) {
        for (int axis = 0; axis < 2; ++axis) {
            const char* a = axis == 0 ? "x" : "y";
            std::vector<std::string> row{lang == Language::zh ? fmt::format("{}{} (m)", handle_name(h, n, lang), a)
                                                              : fmt::format("{} {} (m)", handle_name(h, n, lang), a)};
            for (const Frame& f : frames) row.push_back(number(f.handles[static_cast<size_t>(h)].pos[axis]));
            t.rows.push_back(std::move(row));
        }
    }
    t.caption = lang == Language::zh ? "部分把手在" + zh_times(frames) + "的位置"
                                     : "Positions of some handles" + times_caption(frames);
    return t;
}

PaperTable speeds_table(const std::vector<Frame>& frames, Language lang) {
    PaperTable t;
    t.header = time_headers(frames, "");
    const int n = frames.empty() ? 0 : static_cast<int>(frames.front().handles.size());
    for (int h : paper_handles(n)) {
        std::vector<std::string> row{fmt::format("{} (m/s)", handle_name(h, n, lang))};
        for (const Frame& f : frames) row.push_back(number(f.handles[static_cast<size_t>(h)].speed));
        t.rows.push_back(std::move(row));
    }
    t.caption = lang == Language::zh ? "部分把手在" + zh_times(frames) + "的速度"
                                     : "Speeds of some handles" + times_caption(frames);
    return t;
}

PaperTable frame_table(const Frame& frame, Language lang) {
    PaperTable t;
    t.header = lang == Language::zh ? std::vector<std::string>{"", "横坐标x (m)", "纵坐标y (m)", "速度 (m/s)"}
                                    : std::vector<std::string>{"", "x (m)", "y (m)", "speed (m/s)"};
    const int n = static_cast<int>(frame.handles.size());
    for (int h : paper_handles(n)) {
        const Handle& hd = frame.handles[static_cast<size_t>(h)];
        t.rows.push_back({handle_name(h, n, lang), number(hd.pos.x()), number(hd.pos.y()), number(hd.speed)});
    }
    t.caption = lang == Language::zh ? fmt::format("t = {} s 时部分把手的位置和速度", format_time(frame.time, 9))
                                     : fmt::format("Positions and speeds of some handles at t = {} s",
                                                   format_time(frame.time, 9));
    return t;
}

std::vector<Frame> every_travel(const std::vector<Frame>& frames, double head_speed, double travel) {
    // As `dragon solve` prints them: every travel / speed seconds when that is whole, else every
    // `travel` seconds.
    const double every = travel / head_speed == std::round(travel / head_speed) ? travel / head_speed : travel;
    std::vector<Frame> out;
    if (frames.empty()) return out;
    const double first = frames.front().time;
    for (const Frame& f : frames)
        if (std::fmod(f.time - first, every) == 0.0) out.push_back(f);
    return out;
}

std::vector<PaperTable> contest_tables(const ContestAnswers& a, Language lang) {
    const bool zh = lang == Language::zh;
    std::vector<PaperTable> out;
    const auto add = [&](PaperTable t, const char* id, const std::string& prefix) {
        t.id = id;
        std::string label = id;
        std::replace(label.begin(), label.end(), '_', '-');
        t.label = "tab:dragon-" + label;
        if (!prefix.empty() && !t.caption.empty() && t.caption[0] >= 'A' && t.caption[0] <= 'Z')
            t.caption[0] = static_cast<char>(t.caption[0] - 'A' + 'a');  // "Q1, coiling in: positions ..."
        t.caption = prefix + t.caption;
        out.push_back(std::move(t));
    };
    const double v = a.scenario.head_speed;
    if (a.q1) {
        const std::vector<Frame> f = every_travel(a.q1->frames, v, 60.0);
        add(positions_table(f, lang), "q1_positions", zh ? "问题1：盘入时" : "Q1, coiling in: ");
        add(speeds_table(f, lang), "q1_speeds", zh ? "问题1：盘入时" : "Q1, coiling in: ");
    }
    if (a.q2 && !a.q2->contact) {
        // The layout with no rows, as result2.xlsx: no older contact is left looking like this one's.
        PaperTable t = frame_table(Frame{}, lang);
        t.caption = zh ? "问题2：盘入过程中没有板凳相碰" : "Q2: no two benches touch while the dragon coils in";
        add(std::move(t), "q2_contact", "");
    }
    if (a.q2 && a.q2->contact) {
        const Contact& c = *a.q2->contact;
        PaperTable t = frame_table(c.frame, lang);
        t.caption = zh ? fmt::format("问题2：盘入终止时刻 t = {} s（第{}节与第{}节板凳相碰）部分把手的位置和速度",
                                     format_resolved(c.time, c.tolerance), c.bench_a, c.bench_b)
                       : fmt::format("Q2, the end of coiling in: positions and speeds of some handles at t = {} s, "
                                     "when benches {} and {} touch",
                                     format_resolved(c.time, c.tolerance), c.bench_a, c.bench_b);
        add(std::move(t), "q2_contact", "");
    }
    if (a.q4) {
        const std::vector<Frame> f = every_travel(a.q4->frames, v, 50.0);
        add(positions_table(f, lang), "q4_positions", zh ? "问题4：调头前后" : "Q4, around the turn: ");
        add(speeds_table(f, lang), "q4_speeds", zh ? "问题4：调头前后" : "Q4, around the turn: ");
    }
    PaperTable ans;
    ans.header = zh ? std::vector<std::string>{"问题", "结果", "数值", "单位"}
                    : std::vector<std::string>{"Question", "Answer", "Value", "Unit"};
    const auto row = [&](const char* q, const std::string& what, const std::string& value, const char* unit) {
        ans.rows.push_back({q, what, value, unit});
    };
    if (a.q2) {
        if (const std::optional<Contact>& c = a.q2->contact)
            row("Q2", zh ? fmt::format("盘入终止时刻（第{}节与第{}节板凳相碰）", c->bench_a, c->bench_b)
                         : fmt::format("end of coiling in (benches {} and {} touch)", c->bench_a, c->bench_b),
                format_resolved(c->time, c->tolerance), "s");
        else
            row("Q2", zh ? "盘入终止时刻（无碰撞）" : "end of coiling in (no collision)", "--", "s");
    }
    if (a.q3)
        row("Q3", zh ? "最小螺距" : "minimum pitch",
            std::isnan(a.q3->pitch) ? "--" : fmt::format("{:.10f}", a.q3->pitch), "m");
    if (a.q4_design) {
        const SCurve& s = *a.q4_design;
        row("Q4", zh ? "调头曲线第一段圆弧半径" : "turning curve, first arc's radius", number(s.r1), "m");
        row("Q4", zh ? "调头曲线第二段圆弧半径" : "turning curve, second arc's radius", number(s.r2), "m");
        row("Q4", zh ? "调头曲线长度" : "turning curve's length", number(s.length), "m");
    }
    if (a.q5)
        row("Q5", zh ? "龙头最大行进速度" : "largest head speed", a.q5->unbounded ? "--" : number(a.q5->max_head_speed),
            "m/s");
    if (!ans.rows.empty()) {
        ans.caption = zh ? "各问题的结果" : "The answers";
        add(std::move(ans), "answers", "");
    }
    return out;
}

namespace {

// A cell as a number's parts, or not a number: optional minus, digits, optional point and digits.
struct Numeral {
    bool ok = false, negative = false;
    int integer = 0, decimals = 0;
};
Numeral numeral(const std::string& s) {
    Numeral n;
    size_t i = 0;
    if (i < s.size() && s[i] == '-') n.negative = true, ++i;
    const size_t int_start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    n.integer = static_cast<int>(i - int_start);
    if (i < s.size() && s[i] == '.') {
        const size_t d = ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
        n.decimals = static_cast<int>(i - d);
    }
    n.ok = n.integer > 0 && i == s.size();
    return n;
}

// The columns after the first that hold numbers (or "--") in every row.
std::vector<bool> numeric_columns(const PaperTable& t) {
    std::vector<bool> out(t.header.size(), false);
    for (size_t c = 1; c < t.header.size(); ++c) {
        bool any = false, all = true;
        for (const auto& r : t.rows) {
            if (c >= r.size()) continue;
            if (r[c] == "--") continue;
            const bool is = numeral(r[c]).ok;
            any = any || is;
            all = all && is;
        }
        out[c] = any && all;
    }
    return out;
}

std::string latex_escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += '\\'; out += ch; break;
            case '~': out += "\\textasciitilde{}"; break;
            case '^': out += "\\textasciicircum{}"; break;
            case '\\': out += "\\textbackslash{}"; break;
            default: out += ch;
        }
    }
    return out;
}

std::string latex(const PaperTable& t) {
    const std::vector<bool> num = numeric_columns(t);
    std::string spec = "l";
    for (size_t c = 1; c < t.header.size(); ++c) {
        if (!num[c]) {
            spec += "l";
            continue;
        }
        Numeral widest;
        for (const auto& r : t.rows) {
            const Numeral n = numeral(r[c]);
            if (!n.ok) continue;
            widest.negative = widest.negative || n.negative;
            widest.integer = std::max(widest.integer, n.integer);
            widest.decimals = std::max(widest.decimals, n.decimals);
        }
        // Digits ungrouped, as the workbooks and the contest print them (8.800000, not 8.800 000).
        spec += fmt::format("S[table-format={}{}.{},group-digits=false]", widest.negative ? "-" : "", widest.integer,
                            widest.decimals);
    }
    std::string out = fmt::format(
        "% {} (benchdragon): needs \\usepackage{{booktabs,siunitx}}{}\n"
        "\\begin{{table}}[htbp]\n  \\centering\n  \\small\n  \\caption{{{}}}\n  \\label{{{}}}\n"
        "  \\begin{{tabular}}{{{}}}\n    \\toprule\n",
        t.id, "; Chinese: xeCJK or ctex (xelatex)", latex_escape(t.caption), t.label, spec);
    const auto line = [&](const std::vector<std::string>& cells, bool header) {
        out += "    ";
        for (size_t c = 0; c < cells.size(); ++c) {
            if (c) out += " & ";
            const std::string cell = latex_escape(cells[c]);
            // An S column sets numbers; its header and any text in it go in braces.
            out += c < num.size() && num[c] && (header || !numeral(cells[c]).ok) ? "{" + cell + "}" : cell;
        }
        out += " \\\\\n";
    };
    line(t.header, true);
    out += "    \\midrule\n";
    for (const auto& r : t.rows) line(r, false);
    out += "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
    return out;
}

std::string markdown(const PaperTable& t) {
    const std::vector<bool> num = numeric_columns(t);
    const auto escape = [](const std::string& s) {
        std::string o;
        for (char ch : s) o += ch == '|' ? std::string("\\|") : std::string(1, ch);
        return o;
    };
    std::string out = "|";
    for (const std::string& h : t.header) out += " " + escape(h) + " |";
    out += "\n|";
    for (size_t c = 0; c < t.header.size(); ++c) out += num[c] ? "---:|" : ":---|";
    out += "\n";
    for (const auto& r : t.rows) {
        out += "|";
        for (const std::string& cell : r) out += " " + escape(cell) + " |";
        out += "\n";
    }
    out += fmt::format("\nTable: {}\n", t.caption);  // pandoc's caption
    return out;
}

std::string csv(const PaperTable& t) {
    const auto cell = [](const std::string& s) {
        if (s.find_first_of(",\"\n") == std::string::npos) return s;
        std::string o = "\"";
        for (char ch : s) o += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        return o + "\"";
    };
    std::string out;
    const auto line = [&](const std::vector<std::string>& cells) {
        for (size_t c = 0; c < cells.size(); ++c) out += (c ? "," : "") + cell(cells[c]);
        out += "\n";
    };
    line(t.header);
    for (const auto& r : t.rows) line(r);
    return out;
}

}  // namespace

std::string format_table(const PaperTable& table, TableFormat format) {
    switch (format) {
        case TableFormat::latex: return latex(table);
        case TableFormat::markdown: return markdown(table);
        case TableFormat::csv: return csv(table);
    }
    return csv(table);
}

}  // namespace dragon
