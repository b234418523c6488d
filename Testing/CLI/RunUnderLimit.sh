#!/bin/sh
# Memory guard test (docs/design.md, "Never killed for memory"): under an
# address-space limit, `flowrecon reconstruct --tr inf --exact` (the drawing of
# the stable manifolds, the largest output) of a 20000-point torus
# surface (whose whole flow complex does not fit) must stop with exit code 1 and
# one line giving the estimate and what to do, never abort or be killed; so
# must every limit of a sweep up to where it fits.
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
  ( ulimit -v "$limit"; exec "$flowrecon" reconstruct "$cloud" -o "$out" --tr inf --tp 0 --exact --quiet ) \
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
# Every limit between "refused" and "fits": each guard must count what its phase
# allocates (the VTK output's guard, short by 7 bytes a cell, let VTK abort the
# process at 1.5 GB). Each run either writes its file (exit 0) or gives the
# guard's line (exit 1); the sweep must see both, or it missed the boundary.
fitted=0; refused=0
limit=1050000
while [ "$limit" -le 1750000 ]; do
  out="$work/sweep.vtu"
  rm -f "$out"
  ( ulimit -v "$limit"; exec "$flowrecon" reconstruct "$cloud" -o "$out" --tr inf --tp 0 --exact --quiet ) \
    2> "$work/sweep.err"
  code=$?
  if [ "$code" -eq 0 ] && [ -s "$out" ]; then
    fitted=$((fitted + 1))
  elif [ "$code" -eq 1 ] && [ "$(wc -l < "$work/sweep.err")" -eq 1 ] &&
    grep -q "needs about.*GB are available; " "$work/sweep.err" && [ ! -e "$out" ]; then
    refused=$((refused + 1))
  else
    echo "FAIL: ulimit -v $limit: exit code $code, stderr: [$(cat "$work/sweep.err")]"; status=1
  fi
  limit=$((limit + 50000))
done
echo "sweep 1.05-1.75 GB: $fitted written, $refused refused by a guard"
if [ $fitted -eq 0 ] || [ $refused -eq 0 ]; then
  echo "FAIL: the sweep did not cross from refused to written"; status=1
fi
# The default output (Delaunay simplices on the samples; at t_r inf every
# patch is walked and every Delaunay cell's flow line followed) has no guard of
# its own: where an allocation fails the run must still end in one line. Each
# run writes its file or gives one line, and the largest limit writes.
compact=""
for limit in 300000 325000 350000 400000 500000 700000; do
  out="$work/compact.vtu"
  rm -f "$out"
  ( ulimit -v "$limit"; exec "$flowrecon" reconstruct "$cloud" -o "$out" --tr inf --tp 0 --quiet ) \
    2> "$work/compact.err"
  code=$?
  if [ "$code" -eq 0 ] && [ -s "$out" ]; then
    compact="$compact written"
  elif [ "$code" -eq 1 ] && [ "$(wc -l < "$work/compact.err")" -eq 1 ] &&
    grep -q "out of memory\|needs about.*GB are available; " "$work/compact.err" && [ ! -e "$out" ]; then
    compact="$compact refused"
  else
    echo "FAIL: default output, ulimit -v $limit: exit code $code, stderr: [$(cat "$work/compact.err")]"
    status=1
  fi
done
echo "default output at 0.3-0.7 GB:$compact"
case "$compact" in
  *written) ;;
  *) echo "FAIL: the default output did not fit in 0.7 GB"; status=1 ;;
esac
[ $status -eq 0 ] && echo PASS
exit $status
