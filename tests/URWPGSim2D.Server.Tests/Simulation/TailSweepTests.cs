using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// The tail's wave turned over the cycle (<see cref="World.TailSweeps"/>): each fish ends the cycle
/// with the wave's joints for its decision (or, its move rejected, the ones it began with), the
/// turning tail never lands inside anything at the start of a cycle, and nothing is left overlapping.
/// </summary>
public sealed class TailSweepTests
{
    [Fact]
    public void EachFishEndsTheCycleWithTheWavesJointsAndNothingIsLeftOverlapping()
    {
        var match = MatchBuilder.Build(DefaultScenario.Load(), seed: 1UL);
        match.World.TailSweeps = true;
        FishState[] fish = match.World.Fish;
        var before = new FishPose[fish.Length];
        int deepAtStart = 0;
        for (int cycle = 1; cycle <= 300; cycle++)
        {
            for (int i = 0; i < fish.Length; i++)
            {
                before[i] = fish[i].Pose;
            }

            match.Step();
            for (int i = 0; i < fish.Length; i++)
            {
                FishState f = fish[i];
                FishPose pose = f.Pose;
                if (match.World.Motion.WasRejected(f.Handle))
                {
                    Assert.Equal((before[i].Joint1, before[i].Joint2, before[i].Joint3), (pose.Joint1, pose.Joint2, pose.Joint3));
                    continue;
                }

                Decision d = f.Decision;
                double end = cycle * 0.1;
                Assert.Equal(TailWave.JointAngle(0, d.VCode, d.TCode, end, f.TailPhase), pose.Joint1);
                Assert.Equal(TailWave.JointAngle(1, d.VCode, d.TCode, end, f.TailPhase), pose.Joint2);
                Assert.Equal(TailWave.JointAngle(2, d.VCode, d.TCode, end, f.TailPhase), pose.Joint3);
            }

            foreach (ContactRecord contact in match.Contacts.Cycle)
            {
                deepAtStart += contact.Time == 0.0 && contact.Mtv.Length() > MotionTolerances.TimeOfImpactTolerance ? 1 : 0;
            }

            Assert.True(match.Motion.LeftoverOverlap <= 1f, $"cycle {cycle}: {match.Motion.LeftoverOverlap} mm left");
            if (cycle % 25 == 0)
            {
                float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
                Assert.True(deepest <= 1f, $"cycle {cycle}: {where} overlaps {deepest} mm");
            }
        }

        Assert.Equal(0, deepAtStart);
    }

    [Fact]
    public void WithTheTailSetAtTheStartOfACycleItLandsInsideOthers()
    {
        // The same match with the wave's joints set at once: the new tail is found overlapping at
        // time 0 (what the sweep removes), so the check above is not empty.
        var match = MatchBuilder.Build(DefaultScenario.Load(), seed: 1UL);
        int deepAtStart = 0;
        for (int cycle = 1; cycle <= 300; cycle++)
        {
            match.Step();
            foreach (ContactRecord contact in match.Contacts.Cycle)
            {
                deepAtStart += contact.Time == 0.0 && contact.Mtv.Length() > MotionTolerances.TimeOfImpactTolerance ? 1 : 0;
            }
        }

        Assert.True(deepAtStart > 0);
    }

    [Fact]
    public void TheSweptTailGivesTheSameMatchFromRunToRun()
    {
        static Vector2[] Play()
        {
            var match = MatchBuilder.Build(DefaultScenario.Load(), seed: 3UL);
            match.World.TailSweeps = true;
            for (int cycle = 0; cycle < 200; cycle++)
            {
                match.Step();
            }

            return [.. match.World.Fish.Select(f => f.Position), .. match.World.Balls.Select(b => b.Position)];
        }

        Assert.Equal(Play(), Play());
    }
}
