using System.Text.RegularExpressions;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// What a failed strategy compilation prints (<see cref="CompileErrors"/>, <see cref="CompileCause"/>):
/// the likely cause first when the errors show one, the first errors of each file grouped by file,
/// and the count.
/// </summary>
public sealed partial class CompileErrorsTests() : TempFolderTest("urwpg-compile-errors-")
{
    [Fact]
    public void TwoStrategiesInOneFolderLeadWithTheCauseThenFewErrorsOfEachFileThenTheCount()
    {
        // Two original-API strategies copied into one folder, and a third file with eight errors of
        // its own (undefined names, one per line): more than a file shows.
        string a = Copy("Faulty", "A.cs");
        string b = Copy("Dribbler", "B.cs");
        string c = Path.Combine(Folder, "C.cs");
        var text = new StringBuilder("namespace Other { public static class Helper { public static int Sum() {\n");
        for (int i = 0; i < 8; i++)
        {
            text.Append(CultureInfo.InvariantCulture, $"    int v{i} = missing{i};\n");
        }

        File.WriteAllText(c, text.Append("    return 0; } } }\n").ToString());
        var e = Assert.Throws<StrategyLoadException>(() => StrategyCompiler.Compile("Two", [a, b, c]));
        Assert.Equal($"likely cause: two strategy classes in one folder (URWPGSim2D.Strategy.Strategy is defined in {a} and {b}); give each team its own folder", e.Message);

        // Grouped: every error line of a file comes before the next file's, at most five of each.
        var lines = e.Details;
        var errorLines = lines.Where(l => !l.StartsWith("  ... ", StringComparison.Ordinal)).SkipLast(1).ToList();
        var files = errorLines.Select(l => l[..l.IndexOf('(', StringComparison.Ordinal)]).ToList();
        Assert.Equal([a, b, c], files.Distinct());
        Assert.Equal(files.Order(StringComparer.Ordinal), files);
        Assert.All(files.GroupBy(f => f), g => Assert.InRange(g.Count(), 1, CompileErrors.PerFile));
        Assert.Contains(errorLines, l => l.Contains(": error CS0101: ", StringComparison.Ordinal));

        // The third file: its first five errors, then the three more, then the count of everything.
        Assert.Equal(Enumerable.Range(0, 5).Select(i => $"{c}({i + 2},14): error CS0103: The name 'missing{i}' does not exist in the current context"), errorLines.Where(l => l.StartsWith(c, StringComparison.Ordinal)));
        Assert.Equal($"  ... 3 more in {c}", lines[^2]);
        var count = CountLine().Match(lines[^1]);
        Assert.True(count.Success, lines[^1]);
        int more = lines.Where(l => l.StartsWith("  ... ", StringComparison.Ordinal)).Sum(l => int.Parse(l.Split(' ')[3], CultureInfo.InvariantCulture));
        Assert.Equal(errorLines.Count + more, int.Parse(count.Groups[1].Value, CultureInfo.InvariantCulture));
        Assert.Equal("3", count.Groups[2].Value);
        Assert.Equal($" (the first {CompileErrors.PerFile} of each file shown)", count.Groups[3].Value);
    }

    [Fact]
    public void AMissingMemberOfTheOriginalsApiIsTheCause()
    {
        string file = Copy("Broken", "Strategy.cs");
        var e = Assert.Throws<StrategyLoadException>(() => StrategyCompiler.Compile("Broken", [file]));
        Assert.Equal("likely cause: Mission.NoSuchMember is a part of the original's API this simulator does not provide (CS1061); use the members docs/strategies.md lists, or report the missing one", e.Message);
        Assert.Equal(3, e.Details.Count);
        Assert.Equal("2 compile errors in 1 file", e.Details[^1]);
    }

    [Theory]
    [InlineData("URWPGSim2D.Common.IMission m = null;", "URWPGSim2D.Common.IMission is a part of the original's API this simulator does not provide (CS0234)")]
    [InlineData("IMission m = null;", "IMission is a part of the original's API this simulator does not provide (CS0246)")]
    [InlineData("int n = System.Math.NoSuchHelper();", null)]
    [InlineData("System.Windows.Forms.MessageBox.Show(\"hi\");", "System.Windows.Forms is a Windows or user-interface API, not available here (CS0234)")]
    [InlineData("MessageBox.Show(\"hi\");", "MessageBox is a Windows or user-interface API, not available here (CS0103)")]
    [InlineData("Form f = null;", "Form is a Windows or user-interface API, not available here (CS0246)")]
    public void TheOriginalsApiAndWindowsApisAreRecognised(string statement, string? cause)
    {
        string file = Path.Combine(Folder, "Strategy.cs");
        File.WriteAllText(file, "using URWPGSim2D.Common;\nnamespace T { public static class S { public static void M() { " + statement + " } } }\n");
        var e = Assert.Throws<StrategyLoadException>(() => StrategyCompiler.Compile("S", [file]));
        if (cause is null)
        {
            // System.Math is no type of the original: nothing to blame on the API.
            Assert.EndsWith("compile error in 1 file:", e.Message, StringComparison.Ordinal);
        }
        else
        {
            Assert.StartsWith("likely cause: " + cause + "; ", e.Message, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void AMissingMemberOfTheTeamsOwnTypeIsNoCauseAndTheCountLeads()
    {
        // The same CS1061 as the original's API gives, on a type the team wrote: a plain error.
        string file = Path.Combine(Folder, "Own.cs");
        string source = "namespace T { public class Own { } public static class S { public static int M(Own o) { return o.Missing; } } }\n";
        File.WriteAllText(file, source);
        int column = source.IndexOf("Missing", StringComparison.Ordinal) + 1;
        var e = Assert.Throws<StrategyLoadException>(() => StrategyCompiler.Compile("Own", [file]));
        Assert.Equal("1 compile error in 1 file:", e.Message);
        Assert.Equal([$"{file}(1,{column}): error CS1061: 'Own' does not contain a definition for 'Missing' and no accessible extension method 'Missing' accepting a first argument of type 'Own' could be found (are you missing a using directive or an assembly reference?)"], e.Details);
    }

    private string Copy(string strategy, string name)
    {
        string to = Path.Combine(Folder, name);
        File.Copy(Path.Combine(OriginalStrategyTests.Folder(strategy), "Strategy.cs"), to);
        return to;
    }

    [GeneratedRegex(@"^([0-9]+) compile errors in ([0-9]+) files( \(the first [0-9]+ of each file shown\))?$")]
    private static partial Regex CountLine();
}
