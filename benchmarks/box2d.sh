#!/usr/bin/env bash
# The project side by side with Box2D v3 (C, -O3, AVX2): identical pairs and crowd scenes,
# interleaved in one run, through the side-by-side harness kept beside the project (by default
# ../shared/peers/box2d: its run.sh, C and C# sources and Box2D's source), then the crowd again
# by each thread's CPU time. From the project's root:
#
#   bash benchmarks/box2d.sh                              # about 10 minutes on 2 cores
#   ROUNDS=3 SCALE_ROUNDS=3 CPU_ROUNDS=3 bash benchmarks/box2d.sh   # quicker, noisier
#   HARNESS_RUN=0 bash benchmarks/box2d.sh                # only the thread-CPU crowd, reusing $BUILD
#
# The harness is copied into a temporary folder (Box2D's source is not: BOX2D_SRC points at it),
# its C# side's reflection is pointed at where the crowd scene, the match builder and the speed
# and turn tables are now, and it runs with the same environment (ROUNDS, SCALE_ROUNDS, PASSES,
# WARM, MEASURE, BUILD, RUN_BDN). Its crowd tables time the wall clock. The thread-CPU crowd:
# benchmarks/URWPGSim2D.CrowdCpu (a whole cycle of `run --crowd N`) and benchmarks/box2d/crowd_cpu.c
# (a Box2D step of the same scene, built against the harness's Box2D library), CPU_ROUNDS
# interleaved rounds of WARM cycles then MEASURE timed ones.
# Results in $BUILD/results: pairs.md, scale.md (wall clock), crowd-cpu.md (thread CPU time).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT"
HARNESS=${HARNESS:-$ROOT/../shared/peers/box2d}
export BOX2D_SRC=${BOX2D_SRC:-$HARNESS/box2d-v3}
export BUILD=${BUILD:-/tmp/peer-build}
export PROJ=$ROOT
export WARM=${WARM:-20} MEASURE=${MEASURE:-50}
CPU_ROUNDS=${CPU_ROUNDS:-7}
HARNESS_RUN=${HARNESS_RUN:-1}
OUT=$BUILD/results

if [ "$HARNESS_RUN" = 1 ]; then
  for f in run.sh analyze.py c cs; do
    [ -e "$HARNESS/$f" ] || { echo "box2d.sh: no side-by-side harness at $HARNESS (set HARNESS=FOLDER)" >&2; exit 2; }
  done
  [ -f "$BOX2D_SRC/CMakeLists.txt" ] || { echo "box2d.sh: no Box2D source at $BOX2D_SRC (set BOX2D_SRC=FOLDER)" >&2; exit 2; }
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$HARNESS/run.sh" "$HARNESS/analyze.py" "$HARNESS/c" "$HARNESS/cs" "$copy/"
  chmod -R u+w "$copy"
  # Where the harness's reflection finds the project's types today.
  sed -i \
    -e 's/Assembly\.Load("URWPGSim2D\.Server")/Assembly.Load("URWPGSim2D.Engine")/' \
    -e 's/Server\.GetType("URWPGSim2D\.Server\.Scenario\.MatchBuilder"/Assembly.Load("URWPGSim2D.Hosting").GetType("URWPGSim2D.Hosting.MatchBuilder"/' \
    -e 's/URWPGSim2D\.Server\.Scenario\.CrowdScenario/URWPGSim2D.Engine.Scenario.CrowdScenario/' \
    -e 's/URWPGSim2D\.Server\.Simulation\.Kinematics\./URWPGSim2D.Engine.Simulation.Kinematics./g' \
    "$copy/cs/Program.cs"
  if grep -n '"URWPGSim2D\.Server[."]' "$copy/cs/Program.cs" >&2; then
    echo "box2d.sh: the harness names types this script does not know how to point at (above)" >&2
    exit 1
  fi
  bash "$copy/run.sh"
fi

# ---------------- the crowd by thread CPU time ----------------
[ -f "$BUILD/box2d/src/libbox2d.a" ] && [ -f "$BUILD/scene_1000.txt" ] && [ -f "$BUILD/scene_10000.txt" ] || {
  echo "box2d.sh: $BUILD holds no Box2D library or crowd scenes: run with HARNESS_RUN=1 first" >&2; exit 2; }
mkdir -p "$OUT"
gcc -O2 -std=c17 -Wall -Wextra -I"$BOX2D_SRC/include" benchmarks/box2d/crowd_cpu.c "$BUILD/box2d/src/libbox2d.a" -lm -lpthread -o "$BUILD/crowd_cpu"
dotnet build -c Release benchmarks/URWPGSim2D.CrowdCpu -o "$BUILD/crowd-cpu-bin" -v q --nologo > "$OUT/crowd-cpu-build.txt"
echo "load at start: $(cat /proc/loadavg)" > "$OUT/crowd-cpu.txt"
for r in $(seq 1 "$CPU_ROUNDS"); do
  echo "[$(date +%H:%M:%S)] thread-CPU crowd round $r"
  for n in 1000 10000; do
    echo "round $r $("$BUILD/crowd_cpu" "$BUILD/scene_$n.txt" "$WARM" "$MEASURE")" >> "$OUT/crowd-cpu.txt"
  done
  dotnet "$BUILD/crowd-cpu-bin/URWPGSim2D.CrowdCpu.dll" 1000,10000 "$WARM" "$MEASURE" | sed "s/^/round $r /" >> "$OUT/crowd-cpu.txt"
done
echo "load at end: $(cat /proc/loadavg)" >> "$OUT/crowd-cpu.txt"
python3 - "$OUT/crowd-cpu.txt" > "$OUT/crowd-cpu.md" <<'PY'
import statistics as st, sys
ours, b2 = {}, {}
for line in open(sys.argv[1]):
    t = line.split()
    if len(t) == 6 and t[0] == "round":
        side = b2 if t[2] == "b2crowd" else ours
        side.setdefault(int(t[3]), {})[int(t[1])] = float(t[4])
def span(v): return f"{st.median(v):.2f} ({min(v):.2f}–{max(v):.2f})"
rounds = sorted(set(ours[1000]) & set(b2[1000]) & set(ours[10000]) & set(b2[10000]))
print(f"Crowd scene, thread CPU time (ms), medians of {len(rounds)} interleaved rounds; "
      "ratio = the project's cycle / Box2D's step, the median of the rounds' ratios (min–max):\n")
print("| bodies | Box2D step | project cycle | ratio |")
print("| ---: | ---: | ---: | ---: |")
for n in (1000, 10000):
    print(f"| {n:,} | {st.median(b2[n][r] for r in rounds):.3f} | {st.median(ours[n][r] for r in rounds):.3f} | "
          + span([ours[n][r] / b2[n][r] for r in rounds]) + " |")
print()
print("From 1,000 to 10,000 bodies (the rounds' ratios, median (min–max)): project "
      + span([ours[10000][r] / ours[1000][r] for r in rounds]) + "×, Box2D "
      + span([b2[10000][r] / b2[1000][r] for r in rounds]) + "×")
PY
grep '^load' "$OUT/crowd-cpu.txt"
cat "$OUT/crowd-cpu.md"
