namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// Everything about a fish that depends on its size only, computed once: each leaf in its
/// rigid frame (vertices counter-clockwise, outward unit edge normals) and the body group's
/// minimum enclosing circle in the body frame.
/// </summary>
internal sealed class FishTemplate
{
    private readonly Vector2[] _vertices = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _normals = new Vector2[FishLeafLayout.VertexCount];

    public FishTemplate(in FishSize size)
    {
        Size = size;
        FishLocalGeometry.Write(size, _vertices);
        for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
        {
            int at = FishLeafLayout.Offset(leaf), n = FishLeafLayout.Count(leaf);
            var v = _vertices.AsSpan(at, n);
            if (ConvexPolygon.SignedArea2(v) < 0f)
            {
                v.Reverse();
            }

            for (int i = 0; i < n; i++)
            {
                _normals[at + i] = Vector2.Normalize(XZPlane.RightPerp(v[(i + 1) % n] - v[i]));
            }
        }

        BodyGroup = EnclosingCircle.Minimum(_vertices.AsSpan(0, FishLeafLayout.TailGroupFirstVertex));
        HalfLength = 0.5f * size.Length;
        HeadReach = 0.5f * size.Length + size.Head;

        // Every vertex lies within the body frame's reach of P, or within L/2 + L1 + L2 plus
        // frame 3's reach (the caudal fin); |dx| + |dz| ≤ √2 times that distance (1.5: room for round-off).
        float reach = MaxLength(_vertices.AsSpan(0, FishLeafLayout.FrameStart(1)));
        float tailReach = HalfLength + size.Joint1 + size.Joint2 + MaxLength(_vertices.AsSpan(FishLeafLayout.FrameStart(3)));
        SlabReach = 1.5f * MathF.Max(reach, MathF.Max(tailReach, HalfLength + size.Joint1 + MaxLength(_vertices.AsSpan(FishLeafLayout.FrameStart(1), 8))));
    }

    /// <summary>A bound on |x − Px| + |z − Pz| over every vertex at every pose, mm (sets the float slabs' outward pad).</summary>
    public float SlabReach { get; }

    /// <summary>The size this template was built for.</summary>
    public FishSize Size { get; }

    /// <summary>L/2, mm: tail segment 1 starts at P − (L/2)·u.</summary>
    public float HalfLength { get; }

    /// <summary>L/2 + H, mm: the head tip is P + (L/2 + H)·u.</summary>
    public float HeadReach { get; }

    /// <summary>Frame-local vertices of all leaves, counter-clockwise per leaf, packed (see <see cref="FishLeafLayout"/>).</summary>
    public ReadOnlySpan<Vector2> Vertices => _vertices;

    /// <summary>Frame-local outward unit normal of edge i → i+1 of each leaf, packed like the vertices.</summary>
    public ReadOnlySpan<Vector2> Normals => _normals;

    /// <summary>The body group's minimum enclosing circle in the body frame (centre relative to P).</summary>
    public Circle BodyGroup { get; }

    private static float MaxLength(ReadOnlySpan<Vector2> points)
    {
        float max = 0f;
        foreach (var p in points)
        {
            max = MathF.Max(max, p.Length());
        }

        return max;
    }
}
