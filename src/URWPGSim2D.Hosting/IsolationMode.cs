namespace URWPGSim2D.Hosting;

/// <summary><c>--isolation</c>: where user strategies run.</summary>
public enum IsolationMode
{
    /// <summary>Each team's strategy in its own strategy host process (the default).</summary>
    Process,

    /// <summary>Inside the server's process, on their own threads (trusted code, fastest).</summary>
    None,
}
