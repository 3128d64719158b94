using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision;

namespace URWPGSim2D.Collision.Benchmarks.Baseline.Cycle;

/// <summary>
/// A detection result in plane coordinates: the MTV moves A out of B, the normal points from B
/// toward A, the action point lies in the overlap; parts are fish leaves (−1 for non-fish).
/// </summary>
internal readonly struct Hit
{
    private Hit(in CollisionDetectionResult r, sbyte partA, sbyte partB)
    {
        Intersect = r.Intersect;
        Mtv = XZPlane.ToPlane(r.MinimumTranslationVector);
        Normal = XZPlane.ToPlane(r.NormalAxis);
        Point = XZPlane.ToPlane(r.ActionPoint);
        Depth = r.Intersect ? Mtv.Length() : 0f;
        PartA = partA;
        PartB = partB;
    }

    /// <summary>Whether the shapes overlap.</summary>
    public bool Intersect { get; }

    /// <summary>Minimum translation of A, mm.</summary>
    public Vector2 Mtv { get; }

    /// <summary>Unit normal from B toward A.</summary>
    public Vector2 Normal { get; }

    /// <summary>Action point, mm.</summary>
    public Vector2 Point { get; }

    /// <summary>Overlap depth |MTV|, mm.</summary>
    public float Depth { get; }

    /// <summary>Fish part of A, or −1.</summary>
    public sbyte PartA { get; }

    /// <summary>Fish part of B, or −1.</summary>
    public sbyte PartB { get; }

    /// <summary>From a plain result (no fish parts).</summary>
    public static Hit From(in CollisionDetectionResult r) => new(r, -1, -1);

    /// <summary>From a plain result with the fish parts given.</summary>
    public static Hit From(in CollisionDetectionResult r, sbyte partA, sbyte partB) => new(r, partA, partB);

    /// <summary>From a fish contact.</summary>
    public static Hit From(in FishContact c) =>
        new(c.Result, c.PartA.HasValue ? (sbyte)c.PartA.Value : (sbyte)-1, c.PartB.HasValue ? (sbyte)c.PartB.Value : (sbyte)-1);
}
