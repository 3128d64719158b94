using URWPGSim2D.Engine.Matches;
using Xunit.Abstractions;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// The motion guarantee: after every cycle no two bodies overlap by more than 0.5 mm (walls
/// included), checked by an independent brute-force audit (<see cref="OverlapAudit"/>: every
/// fish leaf polygon and ball against everything, the library's plain shape tests) of every cycle
/// of random scenes (<see cref="SceneGenerator"/>) and of hand-built jams.
/// </summary>
public sealed class MotionGuaranteeTests(ITestOutputHelper output)
{
    private const float Guarantee = 0.5f;
    private const int ScenesPerBatch = 25;
    private const int Batches = 12;
    private const int Cycles = 60;

    public static TheoryData<int> BatchIndices()
    {
        var data = new TheoryData<int>();
        for (int i = 0; i < Batches; i++)
        {
            data.Add(i);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(BatchIndices))]
    public void RandomScenesNeverEndACycleOverlapping(int batch)
    {
        float worst = 0f;
        int cycles = 0;
        for (int scene = batch * ScenesPerBatch; scene < (batch + 1) * ScenesPerBatch; scene++)
        {
            Match match = SceneGenerator.Build(scene, out string json);
            for (int k = 1; k <= Cycles; k++)
            {
                match.Step();
                cycles++;
                float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
                worst = MathF.Max(worst, deepest);
                Assert.True(deepest <= Guarantee, $"scene {scene}, cycle {k}: {where} overlaps {deepest} mm\n{json}");
            }
        }

        output.WriteLine($"scenes {batch * ScenesPerBatch}-{((batch + 1) * ScenesPerBatch) - 1}: {cycles} cycles, worst overlap left {worst} mm");
    }

    [Theory]
    [InlineData("wall", "\"balls\":[{\"position\":[1390,0],\"radius\":58}]", "[1150,0]", 0.0)]
    [InlineData("goal block", "\"balls\":[{\"position\":[1290,320],\"radius\":58}]", "[1050,320]", 0.0)]
    [InlineData("obstacle", "\"balls\":[{\"position\":[300,0],\"radius\":78}],\"obstacles\":[{\"type\":\"rectangle\",\"center\":[420,0],\"length\":40,\"width\":300,\"heading\":0.3}]", "[60,0]", 0.0)]
    [InlineData("round obstacle", "\"balls\":[{\"position\":[300,0],\"radius\":38}],\"obstacles\":[{\"type\":\"round\",\"center\":[400,10],\"radius\":60}]", "[60,0]", 0.0)]
    [InlineData("corner", "\"balls\":[{\"position\":[1420,920],\"radius\":58}]", "[1200,750]", 0.6)]
    public void ABallPinnedByAFishStaysOutside(string against, string balls, string fishAt, double heading)
    {
        string json = $"{{\"fish\":[{{\"team\":0,\"position\":{fishAt},\"heading\":{heading},\"strategy\":\"fixed\",\"decision\":{{\"vcode\":15,\"tcode\":7}}}}],{balls}}}";
        Play(json, 300, against);
    }

    [Fact]
    public void ABallBetweenTwoFishStaysOutsideBoth()
    {
        Play("""
            {"fish":[{"team":0,"position":[-300,0],"heading":0,"strategy":"fixed","decision":{"vcode":15,"tcode":7}},
                     {"team":1,"position":[300,0],"heading":3.14159,"strategy":"fixed","decision":{"vcode":15,"tcode":7}}],
             "balls":[{"position":[0,0],"radius":58}]}
            """, 300, "two fish");
    }

    [Fact]
    public void SeveralFishPushingOneBallIntoACornerStayApart()
    {
        Play("""
            {"fish":[{"team":0,"position":[700,500],"heading":0.6,"strategy":"chase-ball"},
                     {"team":0,"position":[500,800],"heading":0,"strategy":"chase-ball"},
                     {"team":1,"position":[1000,200],"heading":1.5,"strategy":"chase-ball"},
                     {"team":1,"position":[900,-300],"heading":1.2,"strategy":"fixed","decision":{"vcode":15,"tcode":9}}],
             "balls":[{"position":[1300,800],"radius":78}]}
            """, 600, "crowd in a corner");
    }

    [Theory]
    [InlineData(1350.0, 0.0, 0.0, 7)]
    [InlineData(1300.0, 150.0, 0.4, 12)]
    [InlineData(-1320.0, -120.0, 3.3, 2)]
    public void AFishWedgedInAGoalMouthStaysApart(double x, double z, double heading, int tcode)
    {
        string json = FormattableString.Invariant($"{{\"fish\":[{{\"team\":0,\"position\":[{x - (200 * Math.Cos(heading))},{z - (200 * Math.Sin(heading))}],\"heading\":{heading},\"strategy\":\"fixed\",\"decision\":{{\"vcode\":15,\"tcode\":{tcode}}}}}],\"balls\":[]}}");
        Play(json, 300, "goal mouth");
    }

    private void Play(string json, int cycles, string what)
    {
        Match match = TestMatches.FromJson(json);
        float worst = 0f;
        int contacts = 0;
        for (int k = 1; k <= cycles; k++)
        {
            match.Step();
            contacts += match.Contacts.Count;
            float deepest = OverlapAudit.DeepestOverlap(match.World, out string where);
            worst = MathF.Max(worst, deepest);
            Assert.True(deepest <= Guarantee, $"{what}, cycle {k}: {where} overlaps {deepest} mm");
        }

        Assert.True(contacts > cycles / 4, $"{what}: only {contacts} contacts in {cycles} cycles: the scene is not a jam");
        output.WriteLine($"{what}: {cycles} cycles, {contacts} contacts, worst overlap left {worst} mm");
    }
}
