using URWPGSim2D.Server.Tests.Batch.Slurm;

namespace URWPGSim2D.Server.Tests.Cli;

/// <summary>
/// <see cref="ServerCommand"/>: in a framework-dependent build (as here, where the tests run the
/// server's DLL on the shared runtime) the tasks start the dotnet host of that runtime on the
/// server's DLL, both by absolute paths, and that command really starts the server.
/// </summary>
public sealed class ServerCommandTests
{
    [Fact]
    public void AFrameworkDependentServerIsTheRuntimesDotnetOnItsDll()
    {
        var words = ServerCommand.OfThisProcess();

        Assert.Equal(2, words.Count);
        Assert.True(Path.IsPathFullyQualified(words[0]) && File.Exists(words[0]), words[0]);
        Assert.Equal(OperatingSystem.IsWindows() ? "dotnet.exe" : "dotnet", Path.GetFileName(words[0]));
        Assert.Equal(Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll"), words[1]);

        string script = Path.Combine(Path.GetTempPath(), "urwpg-server-" + Guid.NewGuid().ToString("N") + ".sh");
        try
        {
            File.WriteAllText(script, "exec " + ShellWord.Quote(words[0]) + " " + ShellWord.Quote(words[1]) + " merge --help\n");
            var (code, stdout, stderr) = Bash.Run(script, "/");
            Assert.True(code == 0, stderr);
            Assert.StartsWith("Usage: urwpgsim2d merge [--out FILE [--force]] FILE...", stdout, StringComparison.Ordinal);
        }
        finally
        {
            File.Delete(script);
        }
    }
}
