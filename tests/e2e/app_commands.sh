#!/usr/bin/env bash
# End to end, issue 31: the commands a PlatformIO user expects. test NAME
# runs one test (an unknown one gets a did-you-mean); clean removes the
# build folder and says so; the completion scripts list every command;
# --port is checked by config check and build, with a did-you-mean, and a
# device the port has not is named with the fix.
#   app_commands.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
"$openswarm" new app --template blinky >/dev/null
cd app
# test NAME: one test; an unknown name is refused before the build.
cp tests/blinks.trace tests/other.trace
sed -i 's/^0.002,led,0,3,0$/0.002,led,3,3,3/' tests/other.trace
logged 0 "^1 passed, 0 failed$" "$openswarm" test blinks
grep -q "^blinks  *PASSED$" out.log
! grep -q "^other" out.log
logged 2 "no test 'blink' \(./tests/blink.trace\) \(did you mean 'blinks'\?\); tests: blinks, other" "$openswarm" test blink
logged 1 "^0 passed, 1 failed$" "$openswarm" test other
# clean: the build folder goes, and it says so; nothing left, it says that.
test -d build
logged 0 "^Removed ./build \([0-9]+ files, [0-9.]+ MB\)" "$openswarm" clean
test ! -e build
logged 0 "^Nothing to remove: ./build does not exist$" "$openswarm" clean
logged 2 "^openswarm: tests/openswarm.json: not found; .*-C DIR$" "$openswarm" clean -C tests
test -f tests/blinks.trace
logged 0 "Remove the app's build folder" "$openswarm" clean --help
# Completion: every command of `openswarm --help`, and a working bash function.
commands=$("$openswarm" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}')
test -n "$commands"
for shell in bash zsh; do
    "$openswarm" completion $shell > completion.$shell
    for c in $commands; do grep -q "\b$c\b" completion.$shell || { echo "$shell: no $c"; exit 1; }; done
done
bash -n completion.bash
(
    source completion.bash
    COMP_WORDS=(openswarm cle); COMP_CWORD=1; _openswarm; test "${COMPREPLY[*]}" = "clean"
    COMP_WORDS=(openswarm config check --p); COMP_CWORD=3; _openswarm; test "${COMPREPLY[*]}" = "--port"
)
logged 2 "Argument 'fish'|fish" "$openswarm" completion fish
# --port: checked, with a did-you-mean; a device the port has not, named.
logged 2 "unknown port 'kilobt'; ports: .*did you mean 'kilobot'" "$openswarm" build --port kilobt
logged 2 "unknown port 'epuk2'.*did you mean 'epuck2'" "$openswarm" config check --port epuk2
logged 0 "openswarm.json is valid for epuck2$" "$openswarm" config check --port epuck2
sed -i 's/^  "port": "kilobot",$/&\n  "devices": { "light": { "processor": "raw" } },/' openswarm.json
logged 0 "openswarm.json is valid$" "$openswarm" config check
logged 2 "devices.light.*no device \"light\" on epuck2 \(--port epuck2; the file's \"port\" is kilobot\): build for kilobot \(leave --port out\), or remove this device for epuck2" \
    "$openswarm" config check --port epuck2
logged 2 "no device \"light\" on epuck2 \(--port epuck2" "$openswarm" build --port epuck2
! grep -q "writable" out.log
echo "1 passed, 0 failed"
