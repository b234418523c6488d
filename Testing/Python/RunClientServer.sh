#!/bin/sh
# Starts a pvserver on a free local port, runs test_parallel.py against it from
# pvpython (plugin loaded on the server), and stops the server.
# Usage: RunClientServer.sh PVSERVER PVPYTHON SCRIPT PLUGIN FLOWRECON CLOUD WORKDIR
set -u
pvserver=$1; pvpython=$2; script=$3; shift 3
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
"$pvserver" --server-port="$port" --force-offscreen-rendering > "$4.pvserver.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null' EXIT
sleep 3
timeout 300 "$pvpython" --force-offscreen-rendering "$script" "$@" --server "localhost:$port"
