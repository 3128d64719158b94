using System.CommandLine;
using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>Routing, help and argument errors of the command line.</summary>
public sealed class CliAppTests
{
    private const string TopUsage = "Usage: urwpgsim2d <command> [arguments] (commands: run, collide, query, shapes, render, merge, view, tournament, host, connect, inspect-dll, ladder, completion; --help for details)";
    private const string CollideUsage = "Usage: urwpgsim2d collide FILE";

    [Theory]
    [InlineData("--help")]
    [InlineData("-h")]
    public void HelpGoesToStdoutWithExitCodeZero(string flag)
    {
        var run = CliRun.Of(string.Empty, flag);

        Assert.Equal(0, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        Assert.StartsWith("urwpgsim2d: command-line front end", run.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"\n  urwpgsim2d run \[--item NAME \| --scenario FILE\] \[options\] +Play a match", run.Stdout);
        Assert.Matches(@"\n  urwpgsim2d collide FILE +Test pairs of shapes", run.Stdout);
        Assert.Matches(@"\n  urwpgsim2d shapes FILE +Write the exact collision pieces", run.Stdout);
        Assert.Matches(@"\n  urwpgsim2d render FILE --svg OUT +Draw shapes or pairs", run.Stdout);
        Assert.Matches(@"\n  urwpgsim2d --help +Show this help\.", run.Stdout);
        Assert.Contains("Exit codes: 0 success; 2 bad input", run.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("\n", run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void CollideHelpDescribesTheFormats()
    {
        var run = CliRun.Of(string.Empty, "collide", "--help");

        Assert.Equal(0, run.ExitCode);
        Assert.Equal(string.Empty, run.Stderr);
        Assert.StartsWith(CollideUsage + "\n", run.Stdout, StringComparison.Ordinal);
        foreach (var type in new[] { "circle", "aabb", "kdop8", "polygon", "segment", "fish" })
        {
            Assert.Contains($"{{\"type\":\"{type}\"", run.Stdout, StringComparison.Ordinal);
        }

        Assert.Contains("{\"intersect\":bool,\"mtv\":[x,z],\"normal\":[x,z],\"actionPoint\":[x,z]}", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("\"partA\" and \"partB\"", run.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("shapes", "Usage: urwpgsim2d shapes FILE\n", "\"leaves\":{\"leftPectoral\"")]
    [InlineData("render", "Usage: urwpgsim2d render FILE --svg OUT\n", "MTV")]
    public void ShapesAndRenderHelpDescribeTheFormats(string command, string usageLine, string detail)
    {
        var run = CliRun.Of(string.Empty, command, "--help");

        Assert.Equal((0, string.Empty), (run.ExitCode, run.Stderr));
        Assert.StartsWith(usageLine, run.Stdout, StringComparison.Ordinal);
        foreach (var type in new[] { "circle", "aabb", "kdop8", "polygon", "segment", "fish" })
        {
            Assert.Contains($"{{\"type\":\"{type}\"", run.Stdout, StringComparison.Ordinal);
        }

        Assert.Contains(detail, run.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public void NoArgumentsRunsTheFirstMatchASeedWithGoals()
    {
        var run = new ProbeCommand { NameValue = "run", Received = ["not called"] };
        var app = new CliApp([new ProbeCommand(), run]);

        int code = app.Run([], Streams(out var stdout, out var stderr));

        Assert.Equal(7, code);
        Assert.Equal(["--seed", "6"], run.Received);
        Assert.Equal("probe ran\n", stdout.ToString());
        Assert.Equal(string.Empty, stderr.ToString());
    }

    [Fact]
    public void NoArgumentsWithoutARunCommandPrintsTheHelpToStderrAndFails()
    {
        var app = new CliApp([new ProbeCommand()]);

        int code = app.Run([], Streams(out var stdout, out var stderr));

        Assert.Equal(2, code);
        Assert.Equal(string.Empty, stdout.ToString());
        Assert.StartsWith("urwpgsim2d: command-line front end", stderr.ToString(), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(new[] { "collision" }, "unknown command \"collision\". " + TopUsage)]
    [InlineData(new[] { "" }, "unknown command \"\". " + TopUsage)]
    [InlineData(new[] { "--verbose" }, "unknown command \"--verbose\". " + TopUsage)]
    [InlineData(new[] { "collide" }, "collide: expected one FILE argument (- for stdin), got 0. " + CollideUsage)]
    [InlineData(new[] { "collide", "a.json", "b.json" }, "collide: expected one FILE argument (- for stdin), got 2. " + CollideUsage)]
    [InlineData(new[] { "collide", "-", "--help" }, "collide: expected one FILE argument (- for stdin), got 2. " + CollideUsage)]
    [InlineData(new[] { "collide", "--pretty" }, "collide: unknown option \"--pretty\". " + CollideUsage)]
    [InlineData(new[] { "collide", "" }, "collide: FILE is empty. " + CollideUsage)]
    [InlineData(new[] { "shapes" }, "shapes: expected one FILE argument (- for stdin), got 0. Usage: urwpgsim2d shapes FILE")]
    [InlineData(new[] { "shapes", "a.json", "b.json" }, "shapes: expected one FILE argument (- for stdin), got 2. Usage: urwpgsim2d shapes FILE")]
    [InlineData(new[] { "shapes", "--pretty" }, "shapes: unknown option \"--pretty\". Usage: urwpgsim2d shapes FILE")]
    [InlineData(new[] { "shapes", "" }, "shapes: FILE is empty. Usage: urwpgsim2d shapes FILE")]
    public void WrongArgumentsGiveOneUsageLine(string[] args, string expectedLine)
    {
        var run = CliRun.Of("[]", args);

        CollideErrorTests.AssertOneLineFailure(run, expectedLine);
    }

    [Fact]
    public void ACommandIsFoundByNameAndGetsTheRemainingArguments()
    {
        var probe = new ProbeCommand();
        var app = new CliApp([new ProbeCommand { NameValue = "other" }, probe]);

        int code = app.Run(["probe", "x", "-y"], Streams(out var stdout, out var stderr));

        Assert.Equal(7, code);
        Assert.Equal(["x", "-y"], probe.Received);
        Assert.Equal("probe ran\n", stdout.ToString());
        Assert.Equal(string.Empty, stderr.ToString());
    }

    [Fact]
    public void AnUnexpectedExceptionIsOneLineWithExitCodeOne()
    {
        var app = new CliApp([new ProbeCommand { Failure = new InvalidOperationException("broken\ninvariant") }]);

        int code = app.Run(["probe"], Streams(out var stdout, out var stderr));

        Assert.Equal(1, code);
        Assert.Equal(string.Empty, stdout.ToString());
        Assert.Equal("internal error: InvalidOperationException: broken invariant\n", stderr.ToString());
    }

    [Fact]
    public void InputAndUsageErrorsFromACommandAreOneLineWithExitCodeTwo()
    {
        var input = new CliApp([new ProbeCommand { Failure = new InputException("things[4].size", "must be > 0, got -1") }]);
        var usage = new CliApp([new ProbeCommand { Failure = new CliUsageException("probe: too many arguments", "urwpgsim2d probe") }]);

        int inputCode = input.Run(["probe"], Streams(out var inputOut, out var inputErr));
        int usageCode = usage.Run(["probe"], Streams(out var usageOut, out var usageErr));

        Assert.Equal((2, 2), (inputCode, usageCode));
        Assert.Equal((string.Empty, string.Empty), (inputOut.ToString(), usageOut.ToString()));
        Assert.Equal("things[4].size: must be > 0, got -1\n", inputErr.ToString());
        Assert.Equal("probe: too many arguments. Usage: urwpgsim2d probe\n", usageErr.ToString());
    }

    [Fact]
    public void AnAppNeedsAtLeastOneCommand()
    {
        Assert.Throws<ArgumentException>(() => new CliApp([]));
    }

    private static CliConsole Streams(out StringWriter stdout, out StringWriter stderr)
    {
        stdout = new StringWriter();
        stderr = new StringWriter();
        return new CliConsole(new StringReader(string.Empty), stdout, stderr);
    }

    private sealed class ProbeCommand : ICliCommand
    {
        public string NameValue { get; init; } = "probe";

        public Exception? Failure { get; init; }

        public string[] Received { get; set; } = [];

        public string Name => NameValue;

        public string Synopsis => NameValue;

        public string Summary => "A test double.";

        public Command Syntax => _syntax ??= CliSyntax.Command(NameValue, "A test double.", CliSyntax.Positional("ARG", "anything"));

        private Command? _syntax;

        public int Run(IReadOnlyList<CommandLineWord> words, CliConsole console)
        {
            Received = [.. words.Select(w => w.Text)];
            if (Failure is not null)
            {
                throw Failure;
            }

            console.Out.Write("probe ran\n");
            return 7;
        }
    }
}
