namespace URWPGSim2D.Server.Tests.Json;

/// <summary>How <c>render</c> tells an array of pairs from an array of SHAPEs: by the first element's fields.</summary>
public sealed class RenderInputKindTests
{
    [Theory]
    [InlineData("""[{"a":{"type":"circle","center":[0,0],"radius":1},"b":{"type":"circle","center":[0,0],"radius":1}}]""", true)]
    [InlineData("""[{"b":{"type":"circle"}}]""", true)]
    [InlineData("""[{"a":null}]""", true)]
    [InlineData("""[{"a":{"type":"segment","a":[0,0],"b":[1,1]},"b":{"type":"fish"}}]""", true)]
    [InlineData("""[{"a":{"type":"circle"},"b":{"type":"circle"}}, {"type":"circle"}]""", true)]
    [InlineData("\uFEFF[{\"a\":{},\"b\":{}}]", true)]
    [InlineData("""[{"a":{"type":"circle"},"b":{"type":"circle""", true)]
    [InlineData("""[{"type":"segment","a":[0,0],"b":[1,1]}]""", false)]
    [InlineData("""[{"a":[0,0],"b":[1,1],"type":"segment"}]""", false)]
    [InlineData("""[{"type":"fish","position":[0,0],"heading":0,"joints":[0,0,0]}]""", false)]
    [InlineData("""[{"type":"circle"}, {"a":{},"b":{}}]""", false)]
    [InlineData("[{}]", false)]
    [InlineData("[]", false)]
    [InlineData("[1]", false)]
    [InlineData("{}", false)]
    [InlineData("", false)]
    [InlineData("not json", false)]
    public void TheFirstElementDecides(string json, bool isPairs)
    {
        Assert.Equal(isPairs, RenderInputKind.IsPairs(json));
    }
}
