#!/usr/bin/env bash
# scripts/install-deps.sh on a machine where every package is missing, with apt-get and
# dpkg-query replaced by stand-ins (no root, no network, nothing installed): it says what it does
# in a few lines, keeps apt's output in the log it names, prints the log's end when apt fails,
# and says nothing more than one line when everything is present.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A copy of the script in a checkout of its own, so its log goes to $scratch/build.
mkdir -p "$scratch/scripts" "$scratch/bin"
cp "$root/scripts/install-deps.sh" "$scratch/scripts/"

# dpkg-query: every package installed when $STUB_ALL_PRESENT is set, none otherwise.
cat >"$scratch/bin/dpkg-query" <<'EOF'
#!/bin/sh
[ -n "${STUB_ALL_PRESENT:-}" ] && printf 'install ok installed'
exit 0
EOF
# apt-get: a fresh machine's chatter for each package asked for (and two dependencies each),
# and a failure with its reason at the end when $STUB_FAIL is set.
cat >"$scratch/bin/apt-get" <<'EOF'
#!/bin/sh
echo "apt-get $*" >>"$STUB_CALLS"
[ "$1" = update ] && { echo "Hit:1 http://deb.debian.org/debian bookworm InRelease"; exit 0; }
for p in "$@"; do
  case "$p" in -*|install) continue ;; esac
  for d in "$p" "$p-dep1" "$p-dep2"; do
    echo "Selecting previously unselected package $d."
    echo "Preparing to unpack .../$d.deb ..."
    echo "Unpacking $d ..."
  done
done
if [ -n "${STUB_FAIL:-}" ]; then
  echo "E: Unable to locate package no-such-package" >&2
  exit 100
fi
for p in "$@"; do
  case "$p" in -*|install) continue ;; esac
  for d in "$p" "$p-dep1" "$p-dep2"; do echo "Setting up $d ..."; done
done
EOF
chmod +x "$scratch/bin/"*
export PATH="$scratch/bin:$PATH" STUB_CALLS="$scratch/calls"
log="$scratch/build/install-deps.log"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Everything missing: a few lines, the log named and holding apt's output.
: >"$STUB_CALLS"
out=$(bash "$scratch/scripts/install-deps.sh" 2>&1) || fail "install-deps failed: $out"
echo "$out"
wanted=$(grep -c '^apt-get install' "$STUB_CALLS")
((wanted == 1)) || fail "apt-get install ran $wanted times"
asked=$(grep '^apt-get install' "$STUB_CALLS" | tr ' ' '\n' | grep -vc -e '^-' -e '^apt-get$' -e '^install$')
lines=$(printf '%s\n' "$out" | wc -l)
((lines <= 5)) || fail "$lines lines printed for $asked packages (at most 5 wanted)"
grep -q "Unpacking" <<<"$out" && fail "apt's unpacking is printed"
grep -qF "$log" <<<"$out" || fail "the log $log is not named"
unpacked=$(grep -c '^Unpacking ' "$log")
((unpacked == 3 * asked)) || fail "the log holds $unpacked unpacking lines, not $((3 * asked))"
grep -q "$asked packages, $((3 * asked)) set up" <<<"$out" || fail "the last line does not count what was installed"

# apt fails: a non-zero exit, the failing step and the log's end (the reason) on stderr.
status=0
err=$(STUB_FAIL=1 bash "$scratch/scripts/install-deps.sh" 2>&1 >/dev/null) || status=$?
echo "$err"
((status == 100)) || fail "exit $status when apt-get failed with 100"
grep -q "failed (exit 100)" <<<"$err" || fail "the failure does not say which step failed"
grep -q "Unable to locate package no-such-package" <<<"$err" || fail "the log's end is not shown on failure"
(($(printf '%s\n' "$err" | wc -l) <= 30)) || fail "more than the log's end printed on failure"

# Everything present: one line, apt not run.
: >"$STUB_CALLS"
out=$(STUB_ALL_PRESENT=1 bash "$scratch/scripts/install-deps.sh" run 2>&1)
echo "$out"
[[ $(printf '%s\n' "$out" | wc -l) == 1 && $out == *"packages present"* ]] || fail "not one line when all present: $out"
[[ ! -s $STUB_CALLS ]] || fail "apt-get ran with everything present"
echo "install-deps: OK"
