namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary><c>Detect(in Shape, in Shape)</c> must route every ordered pair to its own typed overload.</summary>
public sealed class DispatchTests
{
    [Theory]
    [MemberData(nameof(PairCorpus.OrderedKindPairs), MemberType = typeof(PairCorpus))]
    public void ShapeDispatchGivesTheTypedOverloadsAnswer(ShapeKind kindA, ShapeKind kindB)
    {
        var cases = PairCorpus.For(kindA, kindB).Take(300).ToArray();
        Assert.Contains(cases, c => CollisionDetector.Detect(c.A.Shape, c.B.Shape).Intersect);
        foreach (var c in cases)
        {
            Assert.Equal(kindA, c.A.Shape.Kind);
            Assert.Equal(kindB, c.B.Shape.Kind);
            Assert.Equal(TypedDetect.Detect(c.A.Shape, c.B.Shape), CollisionDetector.Detect(c.A.Shape, c.B.Shape));
        }
    }
}
