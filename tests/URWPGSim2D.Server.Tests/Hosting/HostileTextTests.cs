using System.Runtime.InteropServices;

namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// What a strategy says and writes is hostile: escape sequences never reach the terminal, a flood
/// on its standard error does not swell the server (checked by running the server in a control
/// group whose memory limit the kernel enforces), and its folder cannot point the compiler at a
/// file outside it.
/// </summary>
public sealed class HostileTextTests() : TempFolderTest("urwpg-text-")
{
    private string Sdk(string name, string body) =>
        SdkStrategy.Write(Folder, name, name, body, usings: "using System; using System.IO; using URWPGSim2D.Strategies;");

    [Attack("faults", "control or escape characters")]
    [Theory]
    [InlineData("process", "off", false)]
    [InlineData("process", "auto", false)]
    [InlineData("process", "auto", true)]
    [InlineData("none", "off", false)]
    [InlineData("none", "off", true)]
    public void Escape_sequences_in_a_strategys_messages_and_printed_lines_never_reach_the_terminal(string isolation, string sandbox, bool strategyLog)
    {
        // Clears the screen, sets the window title, rings the bell, a C1 control sequence introducer:
        // printed to standard output and error (the server passes them on), then thrown.
        var arguments = new System.Collections.Generic.List<string> { "run", "--cycles", "3", "--strategy-timeout", "1000", "--isolation", isolation, "--sandbox", sandbox, "--strategy",
            "0=" + Sdk("Painter" + isolation + sandbox + strategyLog, """
                Console.WriteLine("out \u001b[2J\u001b]0;owned\u0007 x");
                Console.Error.Write("err \u009b31m red\n");
                throw new Exception("\u001b[2J\u001b]0;owned\u0007 and \u009b31m red");
                """) };
        if (strategyLog)
        {
            arguments.Add("--strategy-log");
        }

        // The real program, with its own standard output and error: what reaches the terminal.
        var (code, stdout, stderr) = Docs.DocsOutputsTests.RunServer(string.Empty, [.. arguments]);
        Assert.True(code == 0, stderr);
        Assert.Contains("first: cycle 1: Exception: \\u001b[2J\\u001b]0;owned\\u0007 and \\u009b31m red", stdout, StringComparison.Ordinal);
        Assert.Contains("out \\u001b[2J\\u001b]0;owned\\u0007 x\n", stderr, StringComparison.Ordinal);
        Assert.Contains("err \\u009b31m red\n", stderr, StringComparison.Ordinal);
        foreach (char c in stdout + stderr)
        {
            Assert.False(char.IsControl(c) && c != '\n', $"control character U+{(int)c:X4} in the output");
        }
    }

    [Attack("faults", "its folder holds a symbolic link")]
    [Fact]
    public void A_symbolic_link_in_a_strategy_folder_is_refused_with_one_line_and_never_read()
    {
        string secret = Path.Combine(Folder, "secret.txt");
        File.WriteAllText(secret, "TOPSECRET class");
        string team = Path.Combine(Folder, "team");
        Directory.CreateDirectory(team);
        File.WriteAllText(Path.Combine(team, "A.cs"), "public sealed class A { }");
        File.CreateSymbolicLink(Path.Combine(team, "B.cs"), secret);
        var run = CliRun.Of(string.Empty, "run", "--cycles", "1", "--strategy", "0=" + team);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal($"--strategy 0: {Path.Combine(team, "B.cs")} is a symbolic link: only regular files inside the strategy's folder are read\n", run.Stderr);
        Assert.DoesNotContain("TOPSECRET", run.Stdout + run.Stderr, StringComparison.Ordinal);

        // A linked folder likewise.
        File.Delete(Path.Combine(team, "B.cs"));
        Directory.CreateDirectory(Path.Combine(Folder, "elsewhere"));
        Directory.CreateSymbolicLink(Path.Combine(team, "more"), Path.Combine(Folder, "elsewhere"));
        run = CliRun.Of(string.Empty, "run", "--cycles", "1", "--strategy", "0=" + team);
        Assert.Equal(2, run.ExitCode);
        Assert.Equal($"--strategy 0: {Path.Combine(team, "more")} is a symbolic link: only regular files inside the strategy's folder are read\n", run.Stderr);
    }

    [Attack("faults", "it prints without end")]
    [Fact]
    public async System.Threading.Tasks.Task A_gigabyte_on_standard_error_without_a_line_break_leaves_the_server_small()
    {
        Assert.Null(SandboxCgroup.Unavailable);

        // The server itself (with its host) runs in a control group of 700 MiB: the kernel ends it if it swells.
        string flood = Sdk("Flooder", """
            for (int i = 0; i < d.Length; i++) d[i] = new Decision(10, 7);
            if (s.Cycle != 0) return;
            var block = new string('x', 1 << 20);
            for (int i = 0; i < 1024; i++) Console.Error.Write(block);
            throw new Exception("flooded");
            """);
        using var group = SandboxCgroup.Create(700L << 20, 4096, out string? problem);
        Assert.True(group is not null, problem);
        string runtime = Path.TrimEndingDirectorySeparator(RuntimeEnvironment.GetRuntimeDirectory());
        string dotnet = Path.GetFullPath(Path.Combine(runtime, "..", "..", "..", "dotnet"));
        var start = new ProcessStartInfo("/bin/sh") { UseShellExecute = false, RedirectStandardOutput = true, RedirectStandardError = true };
        var arguments = new System.Collections.Generic.List<string>(group.Wrapper());
        arguments.AddRange([dotnet, Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll"), "run", "--cycles", "3", "--strategy-timeout", "60000", "--sandbox", "off", "--strategy", "0=" + flood]);
        foreach (string argument in arguments.GetRange(1, arguments.Count - 1))
        {
            start.ArgumentList.Add(argument);
        }

        using var server = Process.Start(start)!;
        var error = server.StandardError.ReadToEndAsync();
        string output = await server.StandardOutput.ReadToEndAsync();
        await server.WaitForExitAsync();
        Assert.False(group.OutOfMemory(), "the server ran out of its 700 MiB");
        Assert.True(server.ExitCode == 0, $"exit {server.ExitCode}: {await error}");
        Assert.Contains("first: cycle 1: Exception: flooded", output, StringComparison.Ordinal);
    }
}
