using URWPGSim2D.Collision;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// Independent check of a world's state by brute force: every leaf polygon of every fish and every
/// ball against every other body and the pool's bounds, with the library's plain shape tests (no
/// bounding volumes, no motion world code).
/// </summary>
internal static class OverlapAudit
{
    /// <summary>Deepest overlap of any pair, mm.</summary>
    public static float DeepestOverlap(World world, out string where)
    {
        float deepest = 0f;
        string found = "none";
        var fish = world.Fish;
        var balls = world.Balls;
        var leaves = new ConvexPolygon[fish.Length][];
        for (int i = 0; i < fish.Length; i++)
        {
            leaves[i] = new ConvexPolygon[8];
            for (int p = 0; p < 8; p++)
            {
                leaves[i][p] = new ConvexPolygon(new FishModel(fish[i].Size, fish[i].Pose).GetLeaf((FishPart)p));
            }
        }

        void Take(float depth, string what)
        {
            if (depth > deepest)
            {
                deepest = depth;
                found = what;
            }
        }

        for (int i = 0; i < fish.Length; i++)
        {
            for (int p = 0; p < 8; p++)
            {
                ConvexPolygon leaf = leaves[i][p];
                for (int j = i + 1; j < fish.Length; j++)
                {
                    for (int q = 0; q < 8; q++)
                    {
                        Take(CollisionDetector.Detect(leaf, leaves[j][q]).Depth, $"fish{i}.{p} fish{j}.{q}");
                    }
                }

                for (int b = 0; b < balls.Length; b++)
                {
                    Circle c = balls[b].Shape;
                    Take(CollisionDetector.Detect(leaf, c).Depth, $"fish{i}.{p} ball{b}");
                }

                for (int s = 0; s < world.Statics.Length; s++)
                {
                    Take(Static(leaf, world.Statics[s]), $"fish{i}.{p} static{s}");
                }

                foreach (var v in leaf.Vertices)
                {
                    Take(Outside(world, v, 0f), $"fish{i}.{p} outside");
                }
            }
        }

        for (int b = 0; b < balls.Length; b++)
        {
            Circle c = balls[b].Shape;
            for (int d = b + 1; d < balls.Length; d++)
            {
                Circle e = balls[d].Shape;
                Take(CollisionDetector.Detect(c, e).Depth, $"ball{b} ball{d}");
            }

            for (int s = 0; s < world.Statics.Length; s++)
            {
                Take(Static(c, world.Statics[s]), $"ball{b} static{s}");
            }

            Take(Outside(world, c.Center, c.Radius), $"ball{b} outside");
        }

        where = found;
        return deepest;
    }

    private static float Static(in Shape shape, StaticBody body) => body.Kind switch
    {
        ShapeKind.Circle => CollisionDetector.Detect(shape, (Shape)body.Circle).Depth,
        ShapeKind.Polygon => CollisionDetector.Detect(shape, (Shape)body.Polygon).Depth,
        _ => CollisionDetector.Detect(shape, (Shape)body.Box).Depth,
    };

    private static float Outside(World world, Vector2 p, float radius)
    {
        float hx = world.Field.Length / 2f;
        float hz = world.Field.Width / 2f;
        return MathF.Max(0f, MathF.Max(MathF.Abs(p.X) + radius - hx, MathF.Abs(p.Y) + radius - hz));
    }
}
