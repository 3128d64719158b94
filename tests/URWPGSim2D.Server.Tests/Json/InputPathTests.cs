namespace URWPGSim2D.Server.Tests.Json;

/// <summary>Serializer paths (<c>$[3].a.radius</c>) become user paths (<c>pairs[3].a.radius</c>).</summary>
public sealed class InputPathTests
{
    [Theory]
    [InlineData("$", "pairs")]
    [InlineData("$[0]", "pairs[0]")]
    [InlineData("$[12].b.vertices", "pairs[12].b.vertices")]
    [InlineData("$[3].a.vertices[2][1]", "pairs[3].a.vertices[2][1]")]
    [InlineData("$[1]['odd.name'].x", "pairs[1].odd.name.x")]
    [InlineData("$[x]", "pairs[x]")]
    [InlineData("$..", "pairs..")]
    [InlineData(null, "pairs")]
    [InlineData("", "pairs")]
    public void SerializerPathsAreRootedAtTheInputName(string? serializerPath, string expected)
    {
        Assert.Equal(expected, InputPath.FromSerializerPath(serializerPath, "pairs"));
    }

    [Fact]
    public void ParseSplitsNamesAndIndices()
    {
        var segments = InputPath.Parse("$[3].a.vertices[2][10]");

        Assert.NotNull(segments);

        Assert.Equal(
            [
                JsonPathSegment.Element(3), JsonPathSegment.Property("a"), JsonPathSegment.Property("vertices"),
                JsonPathSegment.Element(2), JsonPathSegment.Element(10),
            ],
            segments);
    }

    [Theory]
    [InlineData("x")]
    [InlineData("$[")]
    [InlineData("$[-1]")]
    [InlineData("$['open")]
    [InlineData("$.")]
    [InlineData("$a")]
    public void MalformedPathsAreNotParsed(string path)
    {
        Assert.Null(InputPath.Parse(path));
    }
}
