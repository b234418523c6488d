#!/bin/sh
# Memory guard test under a cgroup memory limit (a container's, Slurm's): past
# it the kernel kills the process with SIGKILL, so the guard must read the limit
# and refuse first. In a cgroup limited to 200 MB, `flowrecon reconstruct
# --exact` (the drawing of the stable manifolds, the largest output) of a
# 2e5-point torus surface must stop with exit code 1 and the guard's one line
# naming the cgroup limit; and a 20000-point torus at limits from refused to
# fitting must each time either write its file or give that line, never be
# killed. Needs root and a writable memory controller (cgroup v2 or v1):
# otherwise exits 77 (skipped).
# Usage: RunUnderCgroup.sh FLOWRECON WORKDIR
set -u
flowrecon=$1
work=$2
mkdir -p "$work"
skip() { echo "SKIP: $1"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "not root: cannot create a cgroup"
# Below the machine's MemAvailable the cgroup, not the machine, binds.
avail=$(awk '$1 == "MemAvailable:" { print int($2 / 1024) }' /proc/meminfo)
[ "${avail:-0}" -ge 3000 ] || skip "MemAvailable ${avail:-?} MB: the limits would not bind"

# The mount of cgroup v2 if it has the memory controller, else of v1's memory
# hierarchy (mountinfo: the mount point is field 5, the type follows "-").
v2=$(awk '{ for (i = 1; i <= NF; i++) if ($i == "-") { if ($(i + 1) == "cgroup2") print $5; break } }' \
  /proc/self/mountinfo | head -n 1)
v1=$(awk '{ for (i = 1; i <= NF; i++) if ($i == "-") {
    if ($(i + 1) == "cgroup" && $(i + 3) ~ /(^|,)memory(,|$)/) print $5; break } }' \
  /proc/self/mountinfo | head -n 1)
if [ -n "$v2" ] && grep -qw memory "$v2/cgroup.controllers" 2>/dev/null; then
  grep -qw memory "$v2/cgroup.subtree_control" ||
    echo +memory 2>/dev/null > "$v2/cgroup.subtree_control" ||
    skip "cannot enable the memory controller under $v2"
  parent=$v2; limit_file=memory.max
elif [ -n "$v1" ]; then
  parent=$v1; limit_file=memory.limit_in_bytes
else
  skip "no cgroup memory controller mounted"
fi
cgroup="$parent/flowrecon-test-$$"
trap 'rmdir "$cgroup" 2>/dev/null' EXIT
trap 'exit 1' INT TERM

# run LIMIT_BYTES CLOUD OUT: flowrecon reconstruct in a new cgroup of that limit;
# sets code (77: the cgroup could not be made or joined).
run() {
  mkdir "$cgroup" 2>/dev/null && echo "$1" 2>/dev/null > "$cgroup/$limit_file" || { code=77; return; }
  sh -c 'echo $$ > "$1/cgroup.procs" || exit 77; shift; exec "$@"' sh "$cgroup" \
    "$flowrecon" reconstruct "$2" -o "$3" --tr inf --tp 0 --exact --quiet 2> "$work/cgroup.err"
  code=$?
  rmdir "$cgroup"
}
refusal="needs about .* GB of memory, .* GB are available (cgroup memory limit); "

cloud="$work/cgroup_torus.xyz"
awk 'BEGIN { srand(3); pi = 3.141592653589793; n = 0
  while (n < 200000) { u = 2 * pi * rand(); v = 2 * pi * rand()
    if (rand() < (1 + 0.35 * cos(v)) / 1.35) {
      printf "%.9f %.9f %.9f\n", (1 + 0.35 * cos(v)) * cos(u), (1 + 0.35 * cos(v)) * sin(u), 0.35 * sin(v); n++ } } }' > "$cloud"
status=0
out="$work/cgroup.vtu"
rm -f "$out"
run 200000000 "$cloud" "$out"
[ "$code" -ne 77 ] || skip "cannot create or join a cgroup with a memory limit under $parent"
err=$(cat "$work/cgroup.err")
echo "2e5 points, $limit_file 200 MB: exit code $code, stderr: [$err]"
if [ "$code" -ne 1 ] || [ "$(wc -l < "$work/cgroup.err")" -ne 1 ] ||
  ! grep -q "$refusal" "$work/cgroup.err"; then
  [ "$code" -eq 137 ] && echo "FAIL: killed (SIGKILL): the guard did not see the cgroup limit"
  echo "FAIL: expected exit code 1 and the guard's line naming the cgroup limit"; status=1
fi
[ ! -e "$out" ] || { echo "FAIL: $out was written"; status=1; }

# The 20000-point torus of RunUnderLimit.sh (the same generator's first lines)
# needs about 1.2 GB: refused at the drawing, at the VTK output, then written.
small="$work/cgroup_torus_20000.xyz"
head -n 20000 "$cloud" > "$small"
fitted=0; refused=0
for limit in 700 1100 1300 1700; do
  rm -f "$out"
  run "${limit}000000" "$small" "$out"
  if [ "$code" -eq 0 ] && [ -s "$out" ]; then
    fitted=$((fitted + 1))
  elif [ "$code" -eq 1 ] && [ "$(wc -l < "$work/cgroup.err")" -eq 1 ] &&
    grep -q "$refusal" "$work/cgroup.err" && [ ! -e "$out" ]; then
    refused=$((refused + 1))
  else
    echo "FAIL: $limit_file $limit MB: exit code $code, stderr: [$(cat "$work/cgroup.err")]"; status=1
  fi
done
rm -f "$out" "$cloud" "$small"
echo "20000 points, $limit_file 0.7-1.7 GB: $fitted written, $refused refused by a guard"
if [ $fitted -eq 0 ] || [ $refused -eq 0 ]; then
  echo "FAIL: the sweep did not cross from refused to written"; status=1
fi
[ $status -eq 0 ] && echo PASS
exit $status
