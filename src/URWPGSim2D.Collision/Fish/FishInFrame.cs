namespace URWPGSim2D.Collision.Fish;

/// <summary>
/// A fish model carried by a rigid motion x ↦ R·x + t into another frame (another fish's model
/// frame), without rebuilding it: its circles are moved at once, the leaves of a group (vertices
/// and 8-DOP slabs) are moved into caller buffers only when a descent reaches that group, and a
/// leaf's edge normals only when an exact test first takes that leaf. A fish–fish test then costs
/// the circles and the one or two leaf groups that come near, not a whole rebuild of the second
/// fish. The circles are grown by 0.01 mm against the round-off of the move; the slabs are those
/// of the moved vertices, padded like a model's.
/// </summary>
internal ref struct FishInFrame : IFishLeaves
{
    private const float Slack = 0.01f;

    private readonly FishModel _model;
    private readonly Vector2 _rotation;
    private readonly Vector2 _translation;
    private readonly Span<Vector2> _vertices;
    private readonly Span<Vector2> _normals;
    private readonly Span<Vector4> _min;
    private readonly Span<Vector4> _max;
    private bool _bodyPlaced;
    private bool _tailPlaced;
    private int _turned;

    /// <summary>The model moved by the rotation (cos, sin) = <paramref name="rotation"/> and then <paramref name="translation"/>; the buffers hold the moved leaves.</summary>
    public FishInFrame(FishModel model, Vector2 rotation, Vector2 translation, Span<Vector2> vertices, Span<Vector2> normals, Span<Vector4> min, Span<Vector4> max)
    {
        _model = model;
        _rotation = rotation;
        _translation = translation;
        _vertices = vertices;
        _normals = normals;
        _min = min;
        _max = max;
        Root = Moved(model.Root);
        BodyGroup = Moved(model.BodyGroup);
        TailGroup = Moved(model.TailGroup);
    }

    /// <inheritdoc/>
    public Circle Root { get; }

    /// <inheritdoc/>
    public Circle BodyGroup { get; }

    /// <inheritdoc/>
    public Circle TailGroup { get; }

    /// <inheritdoc/>
    public void Prepare(int group)
    {
        if (group == 0 ? _bodyPlaced : _tailPlaced)
        {
            return;
        }

        int firstLeaf = group == 0 ? 0 : FishLeafLayout.BodyGroupEnd;
        int endLeaf = group == 0 ? FishLeafLayout.BodyGroupEnd : FishLeafLayout.LeafCount;
        int start = FishLeafLayout.Offset(firstLeaf);
        int end = group == 0 ? FishLeafLayout.TailGroupFirstVertex : FishLeafLayout.VertexCount;
        // Four points per vector instruction; the same products and sums as RigidTransform.Rotate, so the same bits.
        // The normals wait for an exact test of their leaf (see LeafView).
        RigidTransform.Place(_model.Vertices[start..end], _vertices[start..end], _translation, _rotation);

        for (int leaf = firstLeaf; leaf < endLeaf; leaf++)
        {
            FloatSlabs.Of(_vertices.Slice(FishLeafLayout.Offset(leaf), FishLeafLayout.Count(leaf)), out Vector4 lo, out Vector4 hi);
            _min[leaf] = lo;
            _max[leaf] = hi;
        }

        if (group == 0)
        {
            _bodyPlaced = true;
        }
        else
        {
            _tailPlaced = true;
        }
    }

    /// <inheritdoc/>
    public readonly Vector4 LeafMin(int leaf) => _min[leaf];

    /// <inheritdoc/>
    public readonly Vector4 LeafMax(int leaf) => _max[leaf];

    /// <inheritdoc/>
    public ConvexView LeafView(int leaf)
    {
        int at = FishLeafLayout.Offset(leaf), count = FishLeafLayout.Count(leaf);
        if ((_turned & (1 << leaf)) == 0)
        {
            RigidTransform.Turn(_model.Normals.Slice(at, count), _normals.Slice(at, count), _rotation);
            _turned |= 1 << leaf;
        }

        return new ConvexView(_vertices.Slice(at, count), _normals.Slice(at, count));
    }

    private readonly Circle Moved(in Circle c) =>
        Circle.Bounding(RigidTransform.Rotate(_rotation, c.Center) + _translation, c.Radius + Slack);
}
