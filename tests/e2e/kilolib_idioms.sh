#!/usr/bin/env bash
# End to end, issue 31: a classic program's message_rx that ignores its
# distance_measurement_t * (kilolib's idiom) builds without a warning, even
# with --werror (-Wextra's unused-parameter warned on every such program);
# an unused variable is still warned of.
#   kilolib_idioms.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new classic --template kilolib >/dev/null
cd classic
cat > main.c <<'C'
#include <kilolib.h>

static uint8_t heard;

void message_rx(message_t *m, distance_measurement_t *d) {
    heard = m->data[0];
}

void setup(void) {}

void loop(void) { set_color(heard ? RGB(0, 3, 0) : RGB(0, 0, 0)); }

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_start(setup, loop);
    return 0;
}
C
"$openswarm" build --werror > build.log 2>&1 || { cat build.log; echo "FAILED: the idiom broke --werror"; exit 1; }
! grep -q "warning" build.log || { cat build.log; echo "FAILED: a warning on the idiom"; exit 1; }
sed -i 's|^void loop(void) {|void loop(void) {\n    int unused;|' main.c
status=0
"$openswarm" build --werror > build.log 2>&1 || status=$?
cat build.log
test "$status" = 1 && grep -q "unused variable .*unused" build.log
echo "1 passed, 0 failed"
