using System.Diagnostics;

namespace URWPGSim2D.Ladder.Tests;

/// <summary>
/// <c>urwpgsim2d ladder serve</c> (or any command) as its own process, the server's assembly beside
/// the tests: its first line of output read for the address; killed with SIGKILL, as <c>kill -9</c>.
/// </summary>
public sealed class ServeProcess : IDisposable
{
    private readonly Process _process;

    private ServeProcess(Process process, string firstLine, string? tokenLine)
    {
        _process = process;
        FirstLine = firstLine;
        TokenLine = tokenLine;
    }

    public string FirstLine { get; }

    /// <summary>The organiser's token printed on a first start (when asked for), else null.</summary>
    public string? TokenLine { get; }

    /// <summary>The address the first line names (<c>… at http://…/ (…</c>).</summary>
    public string Url => FirstLine[(FirstLine.IndexOf(" at ", StringComparison.Ordinal) + 4)..].Split(' ')[0];

    public static string ServerDll => Path.Combine(AppContext.BaseDirectory, "URWPGSim2D.Server.dll");

    public static Task<ServeProcess> StartAsync(params string[] arguments) => StartAsync(false, arguments);

    public static async Task<ServeProcess> StartAsync(bool readToken, params string[] arguments)
    {
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(ServerDll);
        foreach (string a in arguments)
        {
            start.ArgumentList.Add(a);
        }

        var process = Process.Start(start)!;
        var line = await process.StandardOutput.ReadLineAsync().WaitAsync(TimeSpan.FromMinutes(3));
        if (line is null)
        {
            string error = await process.StandardError.ReadToEndAsync();
            throw new InvalidOperationException("ladder serve printed nothing: " + error);
        }

        string? token = null;
        if (readToken)
        {
            string? intro = await process.StandardOutput.ReadLineAsync().WaitAsync(TimeSpan.FromMinutes(1));
            token = intro == "organiser token (shown once; keep it):" ? await process.StandardOutput.ReadLineAsync() : throw new InvalidOperationException("no organiser token: " + intro);
        }

        return new ServeProcess(process, line, token);
    }

    /// <summary>Runs a command to its end: exit code, standard output, standard error.</summary>
    public static async Task<(int Code, string Out, string Error)> RunAsync(params string[] arguments)
    {
        var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add(ServerDll);
        foreach (string a in arguments)
        {
            start.ArgumentList.Add(a);
        }

        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        await process.WaitForExitAsync().WaitAsync(TimeSpan.FromMinutes(5));
        return (process.ExitCode, await output, await error);
    }

    /// <summary>SIGKILL, and waits until the process is gone.</summary>
    public void KillHard()
    {
        _process.Kill(entireProcessTree: false);
        _process.WaitForExit();
    }

    public void Dispose() => End(_process);

    /// <summary>Kills <paramref name="process"/> and what it started when it still runs, waits for it, and disposes of it.</summary>
    public static void End(Process process)
    {
        if (!process.HasExited)
        {
            process.Kill(entireProcessTree: true);
            process.WaitForExit();
        }

        process.Dispose();
    }
}
