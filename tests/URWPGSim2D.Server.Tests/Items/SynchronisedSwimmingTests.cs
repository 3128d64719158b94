using URWPGSim2D.Engine.Items.SynchronisedSwimming;

namespace URWPGSim2D.Server.Tests.Items;

/// <summary>花样游泳: the random start poses of MatchSynchronisedSwimming.cs, the server-driven fish 0, no score, the demo's ring.</summary>
public sealed class SynchronisedSwimmingTests() : ItemTests(new SynchronisedSwimmingItem())
{
    [Fact]
    public void TheLayoutIsTenFishAtRandomPosesInTheOriginalsRanges()
    {
        // x in [f.LeftMm + GoalDepth + R, f.RightMm − GoalDepth − R) = [−2250 + 150 + 184, 1916),
        // z in [−1500 + 184, 1316), heading ToRadians(Next(0, 360)); 4500 × 3000, nothing else.
        for (ulong seed = 1; seed <= 50; seed++)
        {
            var s = Item.CreateScenario(seed);
            Assert.Equal((4500f, 3000f, false), (s.FieldLength, s.FieldWidth, s.GoalBlocks));
            Assert.Empty(s.Balls);
            Assert.Empty(s.Obstacles);
            Assert.Equal(10, s.Fish.Count);
            Assert.All(s.Fish, f => Assert.Equal(0, f.Team));
            for (int i = 0; i < s.Fish.Count; i++)
            {
                var f = s.Fish[i];
                string where = $"seed {seed}, fish {i}: ({f.Position.X}, {f.Position.Y}), {f.Heading}";
                Assert.True(f.Position.X >= -1916f && f.Position.X < 1916f && f.Position.X == MathF.Round(f.Position.X), where);
                Assert.True(f.Position.Y >= -1316f && f.Position.Y < 1316f && f.Position.Y == MathF.Round(f.Position.Y), where);
                float degrees = f.Heading * 180f / MathF.PI;
                Assert.True(degrees >= -0.001f && degrees < 359.999f && MathF.Abs(degrees - MathF.Round(degrees)) < 0.001f, where);
                for (int j = 0; j < i; j++)
                {
                    Assert.True(Vector2.Distance(f.Position, s.Fish[j].Position) >= 368f, $"{where} is within two collision radii of fish {j}");
                }
            }
        }

        Assert.Equal(Positions(3), Positions(3));
        Assert.NotEqual(Positions(3), Positions(4));
    }

    [Fact]
    public void NothingIsScoredAndTheMatchLastsItsTime()
    {
        var match = ItemTestMatches.Build(Item, 30);
        Assert.Equal(30, match.PlayAll());
        var r = match.Referee!;
        Assert.Equal(new[] { -1 }, r.Scores);
        Assert.Empty(r.Variables);
        Assert.Equal(new MatchOutcome(-1, "judged by people: no score"), r.Outcome);
        Assert.Equal("end", Assert.Single(r.Events).Kind);

        var summary = new StringBuilder();
        ItemSummary.Append(summary, match, r);
        Assert.Contains("score: team 0 (idle) not scored\n", summary.ToString());
    }

    [Fact]
    public void TheServerDrivesFishZeroWithRandomRightThenLeftTurnsAwayFromTheWalls()
    {
        // Fish 0 asks for gear 15 straight; the server replaces it every cycle. Counter = 399 − (c − 1) mod 401:
        // cycles 1–200 turn right (8–14), 201–401 left (0–6), 402–601 right again; speed gear 0–9.
        var match = ItemTestMatches.Build(Item, 1000, "fixed", seed: 5, edit: s => s with
        {
            Fish = s.Fish.Select((f, i) => i == 0 ? f with { Position = Vector2.Zero, Heading = 0f, Decision = new Decision(15, 7) } : f with { Strategy = "idle" }).ToList(),
        });
        int inside = 0, nearWall = 0;
        var vcodes = new HashSet<int>();
        for (int c = 1; c <= 700; c++)
        {
            Vector2 before = match.World.Fish[0].Position;
            match.Step();
            var d = match.World.Fish[0].Decision;
            if (SynchronisedSwimmingReferee.AwayFromWalls(before, 4500f, 3000f))
            {
                inside++;
                vcodes.Add(d.VCode);
                bool left = (c - 1) % 401 >= 200;
                Assert.True(d.VCode <= 9, $"cycle {c}: {d}");
                Assert.True(left ? d.TCode <= 6 : d.TCode >= 8 && d.TCode <= 14, $"cycle {c} ({(left ? "left" : "right")}): {d}");
            }
            else
            {
                nearWall++;
                Assert.Equal(new Decision(4, 1), d);
            }
        }

        Assert.True(inside > 300, $"only {inside} cycles away from the walls");
        Assert.Equal(10, vcodes.Count);
    }

    [Fact]
    public void NearAWallFishZeroGetsGearFourTurnOne()
    {
        // x = 1900 is within 400 mm of the right wall (2250).
        var match = ItemTestMatches.Build(Item, 100, edit: s => s with
        {
            Fish = s.Fish.Select((f, i) => i == 0 ? f with { Position = new Vector2(1900f, 0f) } : f).ToList(),
        });
        match.Step();
        Assert.Equal(new Decision(4, 1), match.World.Fish[0].Decision);
        Assert.False(SynchronisedSwimmingReferee.AwayFromWalls(new Vector2(1851f, 0f), 4500f, 3000f));
        Assert.True(SynchronisedSwimmingReferee.AwayFromWalls(new Vector2(1850f, -1100f), 4500f, 3000f));
        Assert.False(SynchronisedSwimmingReferee.AwayFromWalls(new Vector2(0f, 1101f), 4500f, 3000f));
    }

    [Fact]
    public void FishZerosCodesAreTheSameForASeedAndDifferBetweenSeeds()
    {
        Assert.Equal(Fish0Codes(7), Fish0Codes(7));
        Assert.NotEqual(Fish0Codes(7), Fish0Codes(8));
    }

    [Theory]
    [InlineData(1UL)]
    [InlineData(2UL)]
    public void TheDemoFishSwimARingAndKeepMovingOffTheWalls(ulong seed)
    {
        var match = ItemMatches.Item("synchronised-swimming", seed, 3000);
        var history = new List<Vector2[]>();
        for (int c = 0; c < 3000; c++)
        {
            match.Step();
            history.Add(match.World.Fish.Select(f => f.Position).ToArray());
        }

        int onRing = 0, samples = 0;
        for (int c = 600; c < history.Count; c++)
        {
            for (int i = 1; i < 10; i++)
            {
                Vector2 p = history[c][i];
                Assert.True(MathF.Abs(p.X) < 2250f - 150f && MathF.Abs(p.Y) < 1500f - 150f, $"seed {seed}: fish {i} at {p} near a wall in cycle {c + 1}");
                float ring = MathF.Abs(new Vector2(p.X / 1400f, p.Y / 900f).Length() - 1f);
                onRing += ring < 0.2f ? 1 : 0;
                samples++;
            }
        }

        Assert.True(onRing > samples * 0.9, $"seed {seed}: {onRing} of {samples} samples on the ring");
        for (int c = 0; c + 300 < history.Count; c += 100)
        {
            for (int i = 1; i < 10; i++)
            {
                float moved = Vector2.Distance(history[c][i], history[c + 300][i]);
                Assert.True(moved > 500f, $"seed {seed}: fish {i} moved only {moved} mm in cycles {c + 1}–{c + 300}");
            }
        }
    }

    private List<(float, float)> Positions(ulong seed) => Item.CreateScenario(seed).Fish.Select(f => (f.Position.X, f.Position.Y)).ToList();

    private static List<Decision> Fish0Codes(ulong seed)
    {
        var match = ItemMatches.Item("synchronised-swimming", seed, 200);
        var codes = new List<Decision>();
        for (int c = 0; c < 200; c++)
        {
            match.Step();
            codes.Add(match.World.Fish[((SynchronisedSwimmingReferee)match.Referee!).DrivenFish].Decision);
        }

        return codes;
    }
}
