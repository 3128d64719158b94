namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>Checks the library's rule for bad input: an <see cref="ArgumentException"/> naming the parameter and the value.</summary>
public static class ArgumentAssert
{
    /// <summary>
    /// Asserts that <paramref name="action"/> throws an ArgumentException whose ParamName is
    /// <paramref name="paramName"/> and whose message contains every one of <paramref name="fragments"/>.
    /// </summary>
    public static ArgumentException Throws(string paramName, Action action, params string[] fragments)
    {
        var e = Assert.ThrowsAny<ArgumentException>(action);
        Assert.Equal(paramName, e.ParamName);
        foreach (var f in fragments)
        {
            Assert.Contains(f, e.Message, StringComparison.Ordinal);
        }

        return e;
    }
}
