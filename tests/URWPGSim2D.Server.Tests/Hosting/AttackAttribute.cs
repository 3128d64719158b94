namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// Marks a test that plays an attack of a hostile strategy (or checks the server's defence against
/// one) with the row of docs/strategies.md that tells users what that attack gets: a row of the fault
/// table (<c>faults</c>), of the sandbox table (<c>sandbox</c>) or of the per-platform table
/// (<c>platforms</c>), named by words of its first cell. <c>StrategiesDocCoversEveryAttackTests</c>
/// checks the two against each other.
/// </summary>
[AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
public sealed class AttackAttribute(string table, string row) : Attribute
{
    /// <summary><c>faults</c>, <c>sandbox</c> or <c>platforms</c>.</summary>
    public string Table { get; } = table;

    /// <summary>Words of the first cell of the row.</summary>
    public string Row { get; } = row;
}
