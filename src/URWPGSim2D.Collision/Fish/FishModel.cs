namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// The collision model of one multi-joint fish: a bounding-volume tree of depth 3 over its
/// eight convex leaf polygons. The root circle encloses the whole fish; its two children are
/// the body group circle (body and both pectoral fins) and the tail group circle (three tail
/// segments and the caudal fin); each leaf is bounded by a tight 8-DOP, with the exact polygon
/// beneath it for the final separating-axis or Voronoi test (see <see cref="FishCollision"/>).
/// </summary>
/// <remarks>
/// Every buffer is allocated here, once; <see cref="SetPose"/> rebuilds the leaves and all
/// bounding volumes in place without allocating. Every circle encloses every leaf below it and
/// is tight: the body group circle is the minimum enclosing circle of its leaves (rigid); the
/// tail group and root circles are at most 1/cos 22.5° ≈ 1.083 times the minimum (each is
/// centred on the smallest fixed-axis octagon around its leaves' slabs and reaches the farthest
/// vertex, see <c>OctagonCentre</c>). The fish's shape in its body frame depends on the joint
/// angles only, so those two circles are computed in the body frame when a joint angle changes
/// and moved with the body otherwise; all three are a function of the pose alone. Each is grown
/// by a few µm against round-off (more for headings of hundreds of radians, whose sums θ + φᵢ
/// round coarsely). The root need not enclose the group circles themselves, which bulge past the
/// fish; the descent only needs each volume to hold its leaves.
/// Each leaf's 8-DOP holds its polygon; its diagonal slabs may lie a few float steps outside
/// the exact projections. Not thread-safe while a pose is being set.
/// </remarks>
public sealed partial class FishModel
{
    private readonly FishTemplate _template;
    private readonly FishShapeCircles _shape;
    private readonly Vector2[] _vertices = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector2[] _normals = new Vector2[FishLeafLayout.VertexCount];
    private readonly Vector4[] _slabMin = new Vector4[FishLeafLayout.LeafCount];
    private readonly Vector4[] _slabMax = new Vector4[FishLeafLayout.LeafCount];

    /// <summary>Creates the model of a fish of the given size at the given pose.</summary>
    /// <param name="size">The fish's dimensions (a validated <see cref="FishSize"/>; not <c>default</c>).</param>
    /// <param name="pose">The initial pose.</param>
    /// <exception cref="ArgumentException"><paramref name="size"/> is <c>default(FishSize)</c>.</exception>
    public FishModel(FishSize size, in FishPose pose)
    {
        if (!size.IsValid)
        {
            throw new ArgumentException($"must be a validated fish size, got default ({size})", nameof(size));
        }

        _template = FishTemplates.Shared.For(size);
        _shape = new FishShapeCircles(_template);
        SetPose(pose);
    }

    /// <summary>The fish's dimensions, mm.</summary>
    public FishSize Size => _template.Size;

    /// <summary>The pose the model was last built for.</summary>
    public FishPose Pose { get; private set; }

    /// <summary>Encloses the whole fish (every leaf), within 1.083 times the smallest enclosing circle at this pose.</summary>
    public Circle Root { get; private set; }

    /// <summary>Encloses the body and both pectoral fins: their minimum enclosing circle (rigid, computed once per size).</summary>
    public Circle BodyGroup { get; private set; }

    /// <summary>Encloses the three tail segments and the caudal fin, within 1.083 times their smallest enclosing circle at this pose.</summary>
    public Circle TailGroup { get; private set; }

    /// <summary>The extreme coordinates of all leaves: the smallest box containing the fish, mm.</summary>
    public Aabb Bounds { get; private set; }

    /// <summary>The head tip, P + (L/2 + H)·u, mm (the reference point of the original's restitution d/300).</summary>
    public Vector2 HeadTip { get; private set; }

    /// <summary>The unit forward direction u = (cos θ, sin θ) of the body.</summary>
    public Vector2 Forward { get; private set; }

    /// <summary>The world vertices of one leaf polygon, counter-clockwise in x–z coordinates, mm.</summary>
    /// <param name="part">Which leaf.</param>
    /// <returns>A view of the model's buffer, valid until the next <see cref="SetPose"/>.</returns>
    /// <exception cref="ArgumentException"><paramref name="part"/> is not one of the eight parts.</exception>
    public ReadOnlySpan<Vector2> GetLeaf(FishPart part)
    {
        int leaf = FishLeafLayout.Index(part, nameof(part));
        return _vertices.AsSpan(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf));
    }

    /// <summary>The 8-DOP around one leaf polygon: its vertices' projections on the four 8-DOP axes (diagonals padded outward by a few float steps).</summary>
    /// <param name="part">Which leaf.</param>
    /// <returns>The leaf's bounding 8-DOP.</returns>
    /// <exception cref="ArgumentException"><paramref name="part"/> is not one of the eight parts.</exception>
    public KDop8 GetLeafBound(FishPart part)
    {
        int leaf = FishLeafLayout.Index(part, nameof(part));
        return KDop8.Build(_slabMin[leaf], _slabMax[leaf]);
    }

    /// <summary>The exact leaf polygon as a view for the narrow phase (vertices and edge normals).</summary>
    internal ConvexView LeafView(int leaf)
    {
        int at = FishLeafLayout.Offset(leaf), count = FishLeafLayout.Count(leaf);
        return new ConvexView(_vertices.AsSpan(at, count), _normals.AsSpan(at, count));
    }

    /// <summary>Every leaf vertex (leaf after leaf, see <c>FishLeafLayout</c>).</summary>
    internal ReadOnlySpan<Vector2> Vertices => _vertices;

    /// <summary>Every leaf edge normal, beside <see cref="Vertices"/>.</summary>
    internal ReadOnlySpan<Vector2> Normals => _normals;

    /// <summary>Lower slab values of the leaf's 8-DOP along the four axes.</summary>
    internal Vector4 LeafMin(int leaf) => _slabMin[leaf];

    /// <summary>Upper slab values of the leaf's 8-DOP along the four axes.</summary>
    internal Vector4 LeafMax(int leaf) => _slabMax[leaf];
}
