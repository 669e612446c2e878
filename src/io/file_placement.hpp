// Putting finished files in place: where a target really is (through a symbolic link), whether
// it may be replaced, the mode the new file gets, and renaming several files all or none.
// AtomicFile, RowLog and RunOutputs share it.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace dragon::placement {

// Where a file written to `target` goes: the target itself, or the file its symbolic link (or
// chain of them) points to, so that the link stays a link. Throws InputError naming the target:
// a link to nothing, a folder, something not a regular file (a FIFO, a device), or a file
// that is read-only (no write permission bit at all, or none for this user: as cp would fail;
// root too is refused a file whose mode has no write bit, though the system would let it).
std::string resolve_target(const std::string& target);

// One file to put in place: `source` (a finished temporary file, or a sweep's rows) renamed to
// `place`. The mode: the replaced file's (never wider: the group loses what others lack when
// the old group cannot be kept), else `new_mode` (what the umask leaves of 0666).
struct Placement {
    std::string source, place;
    std::string target;  // as the user named it, for messages
    mode_t new_mode = 0644;
    bool keep_source = false;  // a sweep's rows: left where they are if the placing fails, and
                               // the folder made durable once they are in place
};

// Gives `source` the mode (and, where the system allows, the owner and group) that `place`'s
// file has now, or `new_mode` if there is none there.
void apply_mode(const Placement& p);

// Puts every file in place, or none: old files are kept under a second name (a hard link) until
// all renames have succeeded, and put back if one fails (the sources that were moved go back
// too). Throws FileError naming the target that failed, "...; no file was changed".
void place_all(const std::vector<Placement>& files);

// A hidden name beside `path` (in its folder, with its extension, unique in this process):
// ".result1.tmp1234-0.xlsx" for kind "tmp".
std::string hidden_name(const std::string& path, const char* kind);

// Makes the entry of `path` in its folder durable (fsync of the folder): after a file is made or
// renamed there. A folder that cannot be opened for reading is left as it is.
void sync_folder_of(const std::string& path);

}  // namespace dragon::placement
