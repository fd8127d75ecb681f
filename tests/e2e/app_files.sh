#!/usr/bin/env bash
# End to end, issue 31: an app of many files, named once. Every .c of src/
# (and below) and of the app's folder is built, a file added later too; a
# renamed app builds; compile_commands.json lists every source with the
# robot's flags; a CMakeLists.txt of the app's own that names the firmware
# otherwise than openswarm.json is refused, naming both files.
#   app_files.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
test ! -e CMakeLists.txt
# The LED's colour comes from src/colour/red.c, the blink's period from
# period.c in the app's folder (added after the first build).
mkdir -p src/colour
printf '#include "openswarm/robot.h"\nuint8_t app_colour(void) { return ROBOT_RGB(3, 0, 0); }\n' > src/colour/red.c
sed -i 's/^#include "openswarm_app.h"$/&\nuint8_t app_colour(void);/; s/ROBOT_RGB(0, 3, 0)/app_colour()/' main.c
"$openswarm" build > build.log
grep -q "^Built ./build/kilobot/app.elf for kilobot$" build.log
# One flash percentage, against the 28 KB below the bootloader (issue 31:
# avr-size's "24.3% Full", of the chip's 32 KB, came first on the same
# screen as the tool's 27.7%).
grep -Eq "^Flash \[.*\] +[0-9.]+% \([0-9]+ of 28672 bytes\)$" build.log || { cat build.log; exit 1; }
if grep -q "% Full)" build.log; then echo "avr-size's percentage of the chip's 32 KB:"; cat build.log; exit 1; fi
"$openswarm" run --time 0.3 > run.log 2>&1
grep -Eq "^\[  0\.00[0-9]+ s\] led +red 3 green 0 blue 0$" run.log
printf 'unsigned app_period(void) { return 100; }\n' > period.c
sed -i 's/^uint8_t app_colour(void);$/&\nunsigned app_period(void);/; s/Sys_Sleep(250)/Sys_Sleep(app_period())/' main.c
"$openswarm" run --time 0.3 > run.log 2>&1
cat run.log
grep -Eq "^\[  0\.10[0-9]+ s\] led +red 0 green 0 blue 0$" run.log
grep -Eq "^\[  0\.20[0-9]+ s\] led +red 3 green 0 blue 0$" run.log
# Every source, compiled for the robot, with the generated headers.
python3 - <<'PY'
import json, os
entries = json.load(open("build/compile_commands.json"))
app = os.getcwd()
for source in ["main.c", "src/colour/red.c", "period.c"]:
    path = os.path.join(app, source)
    found = [e for e in entries if os.path.normpath(os.path.join(e["directory"], e["file"])) == path]
    assert len(found) == 1, (source, len(found))
    command = found[0].get("command") or " ".join(found[0]["arguments"])
    for flag in ["avr-gcc", "-mmcu=atmega328p", "-Wall", "-Wextra",
                 "-I" + os.path.join(app, "build/kilobot/openswarm")]:
        assert flag in command, (source, flag, command)
PY
# The name is in openswarm.json alone: renamed there, the app builds.
sed -i 's/"name": "app"/"name": "renamed"/' openswarm.json
"$openswarm" build > build.log
grep -q "^Built ./build/kilobot/renamed.elf for kilobot$" build.log
# A CMakeLists.txt of the app's own, as the templates had, naming the
# firmware otherwise: refused before CMake runs, naming both files.
cat > CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(app C ASM)
find_package(OpenSwarm REQUIRED)
openswarm_add_firmware(app PORT ${OPENSWARM_PORT} SOURCES main.c)
CMAKE
status=0
"$openswarm" build > build.log 2>&1 || status=$?
cat build.log
test "$status" = 2
grep -q "named \"renamed\" in ./openswarm.json but \"app\" in ./CMakeLists.txt:4" build.log
# The name from a variable: CMake's check names both files.
sed -i 's/^openswarm_add_firmware(app /set(firmware other)\nopenswarm_add_firmware(${firmware} /' CMakeLists.txt
status=0
"$openswarm" build > build.log 2>&1 || status=$?
test "$status" = 1
# (CMake wraps the message's lines)
tr '\n' ' ' < build.log | tr -s ' ' > message.txt
grep -q "named \"renamed\" in $PWD/openswarm.json but \"other\" in $PWD/CMakeLists.txt: give it one name" message.txt
# One name: the files it lists and every other source are built.
sed -i 's/^set(firmware other)$/set(firmware renamed)/' CMakeLists.txt
"$openswarm" run --time 0.3 > run.log 2>&1
grep -Eq "^\[  0\.20[0-9]+ s\] led +red 3 green 0 blue 0$" run.log
echo "1 passed, 0 failed"
