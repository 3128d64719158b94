namespace URWPGSim2D.Server.Tests.Json;

/// <summary>The library's <see cref="ArgumentException"/>s become <c>SHAPE.FIELD: message</c>.</summary>
public sealed class LibraryArgumentErrorsTests
{
    private static readonly Dictionary<string, string> Fields = new() { ["vertices"] = "points", ["radius"] = "radius" };

    [Fact]
    public void TheParameterSuffixIsDroppedAndTheIndexKept()
    {
        var error = Assert.Throws<ArgumentException>(() => new ConvexPolygon([new Vector2(0, 0), new Vector2(1, 0), new Vector2(float.NaN, 1)]));

        var input = LibraryArgumentErrors.ToInputError(error, "pairs[2].b", Fields);

        Assert.Equal("pairs[2].b.points[2]: must have finite coordinates, got [NaN, 1]", input.Line);
    }

    [Fact]
    public void AParameterWithoutAFieldNamesTheShape()
    {
        var input = LibraryArgumentErrors.ToInputError(new ArgumentException("bad thing", "heading"), "pairs[0].a", Fields);

        Assert.Equal("pairs[0].a: bad thing", input.Line);
    }

    [Fact]
    public void AnErrorWithoutAParameterNamesTheShape()
    {
        var input = LibraryArgumentErrors.ToInputError(new ArgumentException("bad\nthing"), "pairs[0].a", Fields);

        Assert.Equal("pairs[0].a: bad thing", input.Line);
    }

    [Fact]
    public void TheRealRadiusMessageMatchesTheContractExample()
    {
        var error = Assert.Throws<ArgumentException>(() => new Circle(Vector2.Zero, -5));

        Assert.Equal("pairs[3].a.radius: must be > 0, got -5", LibraryArgumentErrors.ToInputError(error, "pairs[3].a", Fields).Line);
    }
}
