namespace URWPGSim2D.Hosting;

/// <summary>A warning said at most once, however many matches, hosts or threads run into its cause.</summary>
/// <param name="sink">Where the line goes; null: <see cref="HostSandbox.Warn"/> at the time it is said.</param>
internal sealed class OneWarning(Action<string>? sink = null)
{
    private int _said;

    /// <summary>Says <paramref name="line"/> the first time; later calls say nothing.</summary>
    public void Say(string line)
    {
        if (Interlocked.Exchange(ref _said, 1) == 0)
        {
            (sink ?? HostSandbox.Warn)?.Invoke(line);
        }
    }
}
