#!/usr/bin/env bash
# The sources the benchmarks' frozen baseline is compiled from: a git worktree of the commit
# tagged `benchmark-baseline`, checked out (detached) under
# benchmarks/URWPGSim2D.Collision.Benchmarks.Baseline/tagged (git-ignored). Idempotent and safe
# to run twice at once (a lock): a worktree already at the tagged commit is kept. The baseline
# projects run this before they compile; run it by hand to look at the frozen code. Fails with one
# line when the commit is missing (a shallow clone).
set -euo pipefail
tag=benchmark-baseline
# The tagged commit, pinned: it is an ancestor of main, so every full clone has it, with or
# without its tags.
pinned=ad2603e1e96cb122f6aeefa0391182ab562aa260
root=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
dir="$root/benchmarks/URWPGSim2D.Collision.Benchmarks.Baseline/tagged"
if tagged=$(git -C "$root" rev-parse -q --verify "refs/tags/$tag^{commit}") && [ "$tagged" != "$pinned" ]; then
  echo "benchmark baseline: the git tag '$tag' points at $tagged, not at the pinned commit $pinned" >&2
  exit 1
fi
commit=$pinned
if ! git -C "$root" cat-file -e "$commit^{commit}" 2>/dev/null; then
  echo "benchmark baseline: commit $commit (tag '$tag') is missing from this clone (a shallow clone? git fetch --unshallow); the benchmarks compile their frozen baseline from it" >&2
  exit 1
fi
exec 9>"$root/benchmarks/URWPGSim2D.Collision.Benchmarks.Baseline/.tagged.lock"
flock 9
# Only the tagged src/ is compiled. The tagged benchmarks/ folder goes: BenchmarkDotNet looks for
# its project by name under the clone and fails on a second URWPGSim2D.Collision.Benchmarks.csproj.
if [ -e "$dir/.git" ] && [ "$(git -C "$dir" rev-parse HEAD 2>/dev/null)" = "$commit" ]; then
  rm -rf "$dir/benchmarks"
  exit 0
fi
rm -rf "$dir"
git -C "$root" worktree prune
git -C "$root" worktree add --detach --quiet "$dir" "$commit"
rm -rf "$dir/benchmarks"
