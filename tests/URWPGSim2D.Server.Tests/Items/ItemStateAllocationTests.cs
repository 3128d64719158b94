namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// What the match reads from an item every cycle costs no allocation: its names (the snapshot
/// takes the Chinese name each cycle) and an unchanged variable, however large its value.
/// </summary>
public sealed class ItemStateAllocationTests
{
    [Fact]
    public void AnItemsNamesAreTheSameStringsEveryTime()
    {
        foreach (var item in ItemRegistry.All)
        {
            Assert.Same(item.Slug, item.Slug);
            Assert.Same(item.ChineseName, item.ChineseName);
        }
    }

    [Fact]
    public void SettingAVariableToTheValueItHasAllocatesNothing()
    {
        var variables = new MissionVariables();
        variables.Set("BallsInFieldFlag", 32767);
        variables.Set("Negative", -5);
        variables.Set("Small", 7);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            variables.Set("BallsInFieldFlag", 32767);
            variables.Set("Negative", -5);
            variables.Set("Small", 7);
        }

        Assert.Equal(0L, GC.GetAllocatedBytesForCurrentThread() - before);
        variables.Set("BallsInFieldFlag", 32766);
        Assert.Equal("32766", variables["BallsInFieldFlag"]);
        Assert.Equal("-5", variables["Negative"]);
        Assert.Equal(3, variables.Count);
    }
}
