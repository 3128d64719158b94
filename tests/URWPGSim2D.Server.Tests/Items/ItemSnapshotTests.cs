namespace URWPGSim2D.Server.Tests.Items;

/// <summary>What strategies see of an item: its name, its HtMissionVariables and its length.</summary>
public sealed class ItemSnapshotTests
{
    [Fact]
    public void StrategiesSeeTheItemsNameVariablesAndLength()
    {
        var item = ItemRegistry.Find("ball-grab")!;
        var match = ItemTestMatches.Build(item, 600);

        match.Step();

        Assert.Equal("抢球博弈", match.Snapshot.ItemName);
        Assert.Equal(600, match.Snapshot.TotalCycles);
        Assert.False(match.Snapshot.SidesSwapped);
        // Nine balls, none in a goal box yet: both status keys of every ball are "0" (the original's ints).
        for (int i = 0; i < 9; i++)
        {
            Assert.Equal("0", match.Snapshot.Variables[$"Ball_{i}_Left_Status"]);
            Assert.Equal("0", match.Snapshot.Variables[$"Ball_{i}_Right_Status"]);
        }
    }

    [Fact]
    public void AfterHalfTimeStrategiesAreToldTheSidesSwapped()
    {
        var item = ItemRegistry.Find("ball-grab")!;
        var match = ItemTestMatches.Build(item, 20);

        for (int k = 0; k < 12; k++)
        {
            match.Step();
        }

        Assert.True(match.Referee!.SidesSwapped);
        Assert.True(match.Snapshot.SidesSwapped);
    }
}
