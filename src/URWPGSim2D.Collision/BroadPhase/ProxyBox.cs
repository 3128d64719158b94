using System.Numerics;
using System.Runtime.CompilerServices;

namespace URWPGSim2D.Collision.BroadPhase;

/// <summary>The overlap rule shared by every broad phase: closed boxes, so touching boxes overlap.</summary>
internal static class ProxyBox
{
    /// <summary>True when [minA, maxA] and [minB, maxB] share a point (touching counts).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static bool Overlap(Vector2 minA, Vector2 maxA, Vector2 minB, Vector2 maxB) =>
        minA.X <= maxB.X && minB.X <= maxA.X && minA.Y <= maxB.Y && minB.Y <= maxA.Y;
}
