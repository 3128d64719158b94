using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Engine.Items.Demo;
using Xunit.Sdk;

namespace URWPGSim2D.Server.Tests.Items.Demo;

/// <summary>The shortest turn-limited paths: they end where they should, and their lengths are right.</summary>
public sealed class DubinsPathTests
{
    [Fact]
    public void EveryCandidateEndsAtTheGoalPoseAndNeverTurnsTighterThanItsRadius()
    {
        var rng = new Random(31);
        Span<DubinsPath> paths = stackalloc DubinsPath[8];
        for (int i = 0; i < 500; i++)
        {
            try
            {
                Vector2 from = new(Next(rng, 1500f), Next(rng, 1000f)), to = new(Next(rng, 1500f), Next(rng, 1000f));
                float h0 = Next(rng, MathF.PI), h1 = Next(rng, MathF.PI), r = 50f + (rng.NextSingle() * 400f);
                int n = DubinsPath.Plan(from, h0, to, h1, r, paths);
                Assert.InRange(n, 2, 8);
                foreach (var path in paths[..n])
                {
                    var (end, heading) = path.At(path.Length);
                    Assert.True(Vector2.Distance(end, to) < 0.05f, $"ends at {end}, not {to}");
                    Assert.True(MathF.Abs(Angle.Wrap(heading - h1)) < 1e-3f, $"heading {heading}, not {h1}");
                    Assert.True(path.Length >= Vector2.Distance(from, to) - 0.05f);

                    // Walking the path in small steps: consecutive headings change by at most step / radius.
                    const float step = 5f;
                    var (p, h) = path.At(0f);
                    for (float s = step; s <= path.Length; s += step)
                    {
                        var (q, g) = path.At(s);
                        Assert.True(MathF.Abs(Angle.Wrap(g - h)) <= (step / r) + 1e-3f);
                        Assert.True(Vector2.Distance(p, q) <= step + 1e-2f);
                        (p, h) = (q, g);
                    }
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(31, i, e);
            }
        }
    }

    [Fact]
    public void KnownCasesHaveTheirTextbookLengths()
    {
        Span<DubinsPath> paths = stackalloc DubinsPath[8];

        // Straight ahead: a straight piece only.
        Assert.Equal(1000f, Shortest(paths, new Vector2(0f, 0f), 0f, new Vector2(1000f, 0f), 0f, 100f).Length, 0.01f);

        // Reverse the heading 400 mm to the side (+Z) with radius 200: a half circle, π·200.
        var u = Shortest(paths, Vector2.Zero, 0f, new Vector2(0f, 400f), MathF.PI, 200f);
        Assert.Equal(MathF.PI * 200f, u.Length, 0.05f);
        Assert.Equal(1, u.Turn1);

        // A quarter turn toward −Z then 500 mm straight: π/2·100 + 500 (turning first toward −Z).
        var l = Shortest(paths, Vector2.Zero, 0f, new Vector2(100f, -600f), -MathF.PI / 2f, 100f);
        Assert.Equal((MathF.PI * 50f) + 500f, l.Length, 0.05f);
        Assert.Equal(-1, l.Turn1);
    }

    [Fact]
    public void FacingIsThePoseWithItsHeadingsCosineAndSineToTheBit()
    {
        var rng = new Random(37);
        Span<DubinsPath> paths = stackalloc DubinsPath[8];
        int straight = 0;
        for (int i = 0; i < 300; i++)
        {
            Vector2 from = new(Next(rng, 1500f), Next(rng, 1000f)), to = new(Next(rng, 1500f), Next(rng, 1000f));
            int n = DubinsPath.Plan(from, Next(rng, MathF.PI), to, Next(rng, MathF.PI), 50f + (rng.NextSingle() * 400f), paths);
            foreach (var path in paths[..n])
            {
                var pieces = path.Walk();
                Assert.Equal(pieces.First, path.WalkFirst().First);
                for (float s = -10f; s <= path.Length + 10f; s += 7.3f)
                {
                    var (p, h) = path.At(s, pieces);
                    var (q, ahead) = path.Facing(s, pieces);
                    Assert.Equal(p, q);
                    Assert.Equal(MathF.Cos(h), ahead.X);
                    Assert.Equal(MathF.Sin(h), ahead.Y);
                    straight += path.Turn2 == 0 && s > path.Length1 && s < path.Length1 + path.Length2 ? 1 : 0;
                }
            }
        }

        Assert.True(straight > 1000, $"only {straight} samples on straight middle pieces");
    }

    private static DubinsPath Shortest(Span<DubinsPath> paths, Vector2 from, float h0, Vector2 to, float h1, float r)
    {
        int n = DubinsPath.Plan(from, h0, to, h1, r, paths);
        var best = paths[0];
        foreach (var p in paths[..n])
        {
            if (p.Length < best.Length)
            {
                best = p;
            }
        }

        return best;
    }

    private static float Next(Random rng, float half) => ((rng.NextSingle() * 2f) - 1f) * half;
}
