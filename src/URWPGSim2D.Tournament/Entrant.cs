namespace URWPGSim2D.Tournament;

/// <summary>An entrant of a tournament: its name in the standings, its team SPEC and the version of its code.</summary>
/// <param name="Name">The name (unique in the tournament).</param>
/// <param name="Spec">A team SPEC (built-in name, .dll, .cs file, folder) or <c>demo</c>, the item's demo strategy.</param>
/// <param name="Version">A hash of its files (<see cref="EntrantFiles.Version"/>), or null for a built-in strategy or the demo.</param>
public sealed record Entrant(string Name, string Spec, string? Version = null)
{
    /// <summary>The SPEC of the item's demo strategy.</summary>
    public const string Demo = "demo";
}
