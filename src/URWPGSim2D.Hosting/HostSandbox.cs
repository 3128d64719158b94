using System;
using System.Threading;

namespace URWPGSim2D.Hosting;

/// <summary>Decides, once per run, whether hosts run in the sandbox, and says so once where it cannot be set up.</summary>
public static class HostSandbox
{
    private static int _warned;

    /// <summary>Where the one warning line goes (the CLI sets standard error); null: nowhere.</summary>
    public static Action<string>? Warn { get; set; }

    /// <summary>Whether a host of this run uses the sandbox under <paramref name="mode"/>.</summary>
    /// <exception cref="StrategyLoadException"><see cref="SandboxMode.Required"/> and the sandbox cannot be set up.</exception>
    public static bool Use(SandboxMode mode)
    {
        if (mode == SandboxMode.Off)
        {
            return false;
        }

        if (Sandbox.Unavailable is not { } problem)
        {
            return true;
        }

        if (mode == SandboxMode.Required)
        {
            throw new StrategyLoadException($"--sandbox required: the strategy sandbox cannot be set up here: {problem}");
        }

        if (Interlocked.Exchange(ref _warned, 1) == 0)
        {
            Warn?.Invoke($"warning: strategies run in plain child processes without a sandbox: {problem}");
        }

        return false;
    }
}
