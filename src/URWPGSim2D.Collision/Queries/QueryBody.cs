namespace URWPGSim2D.Collision.Queries;

/// <summary>
/// One side of a query: a primitive shape (one convex part) or a fish (its eight leaf polygons,
/// part i = leaf i). The queries run over the parts and keep the best answer.
/// </summary>
internal readonly ref struct QueryBody
{
    private readonly ref readonly Shape _shape;
    private readonly FishModel? _fish;

    public QueryBody(ref readonly Shape shape)
    {
        _shape = ref shape;
        _fish = null;
    }

    public QueryBody(FishModel fish)
    {
        _fish = fish;
    }

    /// <summary>The fish, or null for a primitive shape.</summary>
    public FishModel? Fish => _fish;

    /// <summary>The primitive shape (only when <see cref="Fish"/> is null).</summary>
    public ref readonly Shape Shape => ref _shape;

    /// <summary>How many convex parts: 1, or 8 for a fish.</summary>
    public int Count => _fish is null ? 1 : FishLeafLayout.LeafCount;

    /// <summary>The part's index as reported (the leaf of a fish), −1 for a primitive.</summary>
    public int PartIndex(int part) => _fish is null ? -1 : part;

    /// <summary>Convex part <paramref name="part"/>; a primitive's own buffer-backed data goes into <paramref name="buffer"/>.</summary>
    public QueryShape Part(int part, ref VertexBuffer8 buffer) =>
        _fish is null ? QueryShape.Of(in _shape, ref buffer) : QueryShape.Of(_fish.LeafView(part));

    /// <summary>A circle enclosing the whole body.</summary>
    public Circle Bound => _fish is null ? _shape.BoundingCircle : _fish.Root;

    /// <summary>The narrow-phase contact of the two bodies (the MTV moves <paramref name="a"/>), with the fish parts.</summary>
    public static FishContact Contact(scoped in QueryBody a, scoped in QueryBody b)
    {
        if (a._fish is not null)
        {
            return b._fish is not null ? FishCollision.Detect(a._fish, b._fish) : FishCollision.Detect(a._fish, b._shape);
        }

        return b._fish is not null
            ? FishCollision.Detect(a._shape, b._fish)
            : new FishContact(CollisionDetector.Detect(a._shape, b._shape), null, null);
    }

    /// <summary>A lower bound of the distance between two parts' bounding circles (0 when they meet).</summary>
    public static float CircleGap(in Circle a, in Circle b) =>
        Vector2.Distance(a.Center, b.Center) - a.Radius - b.Radius;
}
