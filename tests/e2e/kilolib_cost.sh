#!/usr/bin/env bash
# End to end (issue 15): a classic Kilobot program on our kilolib costs
# about what it costs on the classic library. The kilolib template (blink,
# motors, as the classic library's blink lab) builds within 1.5 KB of flash
# of the classic library's 5.8 KB and in at most 450 bytes of RAM with
# every stack but main's (there is none: setup() and loop() run on the
# system thread); the configuration the build generates for it holds
# kilolib_pools.h's pools (the header the avr tests build kilolib with);
# `openswarm size` lists no thread stack.
#   kilolib_cost.sh OPENSWARM OPENSWARM_ROOT WORKDIR
set -euo pipefail
openswarm=$1 root=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new klab --template kilolib --port kilobot > /dev/null
cd klab
"$openswarm" build --json > build.json 2> /dev/null
read -r flash ram < <(python3 -c 'import json, sys; b = json.load(open(sys.argv[1])); print(b["flash"], b["ram"])' build.json)
echo "flash $flash B, RAM $ram B"
[ "$ram" -le 450 ] || { echo "RAM $ram B is over 450"; exit 1; }
[ "$flash" -le $((5800 + 1500)) ] || { echo "flash $flash B is over the classic 5.8 KB + 1.5 KB"; exit 1; }
config=build/kilobot/openswarm/openswarm_config.h
grep -E '^#define OS_CFG_[A-Z_]+ [0-9]+' "$root/ports/kilobot/kilolib/include/kilolib_pools.h" |
    awk '{print $1, $2, $3}' > pools.txt
[ "$(wc -l < pools.txt)" -ge 9 ]
while read -r line; do
    grep -qx "$line" "$config" || { echo "the generated $config lacks '$line'"; cat "$config"; exit 1; }
done < pools.txt
"$openswarm" size > size.log
grep -Eq "^  the stack pool +0$" size.log || { echo "a thread stack pool"; cat size.log; exit 1; }
grep -q "^Warning" size.log && { echo "a warning"; cat size.log; exit 1; }
grep -q "kilolib: " size.log && { echo "kilolib's threads listed"; cat size.log; exit 1; }
grep -E "^Main stack .*worst use [0-9]+ of its [0-9]+ bytes" size.log
echo "1 passed, 0 failed"
