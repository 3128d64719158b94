namespace URWPGSim2D.Server.Tests.Tournament;

/// <summary>
/// <c>tournament --format groups-knockout</c>'s options: bad input is one line naming the option and its
/// value, exit code 2, before anything is written; and a short cup of built-in entrants end to end.
/// </summary>
public sealed class TournamentGroupsKnockoutCommandTests() : TempFolderTest("urwpg-cup-")
{
    private CliRun Run(string item, params string[] more) =>
        CliRun.Of(string.Empty, ["tournament", "--item", item, "--entrant", "a=demo", "--entrant", "b=chase-ball", "--entrant", "c=idle", "--entrant", "d=chase-ball", "--seeds", "1", "--cycles", "40", "--out", Path.Combine(Folder, "out"), .. more]);

    [Theory]
    [InlineData("ball-grab", "--format swiss", "--format must be round-robin or groups-knockout, got \"swiss\"")]
    [InlineData("ball-grab", "--groups 2", "--groups, --advance, --final-seeds and --seeding belong to --format groups-knockout")]
    [InlineData("ball-grab", "--format round-robin --final-seeds 3", "--groups, --advance, --final-seeds and --seeding belong to --format groups-knockout")]
    [InlineData("ball-grab", "--format groups-knockout --groups 3", "--groups 3: 3 groups need at least 6 entrants (two a group), got 4")]
    [InlineData("ball-grab", "--format groups-knockout --groups 0", "--groups must be an integer 1..500, got \"0\"")]
    [InlineData("ball-grab", "--format groups-knockout --advance 3", "--advance 3: must be 1 … 2, the smallest group's size")]
    [InlineData("ball-grab", "--format groups-knockout --final-seeds 0", "--final-seeds must be an integer 1..100000, got \"0\"")]
    [InlineData("ball-grab", "--format groups-knockout --seeding c,x", "--seeding: \"x\" is not an entrant")]
    [InlineData("ball-grab", "--format groups-knockout --seeding c,c", "--seeding: \"c\" is named twice")]
    [InlineData("four-teams", "--format groups-knockout", "--format groups-knockout: four-teams is a 4-team item; a group stage and knockout needs a two-team item")]
    [InlineData("transport", "--format groups-knockout", "--format groups-knockout: transport is a 1-team item; a group stage and knockout needs a two-team item")]
    [InlineData("ball-grab", "--format groups-knockout --slurm jobs", "--format groups-knockout is played on one machine (each knockout round is paired from the results before it, so its matches cannot be laid out as Slurm tasks in advance): --slurm, --shard, --results and --merge go with --format round-robin")]
    public void Bad_input_is_one_line_naming_the_option_and_exit_2_with_nothing_written(string item, string options, string message)
    {
        var run = Run(item, options.Split(' '));
        Assert.Equal(2, run.ExitCode);
        Assert.StartsWith("tournament: " + message + ". Usage: ", run.Stderr, StringComparison.Ordinal);
        Assert.Single(run.Stderr.TrimEnd('\n').Split('\n'));
        Assert.Empty(Directory.GetFileSystemEntries(Folder));
    }

    [Fact]
    public void A_given_seeding_deals_the_groups_and_the_terminal_shows_groups_bracket_and_champion()
    {
        var run = Run("ball-grab", "--format", "groups-knockout", "--seeding", "d,c", "--advance", "1");
        Assert.True(run.ExitCode == 0, run.Stderr);

        // Seeding d, c, a, b: A = d, b; B = c, a. One from each group: the final only.
        Assert.StartsWith("tournament: ball-grab, 4 entrants, 1 seed, groups-knockout: 2 groups, the top 1 of each into the knockout, the final on 1 seed\ngroup stage: 4 matches; 4 to play, 0 already there\nfinal: 2 matches; 2 to play, 0 already there\n", run.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"\ngroup A: 1 (d|b) \d+ pts \([-+]?\d+\), 2 (d|b) \d+ pts \([-+]?\d+\)\ngroup B: 1 (c|a) \d+ pts \([-+]?\d+\), 2 (c|a) ", run.Stdout);
        Assert.Matches(@"\n  final: (d|b) \(A1\) v (c|a) \(B1\): wins \d:\d, goals \d+:\d+ -> \w \((wins|goal difference|seeding)\)\nchampion: \w\n", run.Stdout);
    }
}
