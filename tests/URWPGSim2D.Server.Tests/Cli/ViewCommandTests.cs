namespace URWPGSim2D.Server.Tests.Cli;

/// <summary><c>view TRACE --html FILE</c> and the viewer options of <c>run</c>: bad input is one line, exit code 2, nothing written.</summary>
public sealed class ViewCommandTests() : TempFolderTest("urwpg-view-")
{
    private string File(string name) => Path.Combine(Folder, name);

    private string[] Trace(int cycles)
    {
        string trace = File("t.jsonl");
        var run = CliRun.Of(string.Empty, "run", "--cycles", cycles.ToString(System.Globalization.CultureInfo.InvariantCulture), "--trace", trace, "--force");
        Assert.Equal(0, run.ExitCode);
        return System.IO.File.ReadAllLines(trace);
    }

    private void Fails(string[] lines, string expected)
    {
        string trace = File("bad.jsonl"), page = File("bad.html");
        System.IO.File.WriteAllLines(trace, lines);
        var run = CliRun.Of(string.Empty, "view", trace, "--html", page);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.Equal($"{trace}:{expected}\n", run.Stderr.Replace("\r\n", "\n", StringComparison.Ordinal));
        Assert.False(System.IO.File.Exists(page), "no page is written for a bad trace");
    }

    [Fact]
    public void AGoodTraceGivesThePageOfRunHtml()
    {
        var lines = Trace(20);
        string page = File("p.html"), direct = File("direct.html");
        var view = CliRun.Of(string.Empty, "view", File("t.jsonl"), "--html", page);
        Assert.Equal(0, view.ExitCode);
        Assert.Equal($"{page}: 21 cycles\n", view.Stdout.Replace("\r\n", "\n", StringComparison.Ordinal));
        Assert.Equal(0, CliRun.Of(string.Empty, "run", "--cycles", "20", "--html", direct).ExitCode);
        Assert.Equal(System.IO.File.ReadAllBytes(direct), System.IO.File.ReadAllBytes(page));
        string html = System.IO.File.ReadAllText(page);
        Assert.StartsWith("<!DOCTYPE html>", html, StringComparison.Ordinal);
        Assert.Contains("\"cycles\":21", html, StringComparison.Ordinal);
        Assert.Equal(21, lines.Length);
    }

    [Fact]
    public void ATraceWithoutLayoutIsRejected()
    {
        var lines = Trace(3);
        Fails(lines.Skip(1).ToArray(), "1: layout: missing on the first line (a trace from an older version? play the match again with run --trace)");
    }

    [Fact]
    public void ABadLineIsNamed()
    {
        var lines = Trace(4);
        lines[2] = "{\"cycle\":2,";
        Assert.StartsWith($"{File("bad.jsonl")}:3: not JSON (", Run(lines), StringComparison.Ordinal);

        lines = Trace(4);
        lines[2] = lines[2].Replace("\"cycle\":2", "\"cycle\":5", StringComparison.Ordinal);
        Fails(lines, "3: cycle: expected 2 (lines must be consecutive cycles), got 5");

        lines = Trace(4);
        lines[3] = lines[3].Replace("\"fish\":[{\"position\":[", "\"fish\":[{\"position\":[\"x\",", StringComparison.Ordinal);
        Fails(lines, "4: fish[0].position: expected [x, z]");

        lines = Trace(4);
        lines[1] = lines[1].Replace("\"balls\":[{", "\"balls\":[{\"extra\":1},{", StringComparison.Ordinal);
        Fails(lines, "2: balls: 10 balls, the layout has 9");
    }

    private string Run(string[] lines)
    {
        string trace = File("bad.jsonl");
        System.IO.File.WriteAllLines(trace, lines);
        var run = CliRun.Of(string.Empty, "view", trace, "--html", File("bad.html"));
        Assert.Equal(2, run.ExitCode);
        Assert.False(System.IO.File.Exists(File("bad.html")));
        return run.Stderr;
    }

    [Theory]
    [InlineData("view --html x.html", "view: expected a TRACE file")]
    [InlineData("view t.jsonl", "view: expected --html FILE")]
    [InlineData("view t.jsonl --html a --html b", "view: --html given twice")]
    [InlineData("run --html x.html --batch 2", "run: --trace, --svg and --html record one match; they do not go with --batch")]
    [InlineData("run --port 8080", "run: --port, --host, --speed and --paused belong to --live")]
    [InlineData("run --paused", "run: --port, --host, --speed and --paused belong to --live")]
    [InlineData("run --live --port 0", "run: --port must be an integer 1..65535, got \"0\"")]
    [InlineData("run --live --speed 0", "run: --speed must be a number 0.01..1000 (times real time), got \"0\"")]
    [InlineData("run --live --trace t.jsonl", "run: --live plays the match in the browser; --batch, --trace, --svg and --html do not go with it")]
    [InlineData("run --live --live", "run: --live given twice")]
    public void BadArgumentsAreUsageErrors(string arguments, string message)
    {
        var run = CliRun.Of(string.Empty, arguments.Split(' '));
        Assert.Equal(2, run.ExitCode);
        Assert.Equal(string.Empty, run.Stdout);
        Assert.StartsWith(message + ". Usage: ", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd().Split('\n'));
    }
}
