using System.Collections.Concurrent;

namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>
/// A fixed, seeded set of random pairs for every ordered pair of shape kinds, generated once per
/// test run and shared by the property tests (so each property sees the same cases).
/// </summary>
public static class PairCorpus
{
    /// <summary>Random pairs per ordered pair of kinds.</summary>
    public const int CasesPerPair = 2000;

    private static readonly ConcurrentDictionary<(ShapeKind, ShapeKind), Lazy<PairCase[]>> Cache = new();

    /// <summary>All 25 ordered pairs of kinds, as xunit theory data.</summary>
    public static TheoryData<ShapeKind, ShapeKind> OrderedKindPairs
    {
        get
        {
            var data = new TheoryData<ShapeKind, ShapeKind>();
            foreach (var a in Enum.GetValues<ShapeKind>())
            {
                foreach (var b in Enum.GetValues<ShapeKind>())
                {
                    data.Add(a, b);
                }
            }

            return data;
        }
    }

    /// <summary>
    /// The cases for kinds (a, b) the library finds overlapping, in order, each with the library's
    /// result; with <paramref name="referenceToo"/> only those the reference finds overlapping too.
    /// </summary>
    public static IEnumerable<(PairCase Case, CollisionDetectionResult Result)> Overlapping(ShapeKind a, ShapeKind b, bool referenceToo = false)
    {
        foreach (var c in For(a, b))
        {
            var r = CollisionDetector.Detect(c.A.Shape, c.B.Shape);
            if (r.Intersect && (!referenceToo || c.Reference.Intersect))
            {
                yield return (c, r);
            }
        }
    }

    /// <summary>The cases for kinds (a, b): seed 7919·(5a + b + 1), so every pair has its own fixed sequence.</summary>
    public static PairCase[] For(ShapeKind a, ShapeKind b) =>
        Cache.GetOrAdd((a, b), key => new Lazy<PairCase[]>(() => Generate(key.Item1, key.Item2))).Value;

    private static PairCase[] Generate(ShapeKind a, ShapeKind b)
    {
        var gen = new RandomShapes(7919 * (5 * (int)a + (int)b + 1));
        return Enumerable.Range(0, CasesPerPair).Select(i =>
        {
            var (sa, sb, scenario) = gen.Pair(a, b);
            return new PairCase(i, sa, sb, scenario, ReferenceGeometry.Contact(sa.Reference, sb.Reference));
        }).ToArray();
    }
}

/// <summary>One random pair with its reference contact.</summary>
/// <param name="Index">Position in the corpus.</param>
/// <param name="A">The shape the MTV moves.</param>
/// <param name="B">The other shape.</param>
/// <param name="Scenario">How the pair was placed.</param>
/// <param name="Reference">The double-precision brute-force contact.</param>
public sealed record PairCase(int Index, TestShape A, TestShape B, PairScenario Scenario, ReferenceContact Reference)
{
    /// <summary>True when the reference depth is clear of the touching band, so the library's yes/no must agree.</summary>
    public bool Decided => System.Math.Abs(Reference.SignedDepth) > Tolerances.TouchingBand;

    /// <inheritdoc />
    public override string ToString() =>
        $"#{Index} {Scenario}: a = {A}; b = {B}; reference depth {Reference.SignedDepth:R} normal {Reference.Normal}";
}
