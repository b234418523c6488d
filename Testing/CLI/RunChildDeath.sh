#!/bin/sh
# A stored flow complex is read in a child process that then goes on with the
# command while the parent waits (IsolatedRead.h). When that child dies of a
# signal nobody asked for, the parent must say so in one line and end as it
# did: SIGKILL (what the out-of-memory killer sends) and SIGABRT (a crash).
# A SIGTERM sent to the parent is forwarded and ends both without a word.
# Usage: RunChildDeath.sh FLOWRECON WORKDIR
set -u
flowrecon=$1
work=$2
mkdir -p "$work"
cloud="$work/death.xyz"
complex="$work/death.vtm"
awk 'BEGIN { srand(11); for (i = 0; i < 20000; i++) printf "%.9f %.9f %.9f\n", rand(), rand(), rand() }' > "$cloud"
"$flowrecon" complex "$cloud" -o "$complex" > /dev/null || { echo "FAIL: complex"; exit 1; }

# Starts `reconstruct`, waits until the parent waits for its child (the read is
# over, the child goes on: the parent sits in wait(), not in poll()), then sends
# SIGNAL to TARGET (child or parent). Prints the exit code; stderr in $err.
err="$work/death.err"
run() {
  "$flowrecon" reconstruct "$complex" -o "$work/death.vtu" > /dev/null 2> "$err" < /dev/null &
  parent=$!
  child=
  i=0
  while [ $i -lt 600 ]; do
    child=$(cat /proc/$parent/task/$parent/children 2> /dev/null | tr -d ' ')
    if [ -n "$child" ] && [ "$(cat /proc/$parent/wchan 2> /dev/null)" = do_wait ]; then
      break
    fi
    child=
    sleep 0.1
    i=$((i + 1))
  done
  [ -n "$child" ] || { echo "FAIL: no child going on after the read"; kill -KILL $parent; exit 1; }
  if [ "$2" = child ]; then kill -$1 "$child"; else kill -$1 "$parent"; fi
  wait $parent
  echo $?
}

check() { # SIGNAL TARGET EXPECTED-CODE EXPECTED-STDERR
  code=$(run "$1" "$2")
  got=$(cat "$err")
  echo "SIG$1 to the $2: exit code $code, stderr: [$got]"
  [ "$code" -eq "$3" ] || { echo "FAIL: expected exit code $3"; exit 1; }
  [ "$got" = "$4" ] || { echo "FAIL: expected stderr [$4]"; exit 1; }
}

check KILL child 137 "flowrecon: killed (SIGKILL), as the system does when memory runs out"
check ABRT child 134 "flowrecon: crashed (Aborted); please report it with the input"
check TERM parent 143 ""
echo PASS
