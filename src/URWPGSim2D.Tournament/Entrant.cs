namespace URWPGSim2D.Tournament;

/// <summary>An entrant of a tournament: its name in the standings, its team SPEC and the version of its code.</summary>
/// <param name="Name">The name (unique in the tournament).</param>
/// <param name="Spec">A team SPEC (built-in name, .dll, .cs file, folder), <c>demo</c>, the item's demo strategy, or <c>remote:PORT</c>, a remote client.</param>
/// <param name="Version">A hash of its files (<see cref="EntrantFiles.Version"/>), or null for a built-in strategy, the demo or a remote entrant.</param>
public sealed record Entrant(string Name, string Spec, string? Version = null)
{
    /// <summary>The SPEC of the item's demo strategy.</summary>
    public const string Demo = "demo";

    /// <summary>What the SPEC of a remote entrant starts with: <c>remote:PORT</c>.</summary>
    public const string RemotePrefix = "remote:";

    /// <summary>The port of a remote entrant (<c>remote:PORT</c>; 0: any free one), or null for any other.</summary>
    public int? RemotePort =>
        Spec.StartsWith(RemotePrefix, StringComparison.Ordinal)
        && int.TryParse(Spec.AsSpan(RemotePrefix.Length), System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out int port)
        && port <= 65535 ? port : null;
}
