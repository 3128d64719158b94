using System;

namespace URWPGSim2D.Collision.Fish;

/// <summary>Where the tree descent puts the leaf contacts it finds (fish a's leaf first).</summary>
internal interface IContactSink
{
    /// <summary>Takes one leaf result (ignored unless it intersects); leafB is −1 when b is not a fish.</summary>
    void Add(in CollisionDetectionResult result, int leafA, int leafB);
}

/// <summary>
/// Keeps the deepest contact (largest |MTV|); equal depths go to the smaller (leafA, leafB)
/// pair, so the answer does not depend on the order in which leaves are visited.
/// </summary>
internal struct DeepestSink : IContactSink
{
    private float _depth2;
    private int _key;

    public FishContact Best { get; private set; }

    public void Add(in CollisionDetectionResult result, int leafA, int leafB)
    {
        if (!result.Intersect)
        {
            return;
        }

        float depth2 = result.MinimumTranslationVector.LengthSquared();
        int key = (leafA * 16) + leafB + 1;
        if (Best.Intersect && (depth2 < _depth2 || (depth2 == _depth2 && key >= _key)))
        {
            return;
        }

        _depth2 = depth2;
        _key = key;
        Best = leafB < 0 ? FishContact.OfLeafA(result, leafA) : FishContact.OfLeaves(result, leafA, leafB);
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
