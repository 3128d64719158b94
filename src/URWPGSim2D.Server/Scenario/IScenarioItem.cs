namespace URWPGSim2D.Server.Scenario;

/// <summary>
/// The competition item a scenario is played under, as far as a scenario knows it: the item's name.
/// The items (<c>Items.CompetitionItem</c>) implement it and make the referee of the scenario's matches.
/// </summary>
internal interface IScenarioItem
{
    /// <summary>The item's command-line name (<c>ball-grab</c>, <c>polo-3v3</c>).</summary>
    string Slug { get; }
}
