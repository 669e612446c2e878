// A progress line on stderr for commands that can run for seconds (min-pitch, turnaround,
// figures, video): a bar, done of total, the rate and the time left. Drawn only when stderr is
// a terminal (a log file would fill with redraws) and not with --quiet; redrawn at most ten
// times a second, and not at all before half a second has passed, so quick runs show nothing.
// The line is erased when the work ends, leaving the terminal as the answers expect it.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace dragon::cli {

// The text of one redraw: "[#####.........] 12/40 pitches  3.1/s  0:09 left".
std::string progress_text(const std::string& unit, std::int64_t done, std::int64_t total, double elapsed);

class ProgressLine {
public:
    // `unit` names what is counted ("frames", "pitches"). Draws nothing if `quiet` or if
    // stderr is not a terminal.
    ProgressLine(std::string unit, bool quiet);
    ~ProgressLine();  // erases the line if it is drawn
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // `done` of `total` so far; safe to call from several threads at once.
    void update(std::int64_t done, std::int64_t total);
    // A status line above the progress line (erased first, redrawn by the next update).
    void print_above(const std::string& line);

private:
    void erase();  // with lock_ held

    std::string unit_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, last_;
    std::mutex lock_;
};

}  // namespace dragon::cli
