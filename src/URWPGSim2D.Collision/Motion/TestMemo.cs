namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The last exact tests of a motion world, so that a pair tested again with both bodies exactly where
/// they were (same positions, headings and joints) is answered without testing: the response
/// tests the pair the search for the time of first contact stopped at, the re-planning after a
/// response tests the pair the handler has just separated, the end of a step tests the pairs the
/// last sample saw. Direct-mapped by the pair's ids (a newer test replaces an older one of another
/// pair in the same entry): 128 entries for a small world, one per mover up to 16,384 for a
/// crowd (whose many events at once otherwise evict each other's tests: a 1,000-body crowd
/// repeats 5 % fewer tests with 1,024 entries than with 128; the end of a 10,000-body crowd's step
/// takes a quarter less time with 16,384 than with 1,024), at most about 1.3 megabytes whatever
/// the world's size. Nothing allocates per test.
/// </summary>
internal sealed class TestMemo
{
    private const int SmallestSize = 128;
    private const int LargestSize = 16384;
    private Entry[] _entries = new Entry[SmallestSize];
    private int _shift = 32 - BitOperations.Log2(SmallestSize);

    /// <summary>Exact tests run (not answered from memory) since the count was last reset.</summary>
    public int Tests { get; private set; }

    /// <summary>Starts the count of exact tests again from 0.</summary>
    public void ResetTests() => Tests = 0;

    /// <summary>Adds another memo's count of exact tests to this one's and resets that one (an island worker's, merged into the event loop's).</summary>
    public void TakeTests(TestMemo other)
    {
        Tests += other.Tests;
        other.Tests = 0;
    }

    /// <summary>Forgets every test (the bodies were replaced).</summary>
    public void Clear() => System.Array.Clear(_entries);

    /// <summary>Sizes the memo for a world of <paramref name="movers"/> movers (a power of two, 128 to 16,384 entries) and forgets every test.</summary>
    public void Reserve(int movers)
    {
        int size = (int)Math.Clamp(BitOperations.RoundUpToPowerOf2((uint)Math.Max(movers, 1)), SmallestSize, LargestSize);
        if (size != _entries.Length)
        {
            _entries = new Entry[size];
            _shift = 32 - BitOperations.Log2((uint)size);
        }

        Clear();
    }

    /// <summary>The exact test of A and B now: remembered when both bodies are where they were then, else tested and remembered.</summary>
    public Hit Detect(Body a, Body b)
    {
        ref Entry e = ref _entries[(int)((((uint)a.Id * 0x9E3779B1u) ^ ((uint)b.Id * 0x85EBCA6Bu)) >> _shift)];
        var positions = new Vector4(a.Position.X, a.Position.Y, b.Position.X, b.Position.Y);
        var headings = new Vector2(a.Heading, b.Heading);
        if (e.Valid && e.A == a.Id && e.B == b.Id && e.Positions == positions && e.Headings == headings
            && e.StampA == a.ShapeStamp && e.StampB == b.ShapeStamp)
        {
            return e.Hit;
        }

        Hit hit = PairTest.Detect(a, b);
        Tests++;
        e.Valid = true;
        e.A = a.Id;
        e.B = b.Id;
        e.Positions = positions;
        e.Headings = headings;
        e.StampA = a.ShapeStamp;
        e.StampB = b.ShapeStamp;
        e.Hit = hit;
        return hit;
    }

    /// <summary>The exact test, skipped (nothing rebuilt) when the bounds are apart.</summary>
    public Hit DetectIfNear(Body a, Body b) => PairTest.Gap(a, b) > 0f ? default : Detect(a, b);

    private struct Entry
    {
        public bool Valid;
        public int A;
        public int B;
        public Vector4 Positions;
        public Vector2 Headings;
        public int StampA;
        public int StampB;
        public Hit Hit;
    }
}
