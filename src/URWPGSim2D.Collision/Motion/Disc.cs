namespace URWPGSim2D.Collision.Motion;

/// <summary>A circle as plain numbers (no validation), for cheap distance bounds, mm.</summary>
internal readonly record struct Disc(Vector2 Center, float Radius)
{
    /// <summary>Distance between the two circles' boundaries (negative when they overlap), mm.</summary>
    public float GapTo(in Disc other) => Vector2.Distance(Center, other.Center) - Radius - other.Radius;

    /// <summary>
    /// The least of the four gaps <c>aᵢ.GapTo(bⱼ)</c>, taken as
    /// <c>min(min(a1·b1, a1·b2), min(a2·b1, a2·b2))</c>: the four distances are computed at once,
    /// with the same subtractions, products, sum and square root as <see cref="GapTo(in Disc)"/>,
    /// so the answer is the same to the bit.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static float LeastGap(in Disc a1, in Disc a2, in Disc b1, in Disc b2)
    {
        if (!Vector128.IsHardwareAccelerated)
        {
            return MathF.Min(MathF.Min(a1.GapTo(b1), a1.GapTo(b2)), MathF.Min(a2.GapTo(b1), a2.GapTo(b2)));
        }

        var dx = Vector128.Create(a1.Center.X, a1.Center.X, a2.Center.X, a2.Center.X) - Vector128.Create(b1.Center.X, b2.Center.X, b1.Center.X, b2.Center.X);
        var dy = Vector128.Create(a1.Center.Y, a1.Center.Y, a2.Center.Y, a2.Center.Y) - Vector128.Create(b1.Center.Y, b2.Center.Y, b1.Center.Y, b2.Center.Y);
        var gaps = Vector128.Sqrt((dx * dx) + (dy * dy))
            - Vector128.Create(a1.Radius, a1.Radius, a2.Radius, a2.Radius)
            - Vector128.Create(b1.Radius, b2.Radius, b1.Radius, b2.Radius);
        return MathF.Min(MathF.Min(gaps.GetElement(0), gaps.GetElement(1)), MathF.Min(gaps.GetElement(2), gaps.GetElement(3)));
    }

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
