#!/usr/bin/env bash
# From a fresh clone to "ARMOR ready", as a new user on a fresh machine (issue 33).
#
#   bash bench/cold_start.sh [BRANCH]     (default: the branch checked out here)
#
# Clones this repository into a scratch folder and runs `make run` there with HOME and the
# pip, uv (through XDG_CACHE_HOME), npm and Maven caches pointed at empty folders, so every
# download is made. Prints each set-up step's wall and CPU time (from its own line), the wall
# time to "ARMOR ready", the first `armor call` after it, then the same for a second
# `make run` (warm: nothing to do).
# The node runs in a free DDS domain with its web view on a free port; everything is removed
# at the end.
set -euo pipefail
set -m  # make run in a process group of its own, which Ctrl-C (SIGINT) reaches as a whole
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
branch="${1:-$(git -C "$repo" rev-parse --abbrev-ref HEAD)}"
scratch="$(mktemp -d /tmp/armor-cold-XXXXXX)"
node=""
cleanup() {
  if [ -n "$node" ] && kill -0 "$node" 2>/dev/null; then stop_node; fi
  (cd "$scratch/clone" 2>/dev/null && source install/setup.bash 2>/dev/null \
    && python -c 'from armor_client.cli import call_relay; call_relay.stop()' 2>/dev/null) || true
  rm -rf "$scratch"
}
trap cleanup EXIT

mkdir -p "$scratch/home" "$scratch/pip" "$scratch/npm" "$scratch/m2"
export HOME="$scratch/home" XDG_CACHE_HOME="$scratch/home/.cache" PIP_CACHE_DIR="$scratch/pip"
export npm_config_cache="$scratch/npm" MAVEN_OPTS="-Dmaven.repo.local=$scratch/m2"
# A domain and a port nobody uses (the tests' rule: a bound RTPS port means taken).
domain=$(python3 - <<'EOF'
import pathlib, random
taken = set()
for table in ('/proc/net/udp', '/proc/net/udp6'):
    for line in pathlib.Path(table).read_text().splitlines()[1:]:
        port = int(line.split()[1].rsplit(':', 1)[1], 16)
        if port >= 7400:
            taken.add((port - 7400) // 250)
print(random.choice([d for d in range(100, 200) if d not in taken]))
EOF
)
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_DOMAIN_ID="$domain"

git clone -q --branch "$branch" "$repo" "$scratch/clone"
cd "$scratch/clone"

# run_until_ready LOG: make run in the background until its node says ARMOR ready; its wall
# time goes to $ready_s. The node stays up (process group $node). Not in $(...): $node is needed.
run_until_ready() {
  local started=$EPOCHREALTIME
  : > "$1"
  make run WEB_PORT="$port" > "$1" 2>&1 &
  node=$!
  until grep -q 'ARMOR ready' "$1"; do
    kill -0 "$node" 2>/dev/null || { cat "$1"; echo "cold_start: make run ended before ARMOR ready" >&2; exit 1; }
    sleep 0.1
  done
  ready_s=$(awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
}
first_call() {
  local started=$EPOCHREALTIME
  (source install/setup.bash && armor call robotics QUERY IND CLASS -- Room > "$1" 2>&1)
  awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }'
}
# Ctrl-C as a user would; SIGTERM after 15 s where SIGINT is ignored (a script started in the
# background by a non-interactive shell inherits SIGINT ignored, and the node keeps it so).
stop_node() {
  kill -INT -- "-$node"
  for _ in $(seq 150); do kill -0 "$node" 2>/dev/null || break; sleep 0.1; done
  kill -TERM -- "-$node" 2>/dev/null || true
  wait "$node" || true; node=""
}

echo "cold_start: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start"
run_until_ready "$scratch/cold.log"; cold=$ready_s
sleep 3  # a user switching to another terminal
call=$(first_call "$scratch/call.log")
stop_node
echo "cold: set-up steps (as make run printed them):"
grep -E '^[a-z_]+: .* in [0-9.]+ s( \([0-9.]+ CPU-s\))?$|^setup: done' "$scratch/cold.log" | sed 's/^/  /'
echo "cold: set-up steps' CPU time in all: $(sed -n 's/.* (\([0-9.]*\) CPU-s)$/\1/p' "$scratch/cold.log" \
  | awk '{ t += $1 } END { printf "%.1f", t }') CPU-s on $(nproc) cores"
echo "cold: \"ARMOR ready\" after $cold s; first armor call 3 s after it: $call s"
sed 's/^/  | /' "$scratch/call.log"
(source install/setup.bash && python -c 'from armor_client.cli import call_relay; call_relay.stop()')
run_until_ready "$scratch/warm.log"; warm=$ready_s
call=$(first_call "$scratch/call.log")
stop_node
echo "warm: $(grep '^setup: done' "$scratch/warm.log"); \"ARMOR ready\" after $warm s; first armor call right after it: $call s"
echo "cold_start: load average $(cut -d' ' -f1-3 /proc/loadavg) at the end"
