#!/usr/bin/env bash
# The default match (4 fish, 9 balls, 4 obstacles, goal blocks, walls, every fish on chase-ball)
# against one chase-ball fish and one ball in the same pool (benchmarks/one-fish.json), CYCLES
# cycles each (30,000 unless set), Release, in ROUNDS interleaved rounds (5 unless set). Each
# figure is the match summary's "us per cycle" (wall clock from the first cycle to the last: the
# methods compiled while the match plays are included, about 0.15 s; more cycles spread them
# thinner). Prints every round, the medians, the median of the rounds' ratios and the load
# average. From the project's root:
#   bash benchmarks/few-bodies.sh
#   CYCLES=200000 ROUNDS=3 bash benchmarks/few-bodies.sh   # the cost of a cycle once compiled
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${ROUNDS:-5}
CYCLES=${CYCLES:-30000}
[[ "$CYCLES" =~ ^[1-9][0-9]*$ ]] || { echo "few-bodies.sh: CYCLES must be a positive whole number, got '$CYCLES'" >&2; exit 2; }
dotnet build -c Release src/URWPGSim2D.Server -v q --nologo > /dev/null
server=(dotnet run --no-build -c Release --project src/URWPGSim2D.Server --)
per_cycle() { "${server[@]}" "$@" | sed -n 's/.*(.*, \([0-9.]*\) us per cycle).*/\1/p'; }
echo "load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
many=() one=()
for r in $(seq 1 "$ROUNDS"); do
  many+=("$(per_cycle run --item default --cycles "$CYCLES")")
  one+=("$(per_cycle run --scenario benchmarks/one-fish.json --cycles "$CYCLES")")
  echo "round $r: default match ${many[-1]} us, one fish and one ball ${one[-1]} us per cycle"
done
echo "load at end: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "${many[*]}" "${one[*]}" <<'PY'
import statistics as st, sys
many, one = ([float(x) for x in a.split()] for a in sys.argv[1:3])
ratios = [m / o for m, o in zip(many, one)]
print(f"medians: default match {st.median(many):.1f} us, one fish and one ball {st.median(one):.1f} us a cycle; "
      f"ratio {st.median(ratios):.2f} ({min(ratios):.2f}–{max(ratios):.2f})")
PY
