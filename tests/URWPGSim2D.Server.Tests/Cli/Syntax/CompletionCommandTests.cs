using URWPGSim2D.Server.Cli.Syntax;

namespace URWPGSim2D.Server.Tests.Cli.Syntax;

/// <summary>
/// <c>completion bash|zsh|pwsh</c> prints the scripts; the bash script, run by a real bash against
/// the built program, turns the program's answers into what bash expects (bash splits words at
/// <c>=</c> and <c>:</c>).
/// </summary>
public sealed class CompletionCommandTests
{
    [Theory]
    [InlineData("bash", CompletionScripts.Bash)]
    [InlineData("zsh", CompletionScripts.Zsh)]
    [InlineData("pwsh", CompletionScripts.PowerShell)]
    public void EachShellGetsItsScript(string shell, string script)
    {
        Assert.Equal((0, script, string.Empty), CliRun.Of(string.Empty, "completion", shell) is var r ? (r.ExitCode, r.Stdout, r.Stderr) : default);
        Assert.Contains("\"[suggest]\"", script, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("completion: SHELL must be bash, zsh or pwsh, got \"fish\". Usage: urwpgsim2d completion bash|zsh|pwsh\n", "fish")]
    [InlineData("completion: expected one SHELL (bash, zsh or pwsh), got 0. Usage: urwpgsim2d completion bash|zsh|pwsh\n")]
    [InlineData("completion: expected one SHELL (bash, zsh or pwsh), got 2. Usage: urwpgsim2d completion bash|zsh|pwsh\n", "bash", "zsh")]
    [InlineData("completion: unknown option \"--hlep\"; did you mean --help?\n", "--hlep")]
    public void BadArgumentsAreOneLineWithExitCodeTwo(string line, params string[] args)
    {
        var run = CliRun.Of(string.Empty, ["completion", .. args]);
        Assert.Equal((2, string.Empty, line), (run.ExitCode, run.Stdout, run.Stderr));
    }

    [Fact]
    public void HelpSaysHowToInstallIt()
    {
        var run = CliRun.Of(string.Empty, "completion", "--help");
        Assert.Equal(0, run.ExitCode);
        Assert.StartsWith("Usage: urwpgsim2d completion bash|zsh|pwsh\n", run.Stdout, StringComparison.Ordinal);
        Assert.Contains("urwpgsim2d completion bash >> ~/.bashrc", run.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("urwpgsim2d run --it", "--item")]
    [InlineData("urwpgsim2d run --strategy 0=de", "demo")]
    [InlineData("urwpgsim2d run --strategy 1=remote", "remote:")]
    [InlineData("urwpgsim2d run --item 水球1v", "水球1VS1")]
    public async System.Threading.Tasks.Task TheBashScriptOffersWhatBashReplacesTheWordWith(string line, string reply)
    {
        // bash's own splitting of the line (COMP_WORDBREAKS has '=' and ':'), as it hands it to the function.
        string words = line.Replace("=", " = ", StringComparison.Ordinal).Replace(":", " : ", StringComparison.Ordinal);
        string server = Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");
        string dotnet = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") ?? "dotnet";
        string test = CompletionScripts.Bash + $$"""
            urwpgsim2d() { '{{dotnet}}' '{{server}}' "$@"; }
            COMP_LINE='{{line}}'
            COMP_POINT=${#COMP_LINE}
            COMP_WORDS=({{words}})
            COMP_CWORD=$(( ${#COMP_WORDS[@]} - 1 ))
            _urwpgsim2d_complete
            printf '%s\n' "${COMPREPLY[@]}"
            """;
        var start = new ProcessStartInfo("bash") { RedirectStandardInput = true, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.Environment["LC_ALL"] = "C.UTF-8";
        using var bash = Process.Start(start) ?? throw new InvalidOperationException("bash did not start");
        var error = bash.StandardError.ReadToEndAsync();
        var output = bash.StandardOutput.ReadToEndAsync();
        await bash.StandardInput.WriteAsync(test);
        bash.StandardInput.Close();
        Assert.True(bash.WaitForExit(60_000), "bash did not finish");
        Assert.Equal((reply + "\n", string.Empty), (await output, await error));
    }
}
