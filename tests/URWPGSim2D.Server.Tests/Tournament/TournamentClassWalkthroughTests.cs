namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// A class competition as a teacher runs it, on the real outputs: a folder of 8 students' strategies
/// (sub-folders and .cs files) checked with <c>--check</c>, played as a round robin, one entrant changed
/// (only its pairings played again), one handed in late (only its pairings played), then the group stage
/// and knockout (groups, bracket and champion in every file), asked again (nothing played, the same
/// bytes), and with one entrant changed (only its group pairings played again).
/// </summary>
[Collection(InProcessStaticsCollection.Name)]
public sealed class TournamentClassWalkthroughTests() : TempFolderTest("urwpg-class-")
{
    private static readonly string[] Outputs = ["results.jsonl", "standings.json", "standings.md", "standings.csv", "matches.csv", "report.html"];

    // A student's strategy: every fish swims at the ball (fast when it faces it), or straight on at a constant speed.
    private static string Strategy(string type, string team, int fast, int slow, bool toward) => $$"""
        using System;
        using System.Numerics;
        using URWPGSim2D.Strategies;
        public sealed class {{type}} : IStrategy
        {
            public string TeamName => "{{team}}";
            public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
            {
                for (int k = 0; k < fish.Length; k++)
                {
                    FishView me = snapshot.Fish[fish[k]];
                    if ({{(toward ? "false" : "true")}} || snapshot.Balls.IsEmpty)
                    {
                        decisions[k] = new Decision({{slow}}, 7);
                        continue;
                    }

                    Vector2 to = snapshot.Balls[0].Position - me.Position;
                    float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
                    int turn = 7 + (int)MathF.Round(Math.Clamp(error / 0.5f, -1f, 1f) * 7f);
                    decisions[k] = new Decision(MathF.Abs(error) < 0.5f ? {{fast}} : {{slow}}, turn);
                }
            }
        }
        """;

    private static CliRun Tournament(string dir, params string[] more) =>
        CliRun.Of(string.Empty, ["tournament", "--item", "ball-grab", "--entrants-dir", dir, "--seeds", "1", "--cycles", "100", "--isolation", "none", "--strategy-timeout", "5000", "--threads", "2", .. more]);

    [Fact]
    public void A_class_of_eight_is_checked_played_changed_joined_late_and_played_as_groups_and_a_knockout()
    {
        string dir = Path.Combine(Folder, "class");
        Directory.CreateDirectory(dir);
        (string Name, int Fast, int Slow, bool Toward)[] students =
            [("ada", 14, 4, true), ("ben", 10, 3, true), ("cai", 6, 6, false), ("dai", 12, 2, true), ("eve", 8, 8, false), ("fay", 14, 8, true), ("guo", 3, 3, false), ("hua", 9, 5, true)];
        foreach (var (name, fast, slow, toward) in students)
        {
            string type = char.ToUpperInvariant(name[0]) + name[1..];
            string source = Strategy(type, name == "guo" ? "郭队" : "Team " + type, fast, slow, toward);
            if (name[0] is 'a' or 'c' or 'e' or 'g')
            {
                Directory.CreateDirectory(Path.Combine(dir, name));
                File.WriteAllText(Path.Combine(dir, name, type + ".cs"), source);
            }
            else
            {
                File.WriteAllText(Path.Combine(dir, name + ".cs"), source);
            }
        }

        // The pre-flight table: every entrant compiles and plays a match against idle without a fault.
        var check = Tournament(dir, "--check");
        Assert.True(check.ExitCode == 0, check.Stderr);
        string[] lines = check.Stdout.TrimEnd('\n').Split('\n');
        Assert.Equal("check: ball-grab, 8 entrants, each in one 100-cycle match against idle (seed 1)", lines[0]);
        Assert.Equal(students.Select(s => s.Name), lines[2..10].Select(l => l.Split(' ')[0]));
        Assert.All(lines[2..10], l => Assert.Matches(@"^\w+ +yes +0 +0 +0 +0 ", l));
        Assert.Equal("8 of 8 entrants ready", lines[10]);
        Assert.DoesNotContain(Directory.GetDirectories(Folder), d => Path.GetFileName(d) != "class");

        // The round robin: 8 × 7 matches on one seed.
        string tour = Path.Combine(Folder, "tour");
        var first = Tournament(dir, "--out", tour);
        Assert.True(first.ExitCode == 0, first.Stderr);
        Assert.StartsWith("tournament: ball-grab, 8 entrants, 1 seed, 56 matches; 56 to play, 0 already there\n", first.Stdout, StringComparison.Ordinal);
        using (var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(tour, "standings.json"))))
        {
            Assert.Equal(8, json.RootElement.GetProperty("entrants").GetArrayLength());
            Assert.Equal(112, json.RootElement.GetProperty("points").EnumerateArray().Sum(p => p.GetProperty("played").GetInt32()));
            Assert.False(json.RootElement.TryGetProperty("knockout", out _));
        }

        Assert.Contains("| 郭队 |", File.ReadAllText(Path.Combine(tour, "standings.md")), StringComparison.Ordinal);

        // cai changes its code: its 14 matches are played again, the 42 others stay.
        File.WriteAllText(Path.Combine(dir, "cai", "Cai.cs"), Strategy("Cai", "Team Cai", 13, 5, true));
        var changed = Tournament(dir, "--out", tour);
        Assert.True(changed.ExitCode == 0, changed.Stderr);
        Assert.StartsWith("tournament: ball-grab, 8 entrants, 1 seed, 56 matches; 14 to play, 42 already there, 14 matches of changed or removed entrants dropped\n", changed.Stdout, StringComparison.Ordinal);

        // ivy hands in late: only her 16 matches are played.
        File.WriteAllText(Path.Combine(dir, "ivy.cs"), Strategy("Ivy", "Team Ivy", 11, 4, true));
        var late = Tournament(dir, "--out", tour);
        Assert.True(late.ExitCode == 0, late.Stderr);
        Assert.StartsWith("tournament: ball-grab, 9 entrants, 1 seed, 72 matches; 16 to play, 56 already there\n", late.Stdout, StringComparison.Ordinal);
        Assert.Equal(73, File.ReadAllLines(Path.Combine(tour, "results.jsonl")).Length);

        // The group stage and knockout. Snake seeding in name order: A = ada, dai, eve, hua, ivy; B = ben, cai, fay, guo.
        string cup = Path.Combine(Folder, "cup");
        string[] format = ["--format", "groups-knockout", "--groups", "2", "--final-seeds", "2", "--out", cup];
        var knockout = Tournament(dir, format);
        Assert.True(knockout.ExitCode == 0, knockout.Stderr);
        Assert.StartsWith(
            "tournament: ball-grab, 9 entrants, 1 seed, groups-knockout: 2 groups, the top 2 of each into the knockout, the final on 2 seeds\n"
            + "group stage: 32 matches; 32 to play, 0 already there\nsemi-finals: 4 matches; 4 to play, 0 already there\n",
            knockout.Stdout,
            StringComparison.Ordinal);
        Assert.Matches(@"\nchampion: (ada|dai|eve|hua|ivy|ben|cai|fay|guo)\n", knockout.Stdout);

        using (var json = JsonDocument.Parse(File.ReadAllText(Path.Combine(cup, "standings.json"))))
        {
            var root = json.RootElement;
            var groups = root.GetProperty("groups").EnumerateArray().ToList();
            Assert.Equal(["A", "B"], groups.Select(g => g.GetProperty("name").GetString()));
            Assert.Equal(["ada", "dai", "eve", "hua", "ivy"], groups[0].GetProperty("points").EnumerateArray().Select(p => p.GetProperty("name").GetString()!).Order(StringComparer.Ordinal));
            Assert.All(groups[1].GetProperty("points").EnumerateArray(), p => Assert.Equal(6, p.GetProperty("played").GetInt32()));
            var rounds = root.GetProperty("knockout").GetProperty("rounds").EnumerateArray().ToList();
            Assert.Equal("semi-finals", rounds[0].GetProperty("name").GetString());
            Assert.Equal("final", rounds[^1].GetProperty("name").GetString());
            var semis = rounds[0].GetProperty("pairs").EnumerateArray().ToList();
            Assert.Equal([["A1", "B2"], ["B1", "A2"]], semis.Select(p => p.GetProperty("from").EnumerateArray().Select(f => f.GetString()!).ToArray()));
            var final = rounds[^1].GetProperty("pairs").EnumerateArray().Single();
            Assert.Equal(semis.Select(p => p.GetProperty("winner").GetString()), final.GetProperty("entrants").EnumerateArray().Select(e => e.GetString()));
            Assert.True(final.GetProperty("matches").GetArrayLength() >= 4); // 2 seeds, both sides
            string champion = root.GetProperty("knockout").GetProperty("champion").GetString()!;
            Assert.Equal(final.GetProperty("winner").GetString(), champion);
            Assert.Contains(champion, final.GetProperty("entrants").EnumerateArray().Select(e => e.GetString()));

            // A loser plays no later round.
            var losers = semis.SelectMany(p => p.GetProperty("entrants").EnumerateArray().Select(e => e.GetString())).Except(semis.Select(p => p.GetProperty("winner").GetString()));
            Assert.Empty(final.GetProperty("entrants").EnumerateArray().Select(e => e.GetString()).Intersect(losers));

            // Every view tells the same champion.
            Assert.Contains($"\nChampion: {champion}.\n", File.ReadAllText(Path.Combine(cup, "standings.md")), StringComparison.Ordinal);
            string report = File.ReadAllText(Path.Combine(cup, "report.html"));
            Assert.Contains("<div class=\"bracket\">", report, StringComparison.Ordinal);
            Assert.Contains($"<h3>champion</h3><div class=\"tie champion\"><strong>{champion}</strong>", report, StringComparison.Ordinal);
            string[] standings = File.ReadAllLines(Path.Combine(cup, "standings.csv"));
            Assert.EndsWith(",error,group,group_rank,reached", standings[0], StringComparison.Ordinal);
            Assert.Single(standings, l => l.EndsWith(",champion", StringComparison.Ordinal));
            Assert.Contains(standings, l => l.Split(',')[1] == champion && l.EndsWith(",champion", StringComparison.Ordinal));
            string[] matches = File.ReadAllLines(Path.Combine(cup, "matches.csv"));
            Assert.Equal("match,seed,team_0,team_1,score_0,score_1,winner,result,forfeited,stage,round", matches[0]);
            Assert.Equal(32, matches.Count(l => l.Contains(",group,", StringComparison.Ordinal)));
            Assert.Equal(root.GetProperty("matches").GetInt32(), matches.Length - 1);
            Assert.Equal(final.GetProperty("matches").GetArrayLength(), matches.Count(l => l.EndsWith(",knockout,final", StringComparison.Ordinal)));
        }

        // Asked again: nothing is played and every file keeps its bytes.
        var before = Outputs.Select(f => File.ReadAllBytes(Path.Combine(cup, f))).ToList();
        var again = Tournament(dir, format);
        Assert.True(again.ExitCode == 0, again.Stderr);
        Assert.DoesNotMatch(@"; [1-9]\d* to play", again.Stdout);
        Assert.Contains("group stage: 32 matches; 0 to play, 32 already there\n", again.Stdout, StringComparison.Ordinal);
        Assert.Equal(before, Outputs.Select(f => File.ReadAllBytes(Path.Combine(cup, f))));

        // guo (group B, four entrants) changes its code: its 6 group matches are played again, the 26 others stay.
        File.WriteAllText(Path.Combine(dir, "guo", "Guo.cs"), Strategy("Guo", "郭队 2", 12, 6, true));
        var guo = Tournament(dir, format);
        Assert.True(guo.ExitCode == 0, guo.Stderr);
        Assert.Matches(@"^tournament: [^\n]*; \d+ matches of changed or removed entrants dropped\ngroup stage: 32 matches; 6 to play, 26 already there\n", guo.Stdout);
        Assert.Contains("| 郭队 2 |", File.ReadAllText(Path.Combine(cup, "standings.md")), StringComparison.Ordinal);
    }
}
