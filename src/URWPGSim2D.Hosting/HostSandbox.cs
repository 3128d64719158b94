namespace URWPGSim2D.Hosting;

/// <summary>Decides, once per run, whether hosts run in the sandbox, and says so once where it cannot be set up.</summary>
public static class HostSandbox
{
    private static readonly OneWarning NoSandbox = new();

    /// <summary>Where the one warning line goes (the CLI sets standard error); null: nowhere.</summary>
    public static Action<string>? Warn { get; set; }

    /// <summary>Whether a host of this run uses the sandbox under <paramref name="mode"/>.</summary>
    /// <exception cref="StrategyLoadException"><see cref="SandboxMode.Required"/> and the sandbox cannot be set up.</exception>
    public static bool Use(SandboxMode mode) => Use(mode, mode == SandboxMode.Off ? null : Sandbox.Unavailable, NoSandbox);

    /// <summary><see cref="Use(SandboxMode)"/> where the sandbox cannot be set up for <paramref name="problem"/> (null: it can), the warning said through <paramref name="warning"/>.</summary>
    internal static bool Use(SandboxMode mode, string? problem, OneWarning warning)
    {
        if (mode == SandboxMode.Off)
        {
            return false;
        }

        if (problem is null)
        {
            return true;
        }

        if (mode == SandboxMode.Required)
        {
            throw new StrategyLoadException($"--sandbox required: the strategy sandbox cannot be set up here: {problem}");
        }

        warning.Say($"warning: strategies run in plain child processes without a sandbox: {problem}");
        return false;
    }
}
