#!/usr/bin/env bash
# The core component reads and writes no file and asks nothing of the process (the io component
# does that), so it builds for WebAssembly or a board with no file system: none of the symbols its
# library leaves for others to define is a call on files, folders or the environment.
#   core-touches-no-file.sh CORE_LIBRARY [IO_LIBRARY]
# IO_LIBRARY, when given, is the check's own check: the io library must be caught by it (the
# list below matches what file code really calls), or this script fails as well.
set -euo pipefail
core=$1
io=${2:-}

# The calls refused, by their names as `nm -C` prints them: the C library's file, folder and
# environment calls (with their 64-bit and glibc-internal spellings) and C++'s file system and
# file streams.
refused='^(open|openat|creat|fopen|freopen|rename|renameat|unlink|unlinkat|mkdir|mkdirat|rmdir|fsync|fdatasync|stat|lstat|fstat|fstatat|statx|access|getenv|secure_getenv|setenv|unsetenv|putenv)(64)?$|^__(f|l)?xstat(at)?(64)?$|std::filesystem::|std::(__cxx11::)?basic_(i|o)?fstream|std::(__cxx11::)?basic_filebuf'

undefined() { nm -C --undefined-only "$1" | sed -n 's/^ *U //p' | sort -u; }

found=$(undefined "$core" | grep -E "$refused" || true)
if [[ -n $found ]]; then
  echo "core-touches-no-file: $core calls on files or the environment (they belong in the io component):" >&2
  echo "$found" >&2
  exit 1
fi
echo "core-touches-no-file: $core: no file, folder or environment call among its $(undefined "$core" | wc -l) undefined symbols"
if [[ -n $io ]]; then
  caught=$(undefined "$io" | grep -E "$refused" || true)
  if [[ -z $caught ]]; then
    echo "core-touches-no-file: the check caught nothing in $io, whose code opens, renames and syncs files: it checks nothing" >&2
    exit 1
  fi
  echo "core-touches-no-file: the same check catches $(wc -l <<<"$caught") such calls in $io"
fi
