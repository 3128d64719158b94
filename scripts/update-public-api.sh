#!/usr/bin/env bash
# Brings the public API files of the packed libraries (PublicAPI.Shipped.txt and
# PublicAPI.Unshipped.txt beside each .csproj, read by Microsoft.CodeAnalysis.PublicApiAnalyzers)
# up to date with the code, using the analyzer's own code fixes:
#   RS0016 (a public symbol missing from the files) adds it to PublicAPI.Unshipped.txt,
#   RS0017 (a listed symbol no longer in the code) removes it (from Shipped: marks it *REMOVED*).
# Then sorts each file (the "#nullable enable" line first) so diffs stay small.
#   bash scripts/update-public-api.sh          # after adding/removing public API: review the diff
#   bash scripts/update-public-api.sh --ship   # at a release: move Unshipped into Shipped
# See docs/packaging.md ("Public API").
set -euo pipefail
cd "$(dirname "$0")/.."
projects=(src/URWPGSim2D.Collision src/URWPGSim2D.Strategies src/URWPGSim2D.Compat src/URWPGSim2D.Engine)

count() { grep -vc '^#nullable' "$1" || true; }

sort_api() {
  local file=$1 body
  body=$(grep -v '^#nullable enable$' "$file" | grep -v '^$' | LC_ALL=C sort -u || true)
  { echo '#nullable enable'; if [ -n "$body" ]; then printf '%s\n' "$body"; fi; } > "$file"
}

if [ "${1:-}" = "--ship" ]; then
  for p in "${projects[@]}"; do
    shipped=$p/PublicAPI.Shipped.txt unshipped=$p/PublicAPI.Unshipped.txt
    # A "*REMOVED*X" line in Unshipped deletes X from Shipped; every other line moves over.
    removed=$(grep '^\*REMOVED\*' "$unshipped" | sed 's/^\*REMOVED\*//' || true)
    added=$(grep -v '^#nullable enable$' "$unshipped" | grep -v '^\*REMOVED\*' | grep -v '^$' || true)
    { grep -vxF -f <(printf '%s\n' "$removed") "$shipped" || true; printf '%s\n' "$added"; } > "$shipped.new"
    mv "$shipped.new" "$shipped"
    echo '#nullable enable' > "$unshipped"
    sort_api "$shipped"
    echo "$p: $(count "$shipped") shipped symbols"
  done
  exit 0
fi

for p in "${projects[@]}"; do
  csproj=$(ls "$p"/*.csproj)
  # The fixes only apply to diagnostics at or above the given severity; RS0016/RS0017 are warnings.
  dotnet format analyzers "$csproj" --diagnostics RS0016 RS0017 --severity info -v q
  sort_api "$p/PublicAPI.Shipped.txt"
  sort_api "$p/PublicAPI.Unshipped.txt"
  echo "$p: $(count "$p/PublicAPI.Shipped.txt") shipped, $(count "$p/PublicAPI.Unshipped.txt") unshipped symbols"
done
