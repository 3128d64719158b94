namespace URWPGSim2D.Server.Tests.Batch;

/// <summary>The aggregate's arithmetic on hand-made results, and the result file's round trip.</summary>
public sealed class BatchSummaryTests
{
    [Fact]
    public void MeanSampleStandardDeviationRangeAndTotal()
    {
        var (mean, sd, min, max, total) = BatchSummary.Stats([1, 2, 3, 4]);
        Assert.Equal(2.5, mean, 12);
        Assert.Equal(1.2909944487358056, sd, 12); // sqrt(5/3)
        Assert.Equal((1.0, 4.0, 10.0), (min, max, total));
        Assert.Equal((3.0, 0.0), (BatchSummary.Stats([3]).Mean, BatchSummary.Stats([3]).Sd));
    }

    [Fact]
    public void TheAggregateCountsOutcomesAndFindsTheWorstOverlap()
    {
        var header = new BatchHeader("default", string.Empty, "chase-ball;idle", "scenario", 100, 10, 3, 50, 0, 1);
        MatchResult[] results = [Result(0, 2, 1, 0.004f), Result(1, 0, 0, 0.009f), Result(2, 1, 3, 0.002f)];
        string[] lines = BatchSummary.Aggregate(header, results).TrimEnd('\n').Split('\n');
        Assert.Equal(
            [
                "batch: 3 matches, seeds 10 to 12, 50 cycles each, scene default",
                "goals team 0 (chase-ball): mean 1.000, sd 1.000, min 0, max 2, total 3",
                "goals team 1 (idle): mean 1.333, sd 1.528, min 0, max 3, total 4",
                "outcomes: team 0 won 1, team 1 won 1, drawn 1",
                "largest leftover overlap: 0.009 mm (match 1, cycle 7)",
                "strategy faults: 2",
            ],
            lines);
        Assert.Equal("match 2 (seed 12): goals 1-3, contacts 28, contact events 5, sub-steps 9, overlap 0.002 mm, faults 1\n", BatchSummary.Line(results[2]));
    }

    [Fact]
    public void AnItemsLineGivesTheWinnerAndTheRuleThatDecided()
    {
        // 1-1 on goals, decided by the item's tie rule: the winner is on the line, not only in the results file.
        var won = Result(0, 1, 1, 0f) with { Item = "ball-grab", Scores = [1, 1], Winner = 1, Rule = "earlier first score" };
        Assert.Equal("match 0 (seed 10): score 1-1, team 1 won by earlier first score, contacts 28, contact events 5, sub-steps 9, overlap 0.000 mm, faults 0\n", BatchSummary.Line(won));
        var tie = won with { Scores = [0, 0, 2, -1], Winner = -1, Rule = "tie (no score)" };
        Assert.Equal("match 0 (seed 10): score 0-0-2-n/a, no winner: tie (no score), contacts 28, contact events 5, sub-steps 9, overlap 0.000 mm, faults 0\n", BatchSummary.Line(tie));
    }

    [Fact]
    public void AResultFileReadsBackAsWritten()
    {
        var header = new BatchHeader("file s.json sha256 00ff", "0=My.dll", "My.dll;chase-ball", "off", 250, 4_000_000_000_000UL, 7, 123, 2, 3);
        MatchResult[] results = [Result(2, 5, 0, 0.123456789f), Result(5, 0, 1, 1e-7f)];
        string path = Path.Combine(Path.GetTempPath(), $"urwpg-results-{System.Guid.NewGuid():N}.jsonl");
        try
        {
            ResultFile.Write(path, header, results);
            var (readHeader, readResults) = ResultFile.Read(path);
            Assert.Equal(header, readHeader);
            Assert.Equal(2, readResults.Count);
            Assert.True(results[0].SameAs(readResults[0]) && results[1].SameAs(readResults[1]));
            Assert.Equal(2, readHeader.ShardMatches); // matches 2 and 5 of 7
        }
        finally
        {
            File.Delete(path);
        }
    }

    private static MatchResult Result(int index, int goals0, int goals1, float overlap) =>
        new(index, 10 + (ulong)index, 50, goals0, goals1, [1, 2, 3, 4, 5, 6, 7], 9, 3, 5, overlap, 7, index == 1 ? 1 : index == 2 ? 1 : 0);
}
