using URWPGSim2D.Engine.Items;
using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Engine.Simulation;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// The item lines of the <c>run</c> summary: the item, the score per team, every event with its
/// cycle and the result with the rule that decided it (docs/items.md).
/// </summary>
internal static class ItemSummary
{
    /// <summary>Appends the lines (each ending in a newline).</summary>
    public static void Append(StringBuilder s, Match match, ItemReferee referee)
    {
        var c = CultureInfo.InvariantCulture;
        var item = referee.Item;
        int halves = 1;
        foreach (var e in referee.Events)
        {
            halves += e.Kind == "half-time" && e.Cycle < referee.Cycles ? 1 : 0; // the half-times of normal time
        }

        string length = string.Create(c, $"{referee.Cycles} cycles in {(halves == 1 ? "1 half" : $"{halves} halves")}");
        int played = match.Statistics.Cycles;
        s.Append(c, $"item: {item.Slug} ({item.ChineseName}), {item.TeamCount} x {item.FishPerTeam} fish, ")
            .Append(played == referee.Cycles ? length : string.Create(c, $"normal time {length}, {played} cycles played")).Append('\n');
        s.Append("score:");
        for (int t = 0; t < referee.Scores.Length; t++)
        {
            s.Append(c, $" team {t} ({match.TeamLabel(t)}) {ScoreText(referee.Scores[t])}").Append(t + 1 < referee.Scores.Length ? "," : "\n");
        }

        s.Append(c, $"events: {referee.Events.Count}\n");
        foreach (var e in referee.Events)
        {
            s.Append(c, $"  cycle {e.Cycle}: {e.Kind}: {e.Text}\n");
        }

        var outcome = referee.Outcome;
        string state = referee.IsOver ? string.Empty : " (not over)";
        s.Append(outcome.Winner >= 0
            ? string.Create(c, $"winner: team {outcome.Winner} ({match.TeamLabel(outcome.Winner)}) by {outcome.Rule}{state}\n")
            : string.Create(c, $"winner: none, {outcome.Rule}{state}\n"));
    }

    private static string ScoreText(int score) => score < 0 ? "not scored" : score.ToString(CultureInfo.InvariantCulture);
}
