#!/usr/bin/env bash
# Rewrites every command output shown in README.md and docs/ with the real output of the current
# build, and redraws the committed figures from their inputs. Run it after changing what a command
# prints, then review `git diff` (timing figures change on every run; the tests ignore them).
#   bash scripts/regenerate-docs-outputs.sh               # transcripts and render figures
#   bash scripts/regenerate-docs-outputs.sh --screenshot  # also docs/figures/match.png and ladder-standings.png
#                                                         # (Chromium: ScreenshotForTheReadme, the ladder's PageTests)
# The same test (DocsOutputsTests) fails in CI when a shown output is stale.
set -euo pipefail
cd "$(dirname "$0")/.."
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
# 1. The transcripts: the docs test in its regenerate mode writes what each command prints (Release
#    build, so the timing figures shown are those of the optimised program).
URWPGSIM2D_REGENERATE_DOCS=1 dotnet test tests/URWPGSim2D.Server.Tests -c Release --filter 'FullyQualifiedName~DocsOutputsTests' \
  --logger 'console;verbosity=minimal'
# 2. The figures drawn by render (.ci/smoke checks that they are what render makes).
for json in docs/figures/fish-tree.json docs/figures/fish-ball-contact.json; do
  dotnet run -c Release --project src/URWPGSim2D.Server -- render "$json" --svg "${json%.json}.svg"
done
# 3. Only when asked: the README's screenshot of the replay page (the test writes it to a temporary
#    folder otherwise; a screenshot can differ by a few pixels between machines' fonts).
if [ "${1:-}" = "--screenshot" ]; then
  bash .ci/install-chromium
  URWPGSIM2D_REGENERATE_DOCS=1 dotnet test tests/URWPGSim2D.Server.Viewer.Tests --filter 'FullyQualifiedName~Screenshot' \
    --logger 'console;verbosity=minimal'
  # and the README's picture of the ladder's standings (docs/figures/ladder-standings.png)
  URWPGSIM2D_REGENERATE_DOCS=1 dotnet test tests/URWPGSim2D.Ladder.Tests --filter 'FullyQualifiedName~PageTests' \
    --logger 'console;verbosity=minimal'
fi
git --no-pager diff --stat -- README.md docs
