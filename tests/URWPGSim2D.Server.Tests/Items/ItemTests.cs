namespace URWPGSim2D.Server.Tests.Items;

/// <summary>The tests of one competition item: each test gets the item it plays.</summary>
public abstract class ItemTests(CompetitionItem item)
{
    /// <summary>The item under test.</summary>
    protected CompetitionItem Item { get; } = item;
}
