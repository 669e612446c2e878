#!/usr/bin/env bash
# Writes docs/cli.md from the tool's own help: `bash scripts/cli-docs.sh > docs/cli.md`.
# tests/cli/test_cli_docs.cpp checks that every block below is what the tool prints now.
set -euo pipefail
cd "$(dirname "$0")/.."
dragon=${1:-build/src/dragon}
commands=(simulate solve collide min-pitch turnaround max-speed render figures video film sweep)
cat <<'HEAD'
# The `dragon` command line

Generated from the tool's own help by `bash scripts/cli-docs.sh > docs/cli.md`; a test keeps
each block equal to what `dragon COMMAND --help` prints. The README's quick start and the other
documents say what the commands are for; this is every option of each.

HEAD
echo '## `dragon`'
echo
echo '```text'
"$dragon" --help
echo '```'
for c in "${commands[@]}"; do
    echo
    echo "## \`dragon $c\`"
    echo
    echo '```text'
    "$dragon" "$c" --help
    echo '```'
done
echo
echo '## `dragon sweep merge`'
echo
echo '```text'
"$dragon" sweep merge --help
echo '```'
echo
echo '## Keys'
echo
echo 'Every value a user can set, from the library'"'"'s one description (`include/dragon/keys.hpp`):'
echo 'flags and the web page'"'"'s URL spell a name with hyphens, TOML files and Python with'
echo 'underscores (the name below; a scenario file'"'"'s old sections `[dragon]`, `[path]`, `[motion]` are'
echo 'read with a warning, see usage.md); "-" under flag: the library'"'"'s and Python'"'"'s only.'
echo '`dragon keys --json` prints the same as JSON.'
echo
echo '```text'
"$dragon" keys
echo '```'
