using System.Numerics;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The last exact tests of a stepper, so that a pair tested again with both bodies exactly where
/// they were (same positions, headings and joints) is answered without testing: the response
/// tests the pair the search for the time of first contact stopped at, the re-planning after a
/// response tests the pair the handler has just separated, the end of a step tests the pairs the
/// last sample saw. Direct-mapped by the pair's ids (a newer test replaces an older one of another
/// pair in the same entry); a few kilobytes whatever the world's size. Nothing allocates.
/// </summary>
internal sealed class TestMemo
{
    private const int Size = 128;
    private readonly Entry[] _entries = new Entry[Size];

    /// <summary>Forgets every test (the bodies were replaced).</summary>
    public void Clear() => System.Array.Clear(_entries);

    /// <summary>The exact test of A and B now: remembered when both bodies are where they were then, else tested and remembered.</summary>
    public Hit Detect(Body a, Body b)
    {
        ref Entry e = ref _entries[(int)((((uint)a.Id * 0x9E3779B1u) ^ ((uint)b.Id * 0x85EBCA6Bu)) >> 25)];
        var positions = new Vector4(a.Position.X, a.Position.Y, b.Position.X, b.Position.Y);
        var headings = new Vector2(a.Heading, b.Heading);
        if (e.Valid && e.A == a.Id && e.B == b.Id && e.Positions == positions && e.Headings == headings
            && e.StampA == a.ShapeStamp && e.StampB == b.ShapeStamp)
        {
            return e.Hit;
        }

        Hit hit = PairTest.Detect(a, b);
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
