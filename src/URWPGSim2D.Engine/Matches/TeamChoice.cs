namespace URWPGSim2D.Engine.Matches;

/// <summary>What a team plays in a match built from a scenario (<see cref="SeatPlan.Of"/>).</summary>
public enum TeamChoice
{
    /// <summary>What the scenario's entry of each of its fish names (a built-in strategy, or the item's demo).</summary>
    Scenario,

    /// <summary>The item's demo strategy, for all of its fish.</summary>
    Demo,

    /// <summary>A strategy of its own, for all of its fish.</summary>
    Own,
}
