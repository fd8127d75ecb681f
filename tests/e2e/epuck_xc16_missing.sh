#!/usr/bin/env bash
# End to end: the e-puck (dsPIC30F6014A) port without Microchip XC16, which
# is not in Debian: `openswarm ports` lists it as build only; building a new
# blinky for it fails (exit 1) saying what to install; run and test refuse
# it (nothing here runs a dsPIC image) and say the same.
#   epuck_xc16_missing.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
if command -v xc16-gcc >/dev/null; then
    echo "xc16-gcc is installed: this test is for a machine without it"
    exit 77
fi
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
install="install Microchip XC16 from https://www.microchip.com/xc16 \(it is not in Debian\)"
check "ports lists epuck" 0 \
    "epuck +e-puck: dsPIC30F6014A at 14.7456 MIPS; needs Microchip XC16, not in Debian: build only, no simulator" \
    "$openswarm" ports
check "new blinky for epuck" 0 "Next: cd \./app && openswarm build$" \
    "$openswarm" new app --template blinky --port epuck
check "build without XC16" 1 "openswarm: xc16-gcc was not found, and the epuck port needs it: $install" \
    "$openswarm" build -C app --port epuck
check "run refuses epuck" 1 "nothing here runs epuck images \(no simulator\).*needs xc16-gcc, which was not found: $install" \
    "$openswarm" run -C app
check "test refuses epuck" 1 "nothing here runs epuck images \(no simulator\).*XC16" \
    sh -c "mkdir -p app/tests && printf '0.5,led,1,0,0\n' > app/tests/blink.trace && \"$openswarm\" test -C app"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
