// The tool's gmtime(): the C library's answer, in a result of each calling thread's own
// (gmtime_r) instead of one static struct all threads share. It takes the C library's place for
// the whole process (the executable's definition comes first), which only an application may
// decide: the library's workbooks, which libxlsxwriter stamps through gmtime() as it closes
// them, then close in parallel instead of one at a time (tables/workbooks.cpp sees it and drops
// its lock). Built into the executable itself, not the tool's library, so that nothing else
// that links the pieces of the tool (the tests) gets it unasked.
#include <ctime>

extern "C" std::tm* gmtime(const std::time_t* t) noexcept {
    thread_local std::tm result{};
    return gmtime_r(t, &result);
}
