namespace URWPGSim2D.Server.Tests.Batch;

/// <summary>A match that fails inside the server still has its line in a batch, with the reason; the others are played.</summary>
public sealed class BatchFailureTests() : TempFolderTest("urwpg-batch-fail-")
{
    [Fact]
    public void Every_match_has_its_line_when_one_fails_inside_the_server()
    {
        var header = new BatchHeader("default", string.Empty, "idle;idle", "scenario", 100, 1, 3, 5, 0, 1);
        var lines = new List<string>();
        var results = BatchRunner.Run(header, 2, seed => seed == 2 ? throw new IOException("disk \u001b[2J on fire") : new MatchSettings(DefaultScenario.Load(), 5, seed).Build(), r => lines.Add(BatchSummary.Line(r)));
        Assert.Equal(3, results.Length);
        Assert.Null(results[0].Failed);
        Assert.Equal(5, results[0].Cycles);
        Assert.Equal("IOException: disk \\u001b[2J on fire", results[1].Failed);
        Assert.Null(results[2].Failed);
        Assert.Equal("match 1 (seed 2): failed inside the server: IOException: disk \\u001b[2J on fire\n", lines[1]);

        string file = Path.Combine(Folder, "results.jsonl");
        ResultFile.Write(file, header, results);
        Assert.EndsWith(",\"strategyFaults\":0,\"failed\":\"IOException: disk \\\\u001b[2J on fire\"}", File.ReadAllLines(file)[2], StringComparison.Ordinal);
        var read = ResultFile.Read(file).Results;
        Assert.Equal(results[1].Failed, read[1].Failed);
        Assert.Null(read[0].Failed);
    }
}
