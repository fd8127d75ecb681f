#!/usr/bin/env bash
# End to end: `openswarm new NAME --force` keeps every app it replaces,
# whole, in NAME.replaced-1, -2, ..., and says where (issue 30: the old
# app was removed once the new one was in place - left half-removed when a
# file could not be removed - and an older copy deleted without a word).
#   new_force.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

# every file of a folder and its content, to compare copies whole
contents() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 sha256sum); }
# same DESCRIPTION A B: the two listings are equal.
same() {
    if [ "$2" = "$3" ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $1"; fi
}

"$openswarm" new app >/dev/null || { echo "FAILED: openswarm new app"; exit 1; }
echo "first notes" > app/notes.txt
mkdir app/data && echo "measured" > app/data/run.csv
first=$(contents app)
# an older tool's copy beside it: not the tool's to delete
mkdir .app.openswarm-old && echo "older" > .app.openswarm-old/kept.txt

check "new --force says where the old app went" 0 \
    "Created \./app from template.*The app it replaces is kept, whole, in \./app\.replaced-1: remove that folder" \
    "$openswarm" new app --force
same "the first replaced app is kept whole in app.replaced-1" "$first" "$(contents app.replaced-1)"
[ -f app/main.c ] && [ ! -e app/notes.txt ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: app is not a fresh copy of the template"; }

echo "second notes" > app/notes.txt
second=$(contents app)
check "new --force again: the next number" 0 "The app it replaces is kept, whole, in \./app\.replaced-2" \
    "$openswarm" new app --force
same "the first copy is untouched by the second --force" "$first" "$(contents app.replaced-1)"
same "the second replaced app is kept whole in app.replaced-2" "$second" "$(contents app.replaced-2)"
grep -qx older .app.openswarm-old/kept.txt && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: .app.openswarm-old was touched"; }

# A file that cannot be removed (immutable) is no obstacle: nothing is
# removed, the folder is renamed whole.
"$openswarm" new forced >/dev/null
mkdir forced/locked && echo "keep" > forced/locked/file
chattr +i forced/locked/file || { echo "FAILED: chattr +i (the test needs it)"; exit 1; }
locked=$(contents forced)
check "new --force over a file that cannot be removed" 0 "kept, whole, in \./forced\.replaced-1" \
    "$openswarm" new forced --force
same "the app with the immutable file is kept whole" "$locked" "$(contents forced.replaced-1)"
chattr -i forced.replaced-1/locked/file forced/locked/file 2>/dev/null
[ -f forced/main.c ] && [ ! -e forced/locked ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: forced is not a fresh copy"; }

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
