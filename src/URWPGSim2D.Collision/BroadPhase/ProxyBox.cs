namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>The overlap rule shared by every broad phase: closed boxes, so touching boxes overlap.</summary>
internal static class ProxyBox
{
    /// <summary>True when [minA, maxA] and [minB, maxB] share a point (touching counts).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Overlap(Vector2 minA, Vector2 maxA, Vector2 minB, Vector2 maxB) =>
        minA.X <= maxB.X && minB.X <= maxA.X && minA.Y <= maxB.Y && minB.Y <= maxA.Y;

    /// <summary>A box packed for <see cref="Overlap(Vector128{float}, Vector128{float})"/>: (min.x, min.y, −max.x, −max.y).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Packed(Vector2 min, Vector2 max) => Vector128.Create(min.X, min.Y, -max.X, -max.Y);

    /// <summary>The other side of a packed box, (max.x, max.y, −min.x, −min.y): <paramref name="packed"/> negated with its halves swapped.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector128<float> Reach(Vector128<float> packed) => -Vector128.Shuffle(packed, Vector128.Create(2, 3, 0, 1));

    /// <summary>
    /// Whether two closed boxes overlap, one given by its <see cref="Reach"/>, the other <see cref="Packed"/>:
    /// minB ≤ maxA and −maxB ≤ −minA on both axes in one comparison, the same answer as the four scalar ones
    /// (negation is exact; a NaN fails both ways).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Overlap(Vector128<float> reachA, Vector128<float> packedB) => Vector128.LessThanOrEqualAll(packedB, reachA);
}
