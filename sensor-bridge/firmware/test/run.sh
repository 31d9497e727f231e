#!/usr/bin/env bash
# Builds the reference firmware's protocol and grain code and the sketch itself for the host with g++, and runs
# their tests: host_test (CRC, COBS, decoder, device logic, and the shared vectors the Kotlin tests use
# too), grains_test (grain counts, scan timing, limits) and sketch_test (hapticon_ref.ino on stubbed Arduino hardware). Sanitizers are used when the
# compiler has them. Exits non-zero on any failure.
#
#   sensor-bridge/firmware/test/run.sh [path/to/framed-vectors.txt]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src="$here/../hapticon_ref"
vectors="${1:-$here/../../../test-fixtures/src/main/resources/streams/framed-vectors.txt}"
cxx="${CXX:-g++}"
out=$(mktemp -d "${TMPDIR:-/tmp}/hapticon-firmware.XXXXXX")
trap 'rm -rf "$out"' EXIT

flags=(-std=c++11 -Wall -Wextra -Werror -pedantic -O1 -g)
echo 'int main() { return 0; }' > "$out/probe.cpp"
if "$cxx" -fsanitize=address,undefined -o "$out/probe" "$out/probe.cpp" 2>/dev/null && ASAN_OPTIONS=detect_leaks=0 "$out/probe"; then
  flags+=(-fsanitize=address,undefined -fno-sanitize-recover=all)
  export ASAN_OPTIONS=detect_leaks=0
fi

"$cxx" "${flags[@]}" -I"$src" -o "$out/host_test" "$here/host_test.cpp" "$src/hfp.cpp" "$src/hfp_device.cpp" "$src/grains.cpp"
"$cxx" "${flags[@]}" -I"$src" -o "$out/grains_test" "$here/grains_test.cpp" "$src/grains.cpp"
# The sketch is C++ with Arduino.h included implicitly, as the Arduino IDE builds it.
"$cxx" "${flags[@]}" -I"$src" -I"$here/arduino_stub" -o "$out/sketch_test" \
  "$here/sketch_test.cpp" "$here/sketch_hooks.cpp" "$src/hfp.cpp" "$src/hfp_device.cpp" "$src/grains.cpp"

"$out/host_test" "$vectors"
"$out/grains_test"
"$out/sketch_test"
