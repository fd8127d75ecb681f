#!/usr/bin/env bash
# End to end: the commands that tell rather than do.
#   informational.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
check "version" 0 "openswarm [0-9]+\.[0-9]+\.[0-9]+" "$openswarm" --version
check "help names every command" 0 "new.*build.*run.*ports.*templates.*config.*doctor" "$openswarm" --help
check "help of a command" 0 "--template" "$openswarm" new --help
check "ports" 0 "kilobot +Kilobot" "$openswarm" ports
check "templates" 0 "blinky .*\[kilobot\]" "$openswarm" templates
check "templates, the C++ ones" 0 "threads-and-events-cpp +the paper's Listing 1 in C\+\+" "$openswarm" templates
check "templates as JSON" 0 "\"name\": \"threads-and-events\"" "$openswarm" templates --json
check "ports as JSON" 0 "\"ram_bytes\": 2048" "$openswarm" ports --json
check "doctor, all there" 0 "Everything is in place" "$openswarm" doctor
mkdir empty-path
check "doctor, nothing there" 1 "sudo apt-get install cmake ninja-build gcc-avr binutils-avr" \
    env PATH="$PWD/empty-path" "$openswarm" doctor
"$openswarm" new shown >/dev/null
check "config show" 0 "port +kilobot" "$openswarm" config show -C shown
check "config check" 0 "shown/openswarm.json is valid" "$openswarm" config check -C shown
check "config check, bad file" 2 "\"port\": missing" sh -c "printf '{\"name\": \"x\"}' > shown/openswarm.json && \"$openswarm\" config check -C shown"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
