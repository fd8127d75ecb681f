#!/usr/bin/env bash
# Installs every Debian 12 package OpenSwarm needs. Safe to run again: it
# only calls apt-get when something is missing.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config python3  # host build, benchmarks
  googletest libgtest-dev                   # host test suites
  gcc-avr avr-libc binutils-avr             # Kilobot (ATmega328P) firmware
  simavr libsimavr-dev libelf-dev          # running firmware cycle-exactly
  libcli11-dev nlohmann-json3-dev           # the openswarm command-line tool, world.json
  libbox2d-dev libcairo2-dev               # the world: physics, pictures
  ffmpeg chromium fonts-dejavu-core        # the world: video; the viewer's browser test
  gcc-arm-none-eabi libnewlib-arm-none-eabi # e-puck2 (STM32F407) firmware
  qemu-system-arm gdb-multiarch             # running it under QEMU, debugging it
  gdb-avr                                   # debugging Kilobot firmware at source level
  openmpi-bin libopenmpi-dev                # experiments spread over ranks and machines (mpirun)
  clang libclang-rt-14-dev                  # fuzzing the file readers (libFuzzer)
  valgrind                                  # checking the simulator's memory (avr.wild_store)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: installed ${#missing[@]} packages"
