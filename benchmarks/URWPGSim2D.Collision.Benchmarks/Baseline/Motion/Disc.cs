using System;
using System.Numerics;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>A circle as plain numbers (no validation), for cheap distance bounds, mm.</summary>
internal readonly record struct Disc(Vector2 Center, float Radius)
{
    /// <summary>Distance between the two circles' boundaries (negative when they overlap), mm.</summary>
    public float GapTo(in Disc other) => Vector2.Distance(Center, other.Center) - Radius - other.Radius;

    /// <summary>Distance from the circle to the box [min, max] (negative when they overlap), mm.</summary>
    public float GapTo(Vector2 min, Vector2 max)
    {
        Vector2 d = Vector2.Max(Vector2.Max(min - Center, Center - max), Vector2.Zero);
        return d.Length() - Radius;
    }

    /// <summary>How far the circle is inside the box [min, max] from its nearest side (negative when it sticks out), mm.</summary>
    public float ClearanceInside(Vector2 min, Vector2 max) =>
        MathF.Min(MathF.Min(Center.X - Radius - min.X, max.X - Center.X - Radius), MathF.Min(Center.Y - Radius - min.Y, max.Y - Center.Y - Radius));
}
