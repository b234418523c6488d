#!/bin/sh
# Starts a pvserver on a free local port, runs test_parallel.py against it from
# pvpython (plugin loaded on the server), and stops the server.
# Usage: RunClientServer.sh PVSERVER PVPYTHON SCRIPT PLUGIN FLOWRECON CLOUD WORKDIR
# Every step has its own bound, below ctest's, so a hang in ParaView's own
# start-up or teardown (seen once on a loaded CI machine) says where it was.
set -u
pvserver=$1; pvpython=$2; script=$3; shift 3
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
"$pvserver" --server-port="$port" --force-offscreen-rendering > "$4.pvserver.log" 2>&1 &
server=$!
stop_server() {
  kill "$server" 2>/dev/null
  i=0
  while kill -0 "$server" 2>/dev/null && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
  if kill -0 "$server" 2>/dev/null; then
    echo "pvserver ignored SIGTERM for 10 s; killed"
    kill -9 "$server" 2>/dev/null
  fi
  wait "$server" 2>/dev/null
}
trap stop_server EXIT
# Wait until the server listens (a fixed sleep was too short under load). Read
# the kernel's socket table: a probe connection would be taken as the client.
/usr/bin/python3 - "$port" <<'PY' || { echo "pvserver did not listen within 60 s"; exit 1; }
import sys, time
port = "%04X" % int(sys.argv[1])
def listening():
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        try:
            for line in open(table).readlines()[1:]:
                f = line.split()
                if f[1].endswith(":" + port) and f[3] == "0A":
                    return True
        except OSError:
            pass
    return False
end = time.time() + 60
while time.time() < end:
    if listening():
        sys.exit(0)
    time.sleep(0.2)
sys.exit(1)
PY
timeout -k 5 200 "$pvpython" --force-offscreen-rendering "$script" "$@" --server "localhost:$port"
status=$?
[ $status -eq 124 ] && echo "pvpython did not exit within 200 s"
exit $status
