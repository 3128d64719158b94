#!/usr/bin/env bash
# The ladder's matches per hour with worker processes: one-minute ball-grab between two user
# strategies (sources), on a PostgreSQL server of its own (a new cluster in a temporary folder, on a
# Unix socket; PostgreSQL's programs from /usr/lib/postgresql, as .ci/install-postgresql installs them).
#   bash benchmarks/ladder-workers.sh [N] [K...]      # N matches (default 40) with K worker processes (default: 1 then 2)
# For each K: `ladder serve --workers 0` on a new database, two teams added and their sources
# submitted, then K `ladder worker` processes (one match at a time each, each with its own data
# folder, as on other machines) until N matches are written. Prints, per K, the wall time from the
# workers' start to the N-th match, and the steady rate: matches finished between the first and the
# N-th finished match, per hour of the time between them (the workers' start and first compile left out).
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-40}
shift || true
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(1 2)
dotnet build src/URWPGSim2D.Server -c Release -v q --nologo >/dev/null
server=$PWD/src/URWPGSim2D.Server/bin/Release/net10.0/URWPGSim2D.Server.dll
pgbin=$(ls -d /usr/lib/postgresql/*/bin | sort -V | tail -1)

# As root, PostgreSQL's programs run as the user postgres (initdb refuses root).
as_pg() { if [ "$(id -u)" = 0 ]; then setpriv --reuid=postgres --regid=postgres --init-groups -- "$@"; else "$@"; fi; }

work=$(mktemp -d)
pg=$(as_pg mktemp -d /tmp/urwpg-bench-pg-XXXXXX)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
  as_pg "$pgbin/pg_ctl" -D "$pg/data" -m fast -w stop >/dev/null 2>&1 || true
  as_pg rm -rf "$pg"
  rm -rf "$work"
}
trap cleanup EXIT
as_pg "$pgbin/initdb" -D "$pg/data" -U postgres -A trust -E UTF8 --locale=C >/dev/null
as_pg "$pgbin/pg_ctl" -D "$pg/data" -l "$pg/server.log" -w -o "-k $pg -p 5432 -c listen_addresses='' -c max_connections=200" start >/dev/null

source benchmarks/ladder-common.sh
write_strategies "$work"
now() { date +%s.%N; }

for k in "${counts[@]}"; do
  as_pg "$pgbin/createdb" -h "$pg" -p 5432 -U postgres "ladder_$k"
  db="Host=$pg;Port=5432;Username=postgres;Database=ladder_$k"
  serve_ladder "$server" "$work/serve-$k" --data "$work/serve-$k" --database "$db" --workers 0
  serve=$pid
  pids+=("$serve")

  start=$(now)
  workers=()
  for w in $(seq 1 "$k"); do
    dotnet "$server" ladder worker --database "$db" --data "$work/worker-$k-$w" >"$work/worker-$k-$w.out" 2>&1 &
    workers+=("$!")
    pids+=("$!")
  done

  done_json() { curl -s "${url}api/matches?state=done&limit=10000"; }
  until [ "$(done_json | jq '.matches | length')" -ge "$n" ]; do sleep 0.5; done
  wall=$(echo "$(now) - $start" | bc)
  # The steady rate, from the matches' own finishing times (the N first finished).
  rate=$(done_json | jq -r --argjson n "$n" '[.matches[].finished | (.[0:19] + "Z" | fromdateiso8601) + ("0." + .[20:-1] | tonumber)] | sort | .[:$n] | (($n - 1) * 3600 / (.[-1] - .[0]))')
  for p in "${workers[@]}" "$serve"; do kill "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; done
  printf '%d worker process(es): %d matches in %.1f s from the workers'"'"' start; steady %.0f matches/hour\n' "$k" "$n" "$wall" "$rate"
done
