#!/bin/sh
# Ctrl-C test: SIGINT two seconds into `flowrecon complex` on a 50000-point
# cloud (a run of several seconds) must stop it cleanly: exit code 130, the
# single line "flowrecon: aborted" on stderr, and no output file.
# Usage: RunInterrupt.sh FLOWRECON WORKDIR
set -u
flowrecon=$1
work=$2
mkdir -p "$work"
cloud="$work/interrupt.xyz"
out="$work/interrupt.vtm"
rm -f "$out"
awk 'BEGIN { srand(7); for (i = 0; i < 50000; i++) printf "%.9f %.9f %.9f\n", rand(), rand(), rand() }' > "$cloud"
# --foreground: GNU timeout otherwise sends the signal twice, to the command and
# to its process group; when the two do not merge, the second one is a second
# Ctrl-C, which exits at once without the message (seen once in CI).
timeout --foreground -s INT --preserve-status 2 "$flowrecon" complex "$cloud" -o "$out" 2> "$work/interrupt.err"
code=$?
err=$(cat "$work/interrupt.err")
echo "exit code $code, stderr: [$err]"
[ "$code" -eq 130 ] || { echo "FAIL: expected exit code 130"; exit 1; }
[ "$err" = "flowrecon: aborted" ] || { echo "FAIL: expected the single line 'flowrecon: aborted'"; exit 1; }
[ ! -e "$out" ] || { echo "FAIL: the interrupted run left $out"; exit 1; }
echo PASS
