namespace URWPGSim2D.Engine.Items.FourTeams;

/// <summary>
/// The rules of 4支队伍测试: none, as the original's <c>Match4Teams</c> (its rule step is empty). The
/// match lasts its time; every score stays 0 and there is no winner. No <c>HtMissionVariables</c>.
/// </summary>
internal sealed class FourTeamsReferee : ItemReferee
{
    /// <summary>Creates the referee of one match.</summary>
    public FourTeamsReferee(FourTeamsItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts) => false;

    /// <inheritdoc/>
    protected override MatchOutcome Decide() => new(-1, "no rules: a test of four teams");
}
