namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Hostile sources against the compiler: the server compiles a team's sources in a limited child
/// process (<see cref="CompilerProcess"/>), so sources that make the compiler swell (string constants
/// that double, 1 KB of source for gigabytes of compiler memory) end as one compile-failure line
/// naming the limit, and the server's own memory is not touched: the thread that loads the strategy
/// allocates next to nothing (it would allocate the gigabytes itself if it compiled). Ordinary compile
/// errors read exactly as the in-process compiler words them.
/// </summary>
public sealed class HostileCompileTests() : TempFolderTest("urwpg-compile-")
{
    private const long ServerAllocationLimit = 64L * 1024 * 1024;

    // 64 characters doubled 20 times: a 64 Mi-character constant, and the compiler needs gigabytes to
    // fold and emit the chain (an in-process compile took the server to 2.3 GB; two more doublings crashed it).
    private string Doubling(string name)
    {
        var text = new StringBuilder("using System; using URWPGSim2D.Strategies;\n");
        text.Append("public sealed class ").Append(name).Append(" : IStrategy\n{\n    public string TeamName => \"").Append(name).Append("\";\n");
        text.Append("    public const string A0 = \"").Append('x', 64).Append("\";\n");
        for (int i = 1; i <= 20; i++)
        {
            text.Append("    public const string A").Append(i).Append(" = A").Append(i - 1).Append(" + A").Append(i - 1).Append(";\n");
        }

        text.Append("    public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) { }\n}\n");
        string file = Path.Combine(Folder, name + ".cs");
        File.WriteAllText(file, text.ToString());
        return file;
    }

    [Attack("faults", "make the compiler swell or spin")]
    [Theory]
    [InlineData("process")]
    [InlineData("none")]
    public void Doubling_string_constants_are_a_compile_failure_naming_the_memory_limit_and_the_server_stays_small(string isolation)
    {
        string file = Doubling("Doubling" + isolation);
        long before = GC.GetAllocatedBytesForCurrentThread();
        var run = CliRun.Of(string.Empty, "run", "--cycles", "5", "--isolation", isolation, "--strategy-memory", "256", "--strategy", "0=" + file);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.Equal(2, run.ExitCode);
        var failures = run.Stderr.Split('\n').Where(l => l.Contains("cannot compile", StringComparison.Ordinal)).ToList();
        Assert.Equal([$"--strategy 0: cannot compile {file}: the compiler ran out of memory: its limit is 256 MiB (--strategy-memory)"], failures);
        Assert.True(allocated < ServerAllocationLimit, $"the server's thread allocated {allocated / (1024 * 1024)} MiB while the strategy was compiled");
    }

    [Attack("faults", "make the compiler swell or spin")]
    [Fact]
    public void A_tournament_entrant_whose_sources_swell_the_compiler_forfeits_with_the_limit_named()
    {
        string file = Doubling("Swell");
        string output = Path.Combine(Folder, "t");
        var run = CliRun.Of(string.Empty, "tournament", "--item", "ball-grab", "--entrant", "demo=demo", "--entrant", "swell=" + file, "--entrant", "idle=idle", "--seeds", "1", "--cycles", "40", "--strategy-memory", "256", "--out", output);
        Assert.True(run.ExitCode == 0, run.Stderr);
        Assert.Contains($"tournament: entrant swell cannot be loaded and forfeits its matches: cannot compile {file}: the compiler ran out of memory: its limit is 256 MiB (--strategy-memory)\n", run.Stderr, StringComparison.Ordinal);
        Assert.Contains("\"played\": 4, \"wins\": 0, \"draws\": 0, \"losses\": 4, \"error\": \"cannot compile", File.ReadAllText(Path.Combine(output, "standings.json")), StringComparison.Ordinal);
    }

    [Fact]
    public void Compile_errors_from_the_compilers_process_read_as_the_in_process_compiler_words_them()
    {
        // Seven errors in one file (five shown, then a line for the rest) and one in another.
        string folder = Path.Combine(Folder, "errors");
        Directory.CreateDirectory(folder);
        var text = new StringBuilder("namespace Other { public static class Helper { public static int Sum() {\n");
        for (int i = 0; i < 7; i++)
        {
            text.Append("    int v").Append(i).Append(" = missing").Append(i).Append(";\n");
        }

        File.WriteAllText(Path.Combine(folder, "A.cs"), text.Append("    return 0; } } }\n").ToString());
        File.WriteAllText(Path.Combine(folder, "B.cs"), "public class Broken {");
        var files = StrategyCompiler.SourceFiles(folder);
        var inProcess = Assert.Throws<StrategyLoadException>(() => StrategyCompiler.Compile(CompiledImages.Name(folder), files));

        var child = Assert.Throws<StrategyLoadException>(() => StrategyResolver.Prepare(folder, settings: HostSettings.Default));
        Assert.Equal($"cannot compile {folder}: {inProcess.Message}", child.Message);
        Assert.Equal(inProcess.Details, child.Details);
        Assert.Contains($"  ... 2 more in {Path.Combine(folder, "A.cs")}", child.Details);
    }
}
