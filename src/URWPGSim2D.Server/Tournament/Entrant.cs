namespace URWPGSim2D.Server.Tournament;

/// <summary>An entrant of a tournament: its name in the standings and its team SPEC.</summary>
/// <param name="Name">The name (unique in the tournament).</param>
/// <param name="Spec">A team SPEC (built-in name, .dll, .cs file, folder) or <c>demo</c>, the item's demo strategy.</param>
internal sealed record Entrant(string Name, string Spec)
{
    /// <summary>The SPEC of the item's demo strategy.</summary>
    public const string Demo = "demo";
}
