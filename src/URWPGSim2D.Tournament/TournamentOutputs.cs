namespace URWPGSim2D.Tournament;

/// <summary>The files of a finished tournament in its folder: results.jsonl, standings.json, standings.md, standings.csv, matches.csv and report.html, each written whole and renamed.</summary>
public static class TournamentOutputs
{
    /// <summary>The results file's name.</summary>
    public const string Results = "results.jsonl";

    /// <summary>The JSON standings' name.</summary>
    public const string StandingsJsonName = "standings.json";

    /// <summary>The Markdown standings' name.</summary>
    public const string StandingsMarkdownName = "standings.md";

    /// <summary>The standings for a spreadsheet.</summary>
    public const string StandingsCsvName = "standings.csv";

    /// <summary>The matches for a spreadsheet.</summary>
    public const string MatchesCsvName = "matches.csv";

    /// <summary>The report's name.</summary>
    public const string Report = "report.html";

    /// <summary>The replay pages' sub-folder.</summary>
    public const string Replays = "replays";

    /// <summary>Match J's replay page in the folder.</summary>
    public static string ReplayPage(string folder, int index) => Path.Combine(folder, Replays, $"match-{index}.html");

    /// <summary>Writes the standings, the report and (in index order) the results.</summary>
    /// <param name="folder">The tournament's folder.</param>
    /// <param name="standings">The standings.</param>
    /// <param name="records">The records.</param>
    /// <param name="teamNames">Per entrant (header order), the team's own name when known (<see cref="EntrantLoader.TeamNames"/>).</param>
    public static void Write(string folder, Standings standings, IEnumerable<TournamentRecord> records, IReadOnlyList<string?>? teamNames = null)
    {
        TournamentFile.Write(Path.Combine(folder, Results), standings.Header, records);
        bool HasReplay(int j) => File.Exists(ReplayPage(folder, j));
        AtomicFile.WriteAllText(Path.Combine(folder, StandingsJsonName), StandingsJson.Format(standings, HasReplay));
        AtomicFile.WriteAllText(Path.Combine(folder, StandingsMarkdownName), StandingsMarkdown.Format(standings, HasReplay, teamNames));
        AtomicFile.WriteAllText(Path.Combine(folder, StandingsCsvName), StandingsCsv.Standings(standings));
        AtomicFile.WriteAllText(Path.Combine(folder, MatchesCsvName), StandingsCsv.Matches(standings));
        AtomicFile.WriteAllText(Path.Combine(folder, Report), ReportPage.Format(standings, HasReplay, teamNames));
    }
}
