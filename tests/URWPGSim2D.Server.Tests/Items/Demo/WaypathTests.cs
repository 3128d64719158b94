using URWPGSim2D.Engine.Items.Demo;
using URWPGSim2D.Engine.Items.Rescue;
using Xunit.Sdk;

namespace URWPGSim2D.Server.Tests.Items.Demo;

/// <summary>The way round obstacles (<see cref="Waypath"/>), on the slalom of 急速救援.</summary>
public sealed class WaypathTests
{
    private static readonly ObstacleView[] Walls = RescueLayout.Walls
        .Select((c, i) => new ObstacleView(i, ObstacleKind.Rectangle, c, RescueLayout.WallLength, RescueLayout.WallWidth, 0f, 0f)).ToArray();

    private static readonly Vector2 Half = new(RescueLayout.FieldLength / 2f, RescueLayout.FieldWidth / 2f);

    private static ObstacleField Field => new(new MatchSnapshot(0, 0, Walls, RescueLayout.FieldLength, RescueLayout.FieldWidth));

    [Fact]
    public void AClearLineIsTakenStraight()
    {
        var ways = new Waypath(Field);
        Assert.True(ways.Next(new Vector2(-1800f, 0f), new Vector2(-1000f, 800f), out var first, out var second));
        Assert.Equal(new Vector2(-1000f, 800f), first);
        Assert.Equal(first, second);
    }

    [Fact]
    public void TheWayThroughTheSlalomKeepsItsMarginAndIsAsShortAsAGridSearchFinds()
    {
        // From the right end to the left end, through both gaps and past the centre wall. Walking
        // the way leg by leg (each query from the point reached), every leg keeps the margin, it
        // arrives, and it is about as long as the shortest way a grid search (25 mm cells, eight
        // neighbours, the same clearance at the cells' centres) finds: at most 30 mm longer (the
        // grid's steps between cell centres may cut a wall corner's clearance by a few mm, at each of
        // the four or so corners passed) and at most the grid's 8.3 % of detour shorter.
        var ways = new Waypath(Field);
        var rng = new Random(12);
        for (int i = 0; i < 6; i++)
        {
            try
            {
                Vector2 from = new(1300f + (rng.NextSingle() * 700f), -1100f + (rng.NextSingle() * 2200f));
                Vector2 to = new(-2000f + (rng.NextSingle() * 700f), -1100f + (rng.NextSingle() * 2200f));
                Vector2 at = from;
                float length = 0f;
                for (int legs = 0; at != to; legs++)
                {
                    Assert.True(legs < 12, "too many legs");
                    Assert.True(ways.Next(at, to, out var next, out _));
                    Assert.True(ways.Free(at, next, Waypath.Margin - 1f), $"leg {at} → {next} is not clear");
                    length += Vector2.Distance(at, next);
                    at = next;
                }

                float grid = GridLength(from, to, Waypath.Margin + 10f);
                Assert.True(length <= grid + 30f, $"way {length:F0} mm, grid {grid:F0} mm");
                Assert.True(length >= grid / 1.083f, $"way {length:F0} mm, grid {grid:F0} mm");
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(12, i, e);
            }
        }
    }

    // Shortest 8-neighbour path on a 25 mm grid through cells whose centres keep `clear` from every
    // wall's box (start and goal cells joined to their exact points), by Dijkstra.
    private static float GridLength(Vector2 from, Vector2 to, float clear)
    {
        const float cell = 25f;
        int nx = (int)(2f * Half.X / cell) + 1, nz = (int)(2f * Half.Y / cell) + 1;
        Vector2 Centre(int x, int z) => new((x * cell) - Half.X, (z * cell) - Half.Y);
        bool Open(Vector2 p) => Walls.All(w => Vector2.Max(Vector2.Abs(p - w.Center) - new Vector2(w.Length / 2f, w.Width / 2f), Vector2.Zero).Length() >= clear
            && !(System.MathF.Abs(p.X - w.Center.X) < w.Length / 2f && System.MathF.Abs(p.Y - w.Center.Y) < w.Width / 2f));
        var distance = new float[nx, nz];
        var done = new bool[nx, nz];
        var queue = new PriorityQueue<(int X, int Z), float>();
        for (int x = 0; x < nx; x++)
        {
            for (int z = 0; z < nz; z++)
            {
                distance[x, z] = float.PositiveInfinity;
            }
        }

        (int X, int Z) start = ((int)MathF.Round((from.X + Half.X) / cell), (int)MathF.Round((from.Y + Half.Y) / cell));
        (int X, int Z) goal = ((int)MathF.Round((to.X + Half.X) / cell), (int)MathF.Round((to.Y + Half.Y) / cell));
        distance[start.X, start.Z] = Vector2.Distance(from, Centre(start.X, start.Z));
        queue.Enqueue(start, distance[start.X, start.Z]);
        while (queue.TryDequeue(out var c, out _))
        {
            if (done[c.X, c.Z])
            {
                continue;
            }

            done[c.X, c.Z] = true;
            if (c == goal)
            {
                return distance[c.X, c.Z] + Vector2.Distance(Centre(c.X, c.Z), to);
            }

            for (int dx = -1; dx <= 1; dx++)
            {
                for (int dz = -1; dz <= 1; dz++)
                {
                    int x = c.X + dx, z = c.Z + dz;
                    if ((dx == 0 && dz == 0) || x < 0 || z < 0 || x >= nx || z >= nz || done[x, z] || !Open(Centre(x, z)))
                    {
                        continue;
                    }

                    float d = distance[c.X, c.Z] + (cell * MathF.Sqrt((dx * dx) + (dz * dz)));
                    if (d < distance[x, z])
                    {
                        distance[x, z] = d;
                        queue.Enqueue((x, z), d);
                    }
                }
            }
        }

        return float.PositiveInfinity;
    }

    [Fact]
    public void APointNearAWallStillFindsItsWayOut()
    {
        // 60 mm from the left gap's lower wall (inside the margin): the first leg keeps what clearance there is.
        var ways = new Waypath(Field);
        Assert.True(ways.Next(new Vector2(-440f, 900f), new Vector2(1500f, 0f), out var first, out _));
        Assert.True(ways.Free(new Vector2(-440f, 900f), first, 30f));
    }
}
