namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// The compiler child's time limit (<see cref="CompilerProcess.TimeLimitSeconds"/>, set lower here):
/// a source whose overload resolution makes the compiler spin for minutes ends as the one line that
/// names the limit, and the compiler child and everything it started are gone afterwards (checked by
/// process ID). Nothing depends on how fast the machine is: the compilation never ends within the limit.
/// </summary>
public sealed class CompilerTimeLimitTests() : TempFolderTest("urwpg-compile-time-")
{
    private const int Limit = 3;

    // Ten nested lambdas, each an argument of a method with five overloads whose parameter types differ: the compiler binds every
    // lambda for every overload of every enclosing one (5^10 bindings): nine of them took over a minute here.
    private string Spinning()
    {
        var names = Enumerable.Range(0, 10).Select(i => "p" + i).ToArray();
        string expression = "(int)(" + string.Join(" + ", names) + ")";
        foreach (string name in names.Reverse())
        {
            expression = $"M({name} => {expression})";
        }

        var text = new StringBuilder("using System; using URWPGSim2D.Strategies;\npublic sealed class Spin : IStrategy\n{\n");
        foreach (string type in new[] { "int", "long", "double", "decimal", "short" })
        {
            text.Append("    static int M(Func<").Append(type).Append(", int> f) => 0;\n");
        }

        text.Append("    public string TeamName => \"spin\";\n");
        text.Append("    public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) => d[0] = new Decision(").Append(expression).Append(", 7);\n}\n");
        string file = Path.Combine(Folder, "Spin.cs");
        File.WriteAllText(file, text.ToString());
        return file;
    }

    [Fact]
    public void A_compiler_past_its_time_limit_is_one_line_and_its_process_is_gone()
    {
        string file = Spinning();
        int pid = 0;
        var e = Assert.Throws<StrategyLoadException>(() => CompilerProcess.Compile("Spin", file, [file], HostSettings.Default, timeLimitSeconds: Limit, started: id => pid = id));

        Assert.Equal($"the compiler took longer than its time limit of {Limit} s, stopped", e.Message);
        Assert.DoesNotContain('\n', e.Message);
        Assert.NotEqual(0, pid);
        Assert.False(Directory.Exists($"/proc/{pid}"), $"the compiler child {pid} is still there");

        // Nor is anything it started (bubblewrap's children, the compiler inside): no process's command line names this test's source.
        foreach (string proc in Directory.EnumerateDirectories("/proc").Where(d => int.TryParse(Path.GetFileName(d), out _)))
        {
            string commandLine;
            try
            {
                commandLine = File.ReadAllText(Path.Combine(proc, "cmdline")).Replace('\0', ' ');
            }
            catch (Exception x) when (x is IOException or UnauthorizedAccessException)
            {
                continue; // ended meanwhile
            }

            Assert.False(commandLine.Contains(Folder, StringComparison.Ordinal), $"process {Path.GetFileName(proc)} is left: {commandLine}");
        }
    }
}
