#!/bin/sh
# Memory guard test (DESIGN.md, "never killed for memory"): under an
# address-space limit, `flowrecon reconstruct --tr inf` of a 20000-point torus
# surface (whose whole flow complex does not fit) must stop with exit code 1 and
# one line giving the estimate and what to do, never abort or be killed.
# Usage: RunUnderLimit.sh FLOWRECON WORKDIR
set -u
flowrecon=$1
work=$2
mkdir -p "$work"
cloud="$work/limit_torus.xyz"
awk 'BEGIN { srand(3); pi = 3.141592653589793; n = 0
  while (n < 20000) { u = 2 * pi * rand(); v = 2 * pi * rand()
    if (rand() < (1 + 0.35 * cos(v)) / 1.35) {
      printf "%.9f %.9f %.9f\n", (1 + 0.35 * cos(v)) * cos(u), (1 + 0.35 * cos(v)) * sin(u), 0.35 * sin(v); n++ } } }' > "$cloud"
status=0
for limit in 300000 800000; do
  out="$work/limit_$limit.vtu"
  rm -f "$out"
  ( ulimit -v "$limit"; exec "$flowrecon" reconstruct "$cloud" -o "$out" --tr inf --tp 0 --quiet ) \
    2> "$work/limit.err"
  code=$?
  lines=$(wc -l < "$work/limit.err")
  err=$(cat "$work/limit.err")
  echo "ulimit -v $limit: exit code $code, stderr: [$err]"
  if [ "$code" -ne 1 ] || [ "$lines" -ne 1 ]; then
    echo "FAIL: expected exit code 1 and one line"; status=1
  fi
  case "$err" in
    *"needs about"*"GB are available; "*) ;;
    *) echo "FAIL: expected the guard's line (estimate, what is available, what to do)"; status=1 ;;
  esac
  [ ! -e "$out" ] || { echo "FAIL: $out was written"; status=1; }
done
[ $status -eq 0 ] && echo PASS
exit $status
