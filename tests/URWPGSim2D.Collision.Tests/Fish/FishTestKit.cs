namespace URWPGSim2D.Collision.Tests.Fish;

/// <summary>Random poses and partner shapes for the fish property tests (fixed seeds, reproducible).</summary>
internal static class FishTestKit
{
    public static readonly FishPart[] AllParts = Enum.GetValues<FishPart>();

    public static float Range(Random rng, float lo, float hi) => lo + ((hi - lo) * (float)rng.NextDouble());

    public static Vector2 Point(Random rng, float half) => new(Range(rng, -half, half), Range(rng, -half, half));

    /// <summary>A pose near the origin; joints within ±maxJoint (π: any bend, even folded back).</summary>
    public static FishPose Pose(Random rng, float maxJoint = MathF.PI, float spread = 200f) =>
        new(Point(rng, spread), Range(rng, -MathF.PI, MathF.PI),
            Range(rng, -maxJoint, maxJoint), Range(rng, -maxJoint, maxJoint), Range(rng, -maxJoint, maxJoint));

    /// <summary>A fish size around the deployed one (each value 0.5× to 2×).</summary>
    public static FishSize Size(Random rng) => new(
        160f * Range(rng, 0.5f, 2f), 45f * Range(rng, 0.5f, 2f), 30f * Range(rng, 0.5f, 2f),
        88f * Range(rng, 0.5f, 2f), 66f * Range(rng, 0.5f, 2f), 55f * Range(rng, 0.5f, 2f));

    public static Circle Circle(Random rng, float spread) => new(Point(rng, spread), Range(rng, 3f, 120f));

    public static Aabb Aabb(Random rng, float spread)
    {
        Vector2 c = Point(rng, spread), h = new(Range(rng, 2f, 150f), Range(rng, 2f, 150f));
        return new Aabb(c - h, c + h);
    }

    public static KDop8 KDop(Random rng, float spread)
    {
        Span<Vector2> p = stackalloc Vector2[5];
        Vector2 c = Point(rng, spread);
        float size = Range(rng, 5f, 150f);
        for (int i = 0; i < p.Length; i++)
        {
            p[i] = c + Point(rng, size);
        }

        return KDop8.FromPoints(p);
    }

    /// <summary>A random convex polygon: 3 to 8 points on an ellipse at sorted random angles.</summary>
    public static ConvexPolygon Polygon(Random rng, float spread)
    {
        int n = rng.Next(3, 9);
        var angles = new float[n];
        for (int i = 0; i < n; i++)
        {
            angles[i] = Range(rng, 0f, 2f * MathF.PI);
        }

        Array.Sort(angles);
        for (int i = 1; i < n; i++)
        {
            angles[i] = MathF.Max(angles[i], angles[i - 1] + 0.05f);
        }

        if (angles[^1] - angles[0] > 2f * MathF.PI - 0.05f)
        {
            return Polygon(rng, spread);
        }

        Vector2 c = Point(rng, spread);
        float rx = Range(rng, 5f, 150f), rz = Range(rng, 5f, 150f);
        var v = new Vector2[n];
        for (int i = 0; i < n; i++)
        {
            v[i] = c + new Vector2(rx * MathF.Cos(angles[i]), rz * MathF.Sin(angles[i]));
        }

        return new ConvexPolygon(v);
    }

    public static Segment Segment(Random rng, float spread)
    {
        Vector2 a = Point(rng, spread);
        return new Segment(a, a + Point(rng, 200f) + new Vector2(1f, 0f));
    }

    /// <summary>The exact leaf polygons of a model as validated polygons (independent of the model's own normals).</summary>
    public static ConvexPolygon[] LeafPolygons(FishModel fish)
    {
        var leaves = new ConvexPolygon[AllParts.Length];
        foreach (var part in AllParts)
        {
            leaves[(int)part] = new ConvexPolygon(fish.GetLeaf(part));
        }

        return leaves;
    }
}
