using static URWPGSim2D.Server.Tests.Cli.ShapeText;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// The built server program run as a real process (the dotnet host on the URWPGSim2D.Server.dll
/// copied next to the tests): real stdin, stdout, stderr and exit code.
/// </summary>
public sealed class ProcessEndToEndTests
{
    [Fact]
    public void CollideFromStdinWritesTheResultsAndExitsZero()
    {
        var (code, stdout, stderr) = RunServer(Pairs(Pair(Circle(0, 0, 10), Circle(16, 0, 10))), "collide", "-");

        Assert.Equal(string.Empty, stderr);
        Assert.Equal(0, code);
        Assert.Equal("[{\"intersect\":true,\"mtv\":[-4,0],\"normal\":[-1,0],\"actionPoint\":[8,0]}]\n", stdout);
    }

    [Fact]
    public void BadInputIsOneStderrLineWithExitCodeTwoAndNoStackTrace()
    {
        var (code, stdout, stderr) = RunServer(Pairs(Pair(Circle(0, 0, 10), Circle(0, 0, 1)), Pair(Circle(0, 0, -5), Circle(0, 0, 1))), "collide", "-");

        Assert.Equal(2, code);
        Assert.Equal(string.Empty, stdout);
        Assert.Equal("pairs[1].a.radius: must be > 0, got -5\n", stderr);
    }

    private static (int Code, string Stdout, string Stderr) RunServer(string stdin, params string[] args)
    {
        string server = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");
        Assert.True(File.Exists(server), $"the server program is not next to the tests: {server}");
        var start = new ProcessStartInfo(Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet")
        {
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        start.ArgumentList.Add(server);
        foreach (var arg in args)
        {
            start.ArgumentList.Add(arg);
        }

        using var process = Process.Start(start) ?? throw new InvalidOperationException("the server did not start");
        var stderrTask = process.StandardError.ReadToEndAsync();
        var stdoutTask = process.StandardOutput.ReadToEndAsync();
        process.StandardInput.Write(stdin);
        process.StandardInput.Close();
        if (!process.WaitForExit(60_000))
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail("the server did not exit within 60 s");
        }

        return (process.ExitCode, stdoutTask.Result, stderrTask.Result);
    }
}
