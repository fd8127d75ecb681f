#!/usr/bin/env bash
# The README's "What you write" program builds for the Kilobot as it is,
# without a warning in it, and runs: the first ```c block after the
# "## What you write" heading becomes main.c of an app scaffolded from the
# blank template.
#   readme_snippet.sh OPENSWARM README WORKDIR
set -euo pipefail
openswarm=$1 readme=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
awk '/^## What you write/ { section = 1; next }
     section && !inside && /^```c[[:space:]]*$/ { inside = 1; next }
     inside && /^```/ { found = 1; exit }
     inside { print }
     END { if (!found) exit 1 }' "$readme" > snippet.c ||
    { echo "FAIL: no closed \`\`\`c block after '## What you write' in $readme"; exit 1; }
grep -q 'int main' snippet.c || { echo "FAIL: the snippet has no main()"; cat snippet.c; exit 1; }
"$openswarm" new app --template blank --port kilobot
cp snippet.c app/main.c
cd app
if ! "$openswarm" build > build.log 2>&1; then
    cat build.log
    echo "FAIL: the README's snippet does not build for the Kilobot"
    exit 1
fi
if grep -E 'main\.c:[0-9]+:[0-9]+: (warning|error)' build.log; then
    echo "FAIL: the README's snippet compiles with warnings"
    exit 1
fi
# It runs: the LED blinks green, and no kernel fault fails the run.
"$openswarm" run --time 1.2 > run.log 2>&1 || { cat run.log; echo "FAIL: the snippet's run failed"; exit 1; }
grep -Eq '\] led +red 0 green 3 blue 0' run.log || { cat run.log; echo "FAIL: the LED never turned green"; exit 1; }
echo "1 passed, 0 failed"
