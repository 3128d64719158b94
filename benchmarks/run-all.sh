#!/usr/bin/env bash
# Reproduces every figure of docs/performance.md on this machine:
#   1. the whole BenchmarkDotNet suite (short job: 3 warm-up and 3 measured iterations per case),
#      which also draws docs/figures/scaling.svg from the scaling and broad-phase results;
#   2. the batch speed-up from the command line (16 default matches on 1 and on 2 threads);
#   3. the default match end to end (the README's main job).
# The whole suite takes about an hour on 2 cores. Arguments go to BenchmarkDotNet instead of
# --filter '*' (e.g. --filter '*Scaling*' to run part of it).
# The tracked figure docs/figures/scaling.svg is replaced only with --update-figures (first
# argument); otherwise the plot of a whole run goes to benchmarks/artifacts/scaling.svg.
# Results: benchmarks/artifacts/results/*-report.{csv,md} (BenchmarkDotNet's tables) and
# benchmarks/last-run.txt (everything printed). Both are git-ignored.
set -euo pipefail
cd "$(dirname "$0")/.."
log=benchmarks/last-run.txt
plot=benchmarks/artifacts/scaling.svg
if [ "${1:-}" = "--update-figures" ]; then
  plot=docs/figures/scaling.svg
  shift
fi
mkdir -p benchmarks/artifacts
{
  echo "# $(date -u +%FT%TZ) on $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs), $(dotnet --version)"
  args=("$@")
  [ "${#args[@]}" -eq 0 ] && args=(--filter '*')
  # The plot needs the scaling results: drawn for the whole suite or with --update-figures only.
  plotting=()
  [ "$#" -eq 0 ] || [ "$plot" = docs/figures/scaling.svg ] && plotting=(--plot "$plot")
  dotnet run -c Release --project benchmarks/URWPGSim2D.Collision.Benchmarks -- \
    --job short --artifacts benchmarks/artifacts "${plotting[@]}" "${args[@]}"
  server=(dotnet run -c Release --project src/URWPGSim2D.Server --)
  for threads in 1 2; do
    echo "## run --batch 16 --threads $threads"
    "${server[@]}" run --batch 16 --threads "$threads" | tail -1
  done
  echo "## the default match (run)"
  "${server[@]}" run
} 2>&1 | tee "$log"
