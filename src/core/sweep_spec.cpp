// A sweep's grid: the parameters it can vary, the axes parsed from their specs, the shards and
// the enumeration of the scenarios.
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

#include "dragon/shown_text.hpp"
#include "dragon/sweep.hpp"
#include "scenario_number.hpp"

namespace dragon {

const std::vector<SweepParameter>& sweep_parameters() {
    static const std::vector<SweepParameter> params = {
        {"pitch", value::pitch, false, "pitch", "m"},
        {"speed", value::head_speed, false, "head speed", "m/s"},
        {"bench-count", value::bench_count, true, "benches", ""},
        {"head-length", value::head_length, false, "head board length", "m"},
        {"body-length", value::body_length, false, "body board length", "m"},
        {"width", value::width, false, "bench width", "m"},
        {"hole-offset", value::hole_offset, false, "hole offset", "m"},
        {"start-turn", value::start_turn, false, "start turn", ""},
        {"turn-radius", value::turn_radius, false, "turning-space radius", "m"},
        {"turn-pitch", value::turn_pitch, false, "turnaround pitch", "m"},
        {"arc-ratio", value::arc_ratio, false, "arc radius ratio r\u2081/r\u2082", ""},
    };
    return params;
}

const SweepParameter* find_sweep_parameter(std::string_view name) {
    for (const SweepParameter& p : sweep_parameters())
        if (name == p.name) return &p;
    return nullptr;
}

namespace {

std::string parameter_names() {
    std::string out;
    for (const SweepParameter& p : sweep_parameters()) out += (out.empty() ? "" : ", ") + std::string(p.name);
    return out;
}

// A finite number that is the whole of `text`, or nullopt.
std::optional<double> number(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v) || errno == ERANGE) return std::nullopt;
    return v;
}

// 12 significant digits: a range's values as a person would write them (0.21, not
// 0.21000000000000002); a range so narrow that two of them round together is refused.
double rounded(double v) { return std::strtod(fmt::format("{:.12g}", v).c_str(), nullptr); }

// Checks the axis's values and makes their cells. `spec` names it in messages.
Axis finish_axis(const SweepParameter& p, std::vector<double> values, const std::string& spec) {
    if (values.size() > kMaxAxisValues)
        throw InputError(Key::vary, shown_text(spec), fmt::format("it gives {} values, at most {}", values.size(),
                                     kMaxAxisValues));
    Axis a{&p, {}, {}};
    std::set<double> seen;
    for (double v : values) {
        if (v == 0.0) v = 0.0;  // -0 and 0 are one value, written "0"
        if (p.whole && (v != std::floor(v) || std::abs(v) > INT_MAX))
            throw InputError(Key::vary, shown_text(spec), fmt::format("{} takes whole numbers, and {} is not one", p.name, v));
        if (!seen.insert(v).second)
            throw InputError(Key::vary, shown_text(spec), fmt::format("it gives {} twice (each scenario once)", v));
        a.values.push_back(v);
        a.cells.push_back(fmt::format("{}", v));
    }
    return a;
}

}  // namespace

void set_parameter(Scenario& s, const SweepParameter& p, double v) {
    if (p.value == value::bench_count) {
        // Checked before the narrowing: 2^31 would become a negative int.
        if (!(v >= 1.0 && v <= kMaxBenchCount)) refuse_bench_count(error_value(v));
        s.bench.bench_count = static_cast<int>(v);
    }
    else *scenario_number(s, p.value) = v;
}

double get_parameter(const Scenario& s, const SweepParameter& p) {
    if (p.value == value::bench_count) return s.bench.bench_count;
    Scenario copy = s;
    return *scenario_number(copy, p.value);
}

Axis parse_axis(const std::string& spec) {
    const std::size_t eq = spec.find('=');
    if (eq == std::string::npos)
        throw InputError(Key::vary, shown_text(spec), "give NAME=FROM:TO:COUNT or NAME=V1,V2,... "
                                     "(width=0.20:0.40:21, speed=0.5,1,2)");
    const std::string name = spec.substr(0, eq), values = spec.substr(eq + 1);
    const SweepParameter* p = find_sweep_parameter(name);
    if (!p)
        throw InputError(Key::vary, shown_text(spec), fmt::format("{} is not a value a sweep can vary; use {}", name.empty() ? "''" : shown_text(name), parameter_names()));
    if (values.find(':') != std::string::npos) {
        // FROM:TO:COUNT
        std::vector<std::string> parts;
        for (std::size_t from = 0;;) {
            const std::size_t colon = values.find(':', from);
            parts.push_back(values.substr(from, colon - from));
            if (colon == std::string::npos) break;
            from = colon + 1;
        }
        const std::optional<double> lo = parts.size() == 3 ? number(parts[0]) : std::nullopt;
        const std::optional<double> hi = parts.size() == 3 ? number(parts[1]) : std::nullopt;
        const std::optional<double> count = parts.size() == 3 ? number(parts[2]) : std::nullopt;
        if (!lo || !hi || !count)
            throw InputError(Key::vary, shown_text(spec), "a range is FROM:TO:COUNT, three finite numbers "
                                         "(width=0.20:0.40:21 is 21 values from 0.20 to 0.40)");
        if (*count != std::floor(*count) || *count < 1 || *count > static_cast<double>(kMaxAxisValues))
            throw InputError(Key::vary, shown_text(spec), fmt::format("the count {} must be a whole number from 1 to {}", shown_text(parts[2]), kMaxAxisValues));
        const auto n = static_cast<std::size_t>(*count);
        if (n == 1 && *lo != *hi)
            throw InputError(Key::vary, shown_text(spec), fmt::format("one value cannot run from {} to {}; give a "
                                         "count of at least 2, or the one value", shown_text(parts[0]), shown_text(parts[1])));
        std::vector<double> v(n);
        for (std::size_t k = 0; k < n; ++k)
            v[k] = k + 1 == n ? *hi : rounded(*lo + (*hi - *lo) * static_cast<double>(k) / static_cast<double>(n - 1));
        return finish_axis(*p, std::move(v), spec);
    }
    std::vector<double> v;
    for (std::size_t from = 0;;) {
        const std::size_t comma = values.find(',', from);
        const std::string item = values.substr(from, comma - from);
        const std::optional<double> x = number(item);
        if (!x)
            throw InputError(Key::vary, shown_text(spec), fmt::format("'{}' is not a finite number (a list is "
                                         "V1,V2,..., a range FROM:TO:COUNT)", shown_text(item)));
        v.push_back(*x);
        if (comma == std::string::npos) break;
        from = comma + 1;
    }
    return finish_axis(*p, std::move(v), spec);
}

Axis axis_from_cells(const std::string& name, const std::vector<std::string>& cells) {
    std::string list;
    for (const std::string& c : cells) list += (list.empty() ? "" : ",") + c;
    Axis a = parse_axis(name + "=" + list);
    if (a.cells != cells)
        throw InputError(fmt::format("the values of {} are not written as a sweep writes them: {}", name, shown_text(list)));
    return a;
}

Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    const auto whole = [](const std::string& t) -> std::optional<std::size_t> {
        if (t.empty() || t.size() > 9 || !std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return std::nullopt;
        return static_cast<std::size_t>(std::stoul(t));
    };
    const std::optional<std::size_t> k = slash == std::string::npos ? std::nullopt : whole(text.substr(0, slash));
    const std::optional<std::size_t> n = slash == std::string::npos ? std::nullopt : whole(text.substr(slash + 1));
    if (!k || !n || *n < 1 || *k < 1 || *k > *n)
        throw InputError(Key::shard, text, "give K/N, the K-th of N parts, 1 <= K <= N (2/8)");
    return {*k, *n};
}

SweepGrid::SweepGrid(std::vector<Axis> axes) : axes_(std::move(axes)) {
    if (axes_.empty()) throw InputError("a sweep needs at least one varied value (NAME=VALUES)");
    ScenarioValues seen = 0;
    for (const Axis& a : axes_) {
        if (seen & a.parameter->value)
            throw InputError(fmt::format("{} is varied twice: vary each value once", a.parameter->name));
        seen |= a.parameter->value;
        if (a.values.empty() || size_ * a.values.size() > kMaxSweepScenarios)
            throw InputError(fmt::format("this sweep is not allowed: it has more than {} scenarios", kMaxSweepScenarios));
        size_ *= a.values.size();
        std::unordered_map<std::string, std::size_t>& cell_at = lookup_.emplace_back();
        for (std::size_t k = 0; k < a.cells.size(); ++k) cell_at.emplace(a.cells[k], k);
    }
}

std::vector<std::size_t> SweepGrid::position(std::size_t index) const {
    std::vector<std::size_t> pos(axes_.size());
    for (std::size_t k = axes_.size(); k-- > 0;) {
        pos[k] = index % axes_[k].values.size();
        index /= axes_[k].values.size();
    }
    return pos;
}

Scenario SweepGrid::scenario(Scenario base, std::size_t index) const {
    const std::vector<std::size_t> pos = position(index);
    for (std::size_t k = 0; k < axes_.size(); ++k) set_parameter(base, *axes_[k].parameter, axes_[k].values[pos[k]]);
    return base;
}

std::vector<std::string> SweepGrid::cells(std::size_t index) const {
    const std::vector<std::size_t> pos = position(index);
    std::vector<std::string> out;
    for (std::size_t k = 0; k < axes_.size(); ++k) out.push_back(axes_[k].cells[pos[k]]);
    return out;
}

std::optional<std::size_t> SweepGrid::index_of(const std::vector<std::string>& cells) const {
    if (cells.size() != axes_.size()) return std::nullopt;
    std::size_t index = 0;
    for (std::size_t k = 0; k < axes_.size(); ++k) {
        const auto it = lookup_[k].find(cells[k]);
        if (it == lookup_[k].end()) return std::nullopt;
        index = index * axes_[k].values.size() + it->second;
    }
    return index;
}

ScenarioValues SweepGrid::varied() const {
    ScenarioValues v = 0;
    for (const Axis& a : axes_) v |= a.parameter->value;
    return v;
}

}  // namespace dragon
