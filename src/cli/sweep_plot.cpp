#include "sweep_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wording.hpp"

namespace dragon::cli {

namespace {

std::vector<std::size_t> plotted_axes(const SweepSetup& setup) {
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < setup.grid.axes().size(); ++k)
        if (setup.grid.axes()[k].values.size() > 1) out.push_back(k);
    return out;
}

// Which of a measure's jams mean its value is not the whole answer, in words for the legend.
std::string jam_meaning(const MeasureInfo& m, Language language) {
    const bool zh = language == Language::zh;
    if (std::string(m.name) == "collide") return zh ? "板凳龙的运动结束前无碰撞" : "no contact before the dragon's motion ends";
    return zh ? "中途截止：板凳龙无法沿 S 形曲线前进" : "cut short: the dragon cannot follow the S-curve";
}

// The Chinese names of the quantities a map shows: each varied value by its flag's name, each
// measure by its command's.
const char* chinese_quantity(const std::string& name) {
    static const std::pair<const char*, const char*> names[] = {
        {"pitch", "螺距"},           {"speed", "龙头速度"},         {"bench-count", "板凳节数"},
        {"head-length", "龙头板长"}, {"body-length", "龙身板长"},   {"width", "板宽"},
        {"hole-offset", "把手孔距板端"}, {"start-turn", "起始圈数"}, {"turn-radius", "调头空间半径"},
        {"turn-pitch", "调头路径螺距"}, {"arc-ratio", "圆弧半径比 r₁/r₂"},
        {"collide", "首次碰撞时间"}, {"min-pitch", "最小螺距"},     {"turnaround", "最小间隙"},
        {"max-speed", "龙头最大速度"},
    };
    for (const auto& [key, zh] : names)
        if (name == key) return zh;
    return nullptr;
}

std::string quantity_in(Language language, const std::string& name, const std::string& english) {
    const char* zh = language == Language::zh ? chinese_quantity(name) : nullptr;
    return zh ? zh : english;
}

// Whether a row's status says this measure found the chain overlapping where it starts: a
// collision, not a refusal (min-pitch calls such a pitch "collides" too).
bool collides_at_start(const std::string& status, const MeasureInfo& m) {
    return status.find(overlap_note_prefix(m)) != std::string::npos;
}

// The value of `values` that is `v` up to the rounding of a sweep's values (12 significant
// digits), if any: where the contest's dragon lies on an axis, if it lies on one.
std::optional<double> on_axis(const std::vector<double>& values, double v) {
    for (double a : values)
        if (std::abs(a - v) <= 1e-11 * std::max(1.0, std::abs(v))) return a;
    return std::nullopt;
}

// The fixed values that are not the contest's, for the map's note.
std::string fixed_note(const SweepSetup& setup, const std::vector<std::size_t>& plotted, Language language) {
    const Scenario contest;
    std::vector<std::string> differ;
    for (const SweepParameter& p : sweep_parameters()) {
        if (!(setup.fixed & p.value) || get_parameter(setup.base, p) == get_parameter(contest, p)) continue;
        differ.push_back(fmt::format("{} {}{}", quantity_in(language, p.name, p.name), get_parameter(setup.base, p),
                                     *p.unit ? std::string(" ") + p.unit : ""));
    }
    for (std::size_t k = 0; k < setup.grid.axes().size(); ++k) {
        const Axis& a = setup.grid.axes()[k];
        if (std::find(plotted.begin(), plotted.end(), k) == plotted.end())
            differ.push_back(fmt::format("{} {}{}", quantity_in(language, a.parameter->name, a.parameter->name), a.cells[0],
                                         *a.parameter->unit ? std::string(" ") + a.parameter->unit : ""));
    }
    if (language == Language::zh)
        return fmt::format("{}。共 {} 个情形。",
                           differ.empty() ? "其余取值同竞赛题" : fmt::format("固定：{}；其余同竞赛题", fmt::join(differ, "，")),
                           setup.grid.size());
    const std::string fixed = differ.empty() ? "Everything else as in the contest"
                                             : fmt::format("Fixed: {}; the rest as in the contest", fmt::join(differ, ", "));
    return fmt::format("{}. {}.", fixed, count_of(static_cast<long long>(setup.grid.size()), "scenario"));
}

}  // namespace

void check_plot(const SweepSetup& setup, const std::string& path) {
    require_map_format(path);
    const std::size_t n = plotted_axes(setup).size();
    if (n == 0 || n > 2)
        throw InputError(fmt::format("--plot {} is not allowed: a map shows one varied value (line plots) or two (heat "
                                     "maps), and this sweep varies {} (a value given one value is fixed)", path,
                                     n == 0 ? "none" : fmt::format("{}", n)));
}

MapCollector::MapCollector(const SweepSetup& setup) : setup_(setup), plotted_(plotted_axes(setup)), header_(header(setup)) {
    std::size_t cells = 1;
    for (std::size_t k : plotted_) cells *= setup.grid.axes()[k].values.size();
    values_.assign(setup.measures.size(), std::vector<double>(cells, NAN));
    cells_.assign(setup.measures.size(), std::vector<MapCell>(cells, MapCell::missing));
}

void MapCollector::add(const std::string& csv_row) {
    const std::vector<std::string> fields = split_csv(csv_row);
    if (fields.size() != header_.size()) return;  // not a row of this sweep: the readers refuse it first
    const std::size_t naxes = setup_.grid.axes().size();
    const std::optional<std::size_t> index =
        setup_.grid.index_of(std::vector<std::string>(fields.begin(), fields.begin() + static_cast<long>(naxes)));
    if (!index) return;
    const std::vector<std::size_t> pos = setup_.grid.position(*index);
    std::size_t cell = 0;
    for (std::size_t k : plotted_) cell = cell * setup_.grid.axes()[k].values.size() + pos[k];
    std::size_t column = naxes;
    for (std::size_t m = 0; m < setup_.measures.size(); ++m) {
        const MeasureInfo& info = *setup_.measures[m];
        const auto at = [&](const std::string& key) -> const std::string& {
            const auto it = std::find(info.columns.begin(), info.columns.end(), key);
            return fields[column + static_cast<std::size_t>(it - info.columns.begin())];
        };
        const bool answered = std::any_of(fields.begin() + static_cast<long>(column),
                                          fields.begin() + static_cast<long>(column + info.columns.size()),
                                          [](const std::string& f) { return !f.empty(); });
        const std::string& value = at(info.key);
        const auto has = [&](const std::string& key) {
            return std::find(info.columns.begin(), info.columns.end(), key) != info.columns.end();
        };
        MapCell state = MapCell::value;
        if (!answered) state = collides_at_start(fields.back(), info) ? MapCell::overlapping : MapCell::refused;
        else if (info.jam_cuts_answer && !at("jam.time").empty()) state = MapCell::jam;
        else if (value.empty() && has("below_range") && at("below_range") == "true") state = MapCell::below_range;
        else if (value.empty() && has("above_range") && at("above_range") == "true") state = MapCell::above_range;
        else if (value.empty()) state = MapCell::no_value;
        cells_[m][cell] = state;
        values_[m][cell] = state == MapCell::value ? std::strtod(value.c_str(), nullptr) : NAN;
        column += info.columns.size();
    }
}

SweepMap MapCollector::map(Language language) const {
    SweepMap map;
    map.language = language;
    if (language == Language::zh) map.mark_label = "竞赛题的板凳龙";
    const Scenario contest;
    // The contest's dragon is marked where every value the measures read but the plotted ones is
    // the contest's.
    ScenarioValues plotted_values = 0;
    for (std::size_t k : plotted_) plotted_values |= setup_.grid.axes()[k].parameter->value;
    bool contest_map = true;
    for (const SweepParameter& p : sweep_parameters()) {
        if (plotted_values & p.value) continue;
        if (setup_.fixed & p.value) contest_map = contest_map && get_parameter(setup_.base, p) == get_parameter(contest, p);
    }
    for (std::size_t k = 0; k < setup_.grid.axes().size(); ++k) {
        const Axis& a = setup_.grid.axes()[k];
        if (std::find(plotted_.begin(), plotted_.end(), k) == plotted_.end())
            contest_map = contest_map && a.values[0] == get_parameter(contest, *a.parameter);
    }
    // ...and each plotted axis holds the contest's value: the dragon is marked on its own
    // scenario, never between the grid's values.
    for (std::size_t k : plotted_) {
        const Axis& a = setup_.grid.axes()[k];
        contest_map = contest_map && on_axis(a.values, get_parameter(contest, *a.parameter));
    }
    const auto axis = [&](std::size_t k) {
        const Axis& a = setup_.grid.axes()[k];
        MapAxis m{quantity_in(language, a.parameter->name, a.parameter->quantity), a.parameter->unit, a.values, std::nullopt};
        if (contest_map) m.mark = on_axis(a.values, get_parameter(contest, *a.parameter));
        return m;
    };
    map.x = axis(plotted_.at(0));
    if (plotted_.size() > 1) map.y = axis(plotted_[1]);
    map.note = fixed_note(setup_, plotted_, language);
    for (std::size_t m = 0; m < setup_.measures.size(); ++m) {
        const MeasureInfo& info = *setup_.measures[m];
        MapPanel panel{quantity_in(language, info.name, info.quantity), info.unit, values_[m], cells_[m],
                       jam_meaning(info, language)};
        if (std::string(info.name) == "min-pitch" && language == Language::zh) {
            panel.below_label = "最小螺距不高于搜索范围（--lo）";
            panel.above_label = "最小螺距（若存在）高于搜索范围（--hi）";
        } else if (language == Language::zh) {
            panel.below_label = "答案低于搜索范围";
            panel.above_label = "答案高于搜索范围";
        } else if (std::string(info.name) == "min-pitch") {
            panel.below_label = "minimum pitch at or below the range searched (--lo)";
            panel.above_label = "minimum pitch, if any, above the range searched (--hi)";
        }
        map.panels.push_back(std::move(panel));
    }
    return map;
}

}  // namespace dragon::cli
