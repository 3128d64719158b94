using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Fish;

/// <summary>Where the tree descent puts the leaf contacts it finds (fish a's leaf first).</summary>
internal interface IContactSink
{
    /// <summary>
    /// True when the sink takes depths only (<see cref="Offer"/>) and its caller finishes the
    /// contact it keeps; false when it takes finished results (<see cref="Add"/>). A constant of
    /// each sink type, so the descent's test of it compiles away.
    /// </summary>
    bool TakesDepths { get; }

    /// <summary>Takes one finished leaf result (ignored unless it intersects); leafB is −1 when b is not a fish.</summary>
    void Add(in CollisionDetectionResult result, int leafA, int leafB);

    /// <summary>Takes the normal and depth of one overlapping leaf (pair); leafB is −1 when b is not a fish.</summary>
    void Offer(in ContactDepth depth, int leafA, int leafB);

    /// <summary>True when the sink holds a contact strictly deeper than <paramref name="bound"/> mm, so no contact of at most that depth can change what it keeps.</summary>
    bool IsDeeperThan(float bound);
}

/// <summary>
/// Keeps the deepest contact (largest |MTV|); equal depths go to the smaller (leafA, leafB)
/// pair, so the answer does not depend on the order in which leaves are visited. It sees depths
/// only: the caller finishes the one it keeps (the action point costs more than the depth, and
/// every overlapping leaf pair would otherwise pay it).
/// </summary>
internal struct DeepestSink : IContactSink
{
    private float _depth2;
    private int _key;

    /// <summary>Whether any leaf overlapped.</summary>
    public bool Found { get; private set; }

    /// <summary>The deepest contact's normal, depth and faces.</summary>
    public ContactDepth Best { get; private set; }

    /// <summary>Its leaf of fish a.</summary>
    public int LeafA { get; private set; }

    /// <summary>Its leaf of fish b (−1: b is not a fish).</summary>
    public int LeafB { get; private set; }

    public readonly bool TakesDepths => true;

    public readonly void Add(in CollisionDetectionResult result, int leafA, int leafB) =>
        throw new InvalidOperationException("the deepest-contact sink takes depths only");

    public readonly bool IsDeeperThan(float bound) => Found && Best.Depth > bound;

    public void Offer(in ContactDepth depth, int leafA, int leafB)
    {
        float depth2 = depth.MtvLengthSquared;
        int key = (leafA * 16) + leafB + 1;
        if (Found && (depth2 < _depth2 || (depth2 == _depth2 && key >= _key)))
        {
            return;
        }

        _depth2 = depth2;
        _key = key;
        Found = true;
        Best = depth;
        LeafA = leafA;
        LeafB = leafB;
    }
}

/// <summary>Writes every intersecting contact into the caller's span, in visiting order.</summary>
internal ref struct SpanSink : IContactSink
{
    private readonly Span<FishContact> _contacts;

    public SpanSink(Span<FishContact> contacts)
    {
        _contacts = contacts;
        Count = 0;
    }

    public int Count { get; private set; }

    public readonly bool TakesDepths => false;

    public readonly void Offer(in ContactDepth depth, int leafA, int leafB) =>
        throw new InvalidOperationException("the span sink takes finished results only");

    public readonly bool IsDeeperThan(float bound) => false;

    public void Add(in CollisionDetectionResult result, int leafA, int leafB)
    {
        if (!result.Intersect)
        {
            return;
        }

        if (Count == _contacts.Length)
        {
            throw new ArgumentException(
                $"span of {_contacts.Length} contacts is too small; {FishCollision.MaxContactsWithShape} always suffice for a shape, {FishCollision.MaxContactsWithFish} for a fish",
                "contacts");
        }

        _contacts[Count++] = leafB < 0 ? FishContact.OfLeafA(result, leafA) : FishContact.OfLeaves(result, leafA, leafB);
    }
}
