#!/usr/bin/env bash
# The ladder's throughput and its overhead against `tournament` for the same matches: one-minute
# ball-grab between two user strategies (sources), N matches, one match at a time.
#   bash benchmarks/ladder-vs-tournament.sh [N]        # N even, default 40
# Builds the server in Release, then times (wall clock, each from its process start):
#   tournament: `tournament --seeds N/2 --threads 1` (both sides of each seed), compiling included;
#   ladder:     `ladder serve --workers 1`, two teams added and their sources submitted (compiled and
#               checked), until N ranked matches are written.
# Prints both times, matches per hour and the ladder's overhead per match.
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-40}
dotnet build src/URWPGSim2D.Server -c Release -v q --nologo >/dev/null
server=src/URWPGSim2D.Server/bin/Release/net10.0/URWPGSim2D.Server.dll
work=$(mktemp -d)
trap 'kill "${pid:-0}" 2>/dev/null || true; rm -rf "$work"' EXIT
source benchmarks/ladder-common.sh
write_strategies "$work"

now() { date +%s.%N; }

start=$(now)
dotnet "$server" tournament --item ball-grab --minutes 1 --entrant toward="$work/toward" --entrant still="$work/still" \
  --seeds $((n / 2)) --threads 1 --out "$work/tour" >/dev/null
tournament=$(echo "$(now) - $start" | bc)

start=$(now)
serve_ladder "$server" "$work/serve" --data "$work/ladder" --workers 1
# Counted from the match list, twice a second (the standings' bootstrap is not computed meanwhile).
played() { curl -s "${url}api/matches?state=done&limit=10000" | grep -o '"id":' | wc -l; }
until [ "$(played)" -ge "$n" ]; do sleep 0.5; done
ladder=$(echo "$(now) - $start" | bc)
done_matches=$(played)
kill "$pid"; wait "$pid" 2>/dev/null || true

printf 'matches: %d (tournament), %d (ladder, when counted)\n' "$n" "$done_matches"
printf 'tournament: %.1f s, %.0f matches/hour\n' "$tournament" "$(echo "$n * 3600 / $tournament" | bc -l)"
printf 'ladder:     %.1f s, %.0f matches/hour\n' "$ladder" "$(echo "$done_matches * 3600 / $ladder" | bc -l)"
printf 'ladder overhead per match: %.0f ms (%.0f %%)\n' "$(echo "($ladder / $done_matches - $tournament / $n) * 1000" | bc -l)" \
  "$(echo "(($ladder / $done_matches) / ($tournament / $n) - 1) * 100" | bc -l)"
