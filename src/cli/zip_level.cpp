// The tool's workbooks are deflated at zlib's level 1, not at the default level 6 that
// libxlsxwriter fixes when it adds each part to the zip (through minizip, with no setting of its
// own). Measured on `dragon solve` (scripts/performance.sh): zlib was a third of its CPU. Level 1
// takes 0.13 s of CPU off it, for workbooks about a fifth larger (result1.xlsx 1.4 -> 1.7 MB). The
// cells are the same: only their compression changes. The executable's definition comes first
// for the whole process, which only an application may decide (as gmtime_per_thread.cpp does);
// the library and whatever else links the tool's pieces (the tests, the Python package) keep
// libxlsxwriter's own level. minizip's headers are not a dependency, so its declaration is
// written out here (zip.h, minizip 1.1: zipFile is a pointer, uInt and uLong are unsigned int
// and unsigned long).
#include <dlfcn.h>

namespace {

using ZipOpen = int (*)(void* file, const char* filename, const void* zipfi, const void* extrafield_local,
                        unsigned size_extrafield_local, const void* extrafield_global,
                        unsigned size_extrafield_global, const char* comment, int method, int level, int raw,
                        int window_bits, int mem_level, int strategy, const char* password,
                        unsigned long crc_for_crypting, unsigned long version_made_by, unsigned long flag_base,
                        int zip64);

constexpr int kZipInternalError = -104;  // minizip's ZIP_INTERNALERROR
constexpr int kToolLevel = 1;

}  // namespace

extern "C" int zipOpenNewFileInZip4_64(void* file, const char* filename, const void* zipfi,
                                       const void* extrafield_local, unsigned size_extrafield_local,
                                       const void* extrafield_global, unsigned size_extrafield_global,
                                       const char* comment, int method, int level, int raw, int window_bits,
                                       int mem_level, int strategy, const char* password,
                                       unsigned long crc_for_crypting, unsigned long version_made_by,
                                       unsigned long flag_base, int zip64) {
    static const auto real = reinterpret_cast<ZipOpen>(dlsym(RTLD_NEXT, "zipOpenNewFileInZip4_64"));
    if (!real) return kZipInternalError;  // the workbook then fails with libxlsxwriter's own message
    // Level 0 (stored) stays stored; any compressed part is compressed at level 1.
    return real(file, filename, zipfi, extrafield_local, size_extrafield_local, extrafield_global,
                size_extrafield_global, comment, method, level == 0 ? 0 : kToolLevel, raw, window_bits, mem_level,
                strategy, password, crc_for_crypting, version_made_by, flag_base, zip64);
}
