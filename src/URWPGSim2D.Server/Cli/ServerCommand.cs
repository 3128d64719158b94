using System.Runtime.InteropServices;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// How a Slurm task starts this very server, by absolute paths: <c>dotnet</c> (the host of the
/// runtime running now) on the server's DLL when the server is framework-dependent (a build or a
/// framework-dependent publish), else the published program itself (self-contained or single
/// file). The tasks run the build that wrote their scripts, whatever their working directory and
/// PATH.
/// </summary>
internal static class ServerCommand
{
    /// <summary>The command words of the running server (before <c>run</c> or <c>merge</c>).</summary>
    public static IReadOnlyList<string> OfThisProcess()
    {
        string dll = Path.Combine(AppContext.BaseDirectory, typeof(ServerCommand).Assembly.GetName().Name + ".dll"); // not there in a single-file program
        string? host = RuntimeHost();
        if (host is not null && File.Exists(dll))
        {
            return [host, Path.GetFullPath(dll)];
        }

        string program = Environment.ProcessPath ?? throw new InvalidOperationException("the path of the running program is unknown");
        return [Path.GetFullPath(program)];
    }

    // The dotnet host of a shared runtime: the runtime runs from ROOT/shared/Microsoft.NETCore.App/VERSION/
    // and its host is ROOT/dotnet. A self-contained program runs its runtime from its own folder: no host.
    private static string? RuntimeHost()
    {
        var version = new DirectoryInfo(RuntimeEnvironment.GetRuntimeDirectory().TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar));
        if (version.Parent is not { Name: "Microsoft.NETCore.App" } framework || framework.Parent is not { Name: "shared", Parent: { } root })
        {
            return null;
        }

        string host = Path.Combine(root.FullName, OperatingSystem.IsWindows() ? "dotnet.exe" : "dotnet");
        return File.Exists(host) ? host : null;
    }
}
