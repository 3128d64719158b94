using System;
using System.Collections.Generic;

namespace URWPGSim2D.Server.Items;

/// <summary>
/// Every competition item by its English slug and the original's Chinese name, in the order
/// <c>run --list-items</c> prints them. An item is added here with one line.
/// </summary>
internal static class ItemRegistry
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

    /// <summary>The item of a slug or Chinese name, or null (the name "default" is not an item: it is the plain scene).</summary>
    public static CompetitionItem? Find(string name)
    {
        foreach (var item in Known)
        {
            if (string.Equals(item.Slug, name, StringComparison.OrdinalIgnoreCase) || item.ChineseName == name)
            {
                return item;
            }
        }

        return null;
    }

    /// <summary>The accepted names for an error message: "default", then every slug.</summary>
    public static string Names()
    {
        var names = new List<string> { "default" };
        foreach (var item in Known)
        {
            names.Add(item.Slug);
        }

        return string.Join(", ", names);
    }
}
