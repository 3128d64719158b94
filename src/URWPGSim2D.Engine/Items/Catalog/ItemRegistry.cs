namespace URWPGSim2D.Engine.Items.Catalog;

/// <summary>
/// Every competition item by its English slug and the original's Chinese name, in the order
/// <c>run --list-items</c> prints them. An item is added here with one line.
/// </summary>
public static class ItemRegistry
{
    private static readonly CompetitionItem[] Known =
    [
        new BallGrab.BallGrabItem(),
        new NewBallGrab.NewBallGrabItem(),
        new Survival.SurvivalItem(),
        new Transport.TransportItem(),
        new SynchronisedSwimming.SynchronisedSwimmingItem(),
        new Rescue.RescueItem(),
        new CrossCountry.CrossCountryItem(),
        new Polo.PoloItem(1),
        new Polo.PoloItem(3),
        new Polo.PoloItem(5),
        new Snooker.SnookerItem(),
        new PushBallAvoidObstacles.PushBallAvoidObstaclesItem(),
        new PushBallViaChannel.PushBallViaChannelItem(),
        new RelayWithBall.RelayWithBallItem(),
        new DoubleFishRace.DoubleFishRaceItem(),
        new FourTeams.FourTeamsItem(),
    ];

    /// <summary>The items, in listing order.</summary>
    public static IReadOnlyList<CompetitionItem> All => Known;

    /// <summary>The item of a slug or Chinese name (either without regard to case: <c>Ball-Grab</c>, <c>水球1vs1</c>), or null (the name "default" is not an item: it is the plain scene).</summary>
    public static CompetitionItem? Find(string name)
    {
        foreach (var item in Known)
        {
            if (string.Equals(item.Slug, name, StringComparison.OrdinalIgnoreCase) || string.Equals(item.ChineseName, name, StringComparison.OrdinalIgnoreCase))
            {
                return item;
            }
        }

        return null;
    }
}
