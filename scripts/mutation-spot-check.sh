#!/usr/bin/env bash
# A mutation spot-check of the server: applies each mutation below alone (a constant, a sign, an
# off-by-one in the response, the rules, the referees, locomotion, the built-in strategy),
# rebuilds the server, runs the server tests that could see it, and counts the mutations the
# tests catch (some test fails) and those they miss. The sources are restored after each one.
# Not part of CI (about 40 s per mutation on a quiet machine). How to read it: docs/development.md.
#   bash scripts/mutation-spot-check.sh                # every mutation
#   bash scripts/mutation-spot-check.sh M05 M17        # only these
# Run it in a clean clone (it edits src/ while it runs): git clone . /tmp/m && bash /tmp/m/scripts/mutation-spot-check.sh
set -uo pipefail
cd "$(dirname "$0")/.."
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
if [ -n "$(git status --porcelain -- src)" ]; then
  echo "mutation-spot-check: src/ has uncommitted changes; run it in a clean clone" >&2
  exit 2
fi

S=src/URWPGSim2D.Server
PC=$S/Simulation/PhysicsConstants.cs
CR=$S/Simulation/ContactResponse.cs
IM=$S/Simulation/Impulse.cs
# id ~ file ~ exact text (must occur once) ~ replacement ~ what it breaks
mutations=$(cat <<EOF
M01~$PC~FishMass = 0.8f~FishMass = 0.9f~fish mass
M02~$PC~BallMass = 0.49f~BallMass = 0.55f~ball mass
M03~$PC~FishInertia = 6000f~FishInertia = 4000f~fish moment of inertia
M04~$PC~TurnImpulseSeconds = 0.01f~TurnImpulseSeconds = 0.02f~turning impulse time
M05~$PC~FishBallRestitution = -0.005f~FishBallRestitution = -0.05f~fish–ball restitution
M06~$PC~FishFishRestitution = -0.005f~FishFishRestitution = -0.05f~fish–fish restitution
M07~$PC~RestitutionReach = 300f~RestitutionReach = 200f~restitution reach along the fish
M08~$PC~BallBallRestitution = 0.005f~BallBallRestitution = 0.5f~ball–ball restitution
M09~$PC~BallWallFactor = -0.001f~BallWallFactor = -0.1f~ball–wall factor
M10~$PC~BallObstacleFactor = -0.1f~BallObstacleFactor = -0.3f~ball–obstacle factor
M11~$PC~FishObstacleFactor = -0.003f~FishObstacleFactor = -0.03f~fish–obstacle factor
M12~$PC~PectoralBallShare = 0.75f~PectoralBallShare = 0.5f~pectoral-fin share of the correction
M13~$PC~MinimumTurningSpeed = 2f~MinimumTurningSpeed = 20f~minimum speed to turn
M14~$PC~SeparationMargin = 0.01f~SeparationMargin = 1f~separation margin
M15~$PC~MaximumCorrectionsPerFish = 8;~MaximumCorrectionsPerFish = 1;~corrections before a fish is wedged
M16~$CR~Turn(a, ra, PhysicsConstants.FishMass~Turn(a, ra, -PhysicsConstants.FishMass~sign of fish A's fish–fish turning impulse
M17~$CR~Turn(fish, lever, -PhysicsConstants.BallMass~Turn(fish, lever, PhysicsConstants.BallMass~sign of the fish–ball turning impulse
M18~$CR~Turn(fish, lever, PhysicsConstants.FishMass * (after - vn) * n)~Turn(fish, lever, -PhysicsConstants.FishMass * (after - vn) * n)~sign of the fish–obstacle turning impulse
M19~$CR~pectoral ? PhysicsConstants.PectoralBallShare : 0.5f~pectoral ? PhysicsConstants.PectoralBallShare : 0.25f~ball's share of a non-pectoral correction
M20~$CR~float common = vb + (ballShare * (vf - vb));~float common = vb + ((1f - ballShare) * (vf - vb));~pressing contact common speed
M21~$CR~fish.HeadReach - Vector2.Dot(point - fish.Position, fish.Forward)~fish.HeadReach + Vector2.Dot(point - fish.Position, fish.Forward)~axis distance from the head tip
M22~$CR~bool border = pair.Kind == PairKind.FishWall || _world.Statics[pair.B].IsGoalBlock;~bool border = pair.Kind == PairKind.FishWall;~a goal block is a border for fish
M23~$CR~float factor = border ? PhysicsConstants.BallWallFactor : PhysicsConstants.BallObstacleFactor;~float factor = border ? PhysicsConstants.BallObstacleFactor : PhysicsConstants.BallWallFactor;~ball wall/obstacle factors swapped
M24~$CR~if (count == PartnersPerFish)~if (count == PartnersPerFish - 7)~first contact per partner and cycle (partners recorded)
M25~$CR~float after = border ? 0f :~float after = border ? -0.5f * vn :~fish–wall normal speed becomes 0
M26~$IM~(restitution * (v2 - v1))~(restitution * (v1 - v2))~sign of e in the exchange
M27~$IM~omega * new Vector2(-r.Y, r.X)~omega * new Vector2(r.Y, -r.X)~point velocity of a turning fish
M28~$S/Simulation/Rules.cs~side > 0 ? 0 : 1~side > 0 ? 1 : 0~which team a goal counts for
M29~$S/Simulation/Rules.cs~b.Velocity = Vector2.Zero;~b.Velocity = b.Velocity;~a scored ball stops
M30~$S/Simulation/Kinematics/BallMotion.cs~speed >= 100f ? 250f~speed >= 100f ? 200f~ball deceleration
M31~$S/Simulation/Locomotion.cs~(v * v / 500000f)~(v * v / 50000f)~heading noise amplitude
M32~$S/Hosting/ChaseBallStrategy.cs~int tcode = 7 + (int)MathF.Round~int tcode = 7 - (int)MathF.Round~chase-ball turns toward its aim
M33~$S/Hosting/ChaseBallStrategy.cs~if (++_still[k] < StuckCycles)~if (++_still[k] <= StuckCycles)~chase-ball stuck detection off by one
M34~$S/Items/BallGrab/BallGrabReferee.cs~if (Scores[team] == 0)~if (Scores[team] != 0)~ball-grab first-score cycle
M35~$S/Items/BallGrab/BallGrabReferee.cs~new MatchOutcome(a < b ? 0 : 1~new MatchOutcome(a > b ? 0 : 1~ball-grab tie-break by earlier first score
M36~$S/Items/BallGrab/BallGrabReferee.cs~Placement.Place(b, -b.Position);~Placement.Place(b, b.Position);~ball-grab balls mirrored at half time
M37~$S/Simulation/Separation.cs~Offset(pair, mtv * shareA, -mtv * shareB);~Offset(pair, mtv * shareB, -mtv * shareA);~correction shares swapped
EOF
)

# The tests that can see a server mutation: every server test but the slow batch, Slurm, process
# and viewer tests (they play the same engine through the command line), the brute-force motion
# audits (MotionGuaranteeTests: a minute of their own) and the allocation tests. Release build: a
# match plays about five times faster than in Debug.
filter='(FullyQualifiedName~URWPGSim2D.Server.Tests.Simulation|FullyQualifiedName~URWPGSim2D.Server.Tests.Items|FullyQualifiedName~URWPGSim2D.Server.Tests.Hosting|FullyQualifiedName~URWPGSim2D.Server.Tests.Docs|FullyQualifiedName~URWPGSim2D.Server.Tests.Scenario|FullyQualifiedName~RunCommandTests|FullyQualifiedName~BatchSummaryTests)&FullyQualifiedName!~MotionGuaranteeTests&FullyQualifiedName!~AllocationTests'

dotnet build tests/URWPGSim2D.Server.Tests -c Release -v q -nologo >/dev/null 2>&1 || { echo "mutation-spot-check: the unmutated build fails" >&2; exit 1; }
bin=tests/URWPGSim2D.Server.Tests/bin/Release/net10.0
caught=0 missed=0 total=0
results=$(mktemp)
while IFS='~' read -r id file from to what; do
  [ -n "$id" ] || continue
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx "$id"; then continue; fi
  n=$(grep -cF -- "$from" "$file" || true)
  if [ "$n" -ne 1 ]; then
    echo "$id  SKIPPED  ($what: the text occurs $n times in $file)"
    continue
  fi
  FROM="$from" TO="$to" python3 -c 'import os,sys; p=sys.argv[1]; s=open(p).read(); open(p,"w").write(s.replace(os.environ["FROM"], os.environ["TO"], 1))' "$file"
  total=$((total + 1))
  if ! dotnet build "$S" -c Release -v q -nologo --no-dependencies >/dev/null 2>&1; then
    verdict="BUILD-FAIL"
  else
    cp "$S/bin/Release/net10.0/URWPGSim2D.Server.dll" "$bin/"
    out=$(dotnet test tests/URWPGSim2D.Server.Tests -c Release --no-build --filter "$filter" 2>&1)
    if [ $? -ne 0 ]; then
      verdict="caught"; caught=$((caught + 1))
      by=$(grep -Eo '^\s+Failed [A-Za-z0-9_.]+' <<<"$out" | awk '{print $2}' | sed -E 's/.*\.([A-Za-z0-9_]+\.[A-Za-z0-9_]+)$/\1/' | sort -u | head -3 | paste -sd, -)
    else
      verdict="MISSED"; missed=$((missed + 1)); by=""
    fi
  fi
  git checkout -q -- "$file"
  printf '%s  %-10s %s%s\n' "$id" "$verdict" "$what" "${by:+  (by $by)}" | tee -a "$results"
done <<<"$mutations"
# Leave the tests' copy of the server unmutated.
dotnet build "$S" -c Release -v q -nologo --no-dependencies >/dev/null 2>&1 && cp "$S/bin/Release/net10.0/URWPGSim2D.Server.dll" "$bin/"
echo "mutations: $total, caught: $caught, missed: $missed"
rm -f "$results"
