namespace URWPGSim2D.Hosting;

/// <summary><c>--sandbox</c>: whether strategy hosts run inside bubblewrap.</summary>
public enum SandboxMode
{
    /// <summary>Use the sandbox where it can be set up; otherwise one warning line and plain child processes.</summary>
    Auto,

    /// <summary>Refuse to play (exit 2) where the sandbox cannot be set up.</summary>
    Required,

    /// <summary>Plain child processes, no sandbox (trusted code, or a machine where bubblewrap misbehaves).</summary>
    Off,
}
