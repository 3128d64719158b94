namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>What one in-process run of the command line produced.</summary>
internal sealed record CliRun(int ExitCode, string Stdout, string Stderr)
{
    /// <summary>Runs the program's command line (<c>CliApp.Run</c>, as <c>Main</c> does) with in-memory streams.</summary>
    public static CliRun Of(string stdin, params string[] args)
    {
        using var input = new StringReader(stdin);
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = CliApp.Run(args, input, output, error);
        return new CliRun(code, output.ToString(), error.ToString());
    }

    /// <summary>Runs <c>collide -</c> with <paramref name="json"/> on stdin.</summary>
    public static CliRun Collide(string json) => Of(json, "collide", "-");

    /// <summary>Runs <c>shapes -</c> with <paramref name="json"/> on stdin.</summary>
    public static CliRun Shapes(string json) => Of(json, "shapes", "-");
}
