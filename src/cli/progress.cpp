#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

namespace dragon::cli {

namespace {
constexpr auto kFirstDraw = std::chrono::milliseconds(500);  // quick work shows no line at all
constexpr auto kRedraw = std::chrono::milliseconds(100);     // ten redraws a second at most
constexpr int kBarWidth = 24;
}  // namespace

std::string progress_text(const std::string& unit, std::int64_t done, std::int64_t total, double elapsed) {
    done = std::clamp<std::int64_t>(done, 0, std::max<std::int64_t>(total, 0));
    const int filled = total > 0 ? static_cast<int>(kBarWidth * done / total) : 0;
    std::string text = fmt::format("[{}{}] {}/{} {}", std::string(static_cast<size_t>(filled), '#'),
                                   std::string(static_cast<size_t>(kBarWidth - filled), '.'), done, total, unit);
    if (done > 0 && elapsed > 0.0) {
        const double rate = static_cast<double>(done) / elapsed;
        const auto left = static_cast<long long>(static_cast<double>(total - done) / rate + 0.5);
        // "2345/s", "3.1/s", "0.05/s": whole numbers once there are some, never "2.3e+03".
        const std::string per_second = rate >= 100.0 ? fmt::format("{:.0f}", rate) : fmt::format("{:.3g}", rate);
        text += fmt::format("  {}/s  {}:{:02d} left", per_second, left / 60, static_cast<int>(left % 60));
    }
    return text;
}

ProgressLine::ProgressLine(std::string unit, bool quiet)
    : unit_(std::move(unit)), enabled_(!quiet && ::isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() {
    const std::lock_guard<std::mutex> hold(lock_);
    erase();
}

void ProgressLine::update(std::int64_t done, std::int64_t total) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    const std::lock_guard<std::mutex> hold(lock_);
    if (now - start_ < kFirstDraw || (drawn_ && now - last_ < kRedraw)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // \r and "erase to the end of the line": the new text over the old, whatever their lengths.
    std::fputs(fmt::format("\r{}\x1b[K", progress_text(unit_, done, total, elapsed)).c_str(), stderr);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressLine::print_above(const std::string& line) {
    const std::lock_guard<std::mutex> hold(lock_);
    erase();
    std::fputs((line + "\n").c_str(), stderr);
}

void ProgressLine::erase() {
    if (!drawn_) return;
    std::fputs("\r\x1b[K", stderr);  // stdio, not fmt: never throws (this runs in a destructor)
    std::fflush(stderr);
    drawn_ = false;
}

}  // namespace dragon::cli
