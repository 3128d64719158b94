namespace URWPGSim2D.Collision.Motion;

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

    private Hit(in Hit h, Vector2 mtv, Vector2 normal, Vector2 point, bool swap)
    {
        Intersect = h.Intersect;
        Mtv = mtv;
        Normal = normal;
        Point = point;
        Depth = h.Depth;
        PartA = swap ? h.PartB : h.PartA;
        PartB = swap ? h.PartA : h.PartB;
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

    /// <summary>This contact, found in a fish model's frame, carried into the world by <paramref name="frame"/>.</summary>
    public Hit ToWorld(in RigidFrame frame) =>
        !Intersect || frame.IsIdentity ? this : new Hit(this, frame.Rotate(Mtv), frame.Rotate(Normal), frame.ToWorld(Point), false);

    /// <summary>The same contact with A and B swapped.</summary>
    public Hit Swapped() => !Intersect ? this : new Hit(this, -Mtv, -Normal, Point, true);

    /// <summary>The contact as the library reports it.</summary>
    public CollisionDetectionResult Result =>
        CollisionDetectionResult.InPlane(Intersect, Mtv, Normal, Point);
}
