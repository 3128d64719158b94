namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary>
/// <see cref="ShardResults"/>: which shards a re-submitted batch plays again. A shard is done when
/// its file holds every match of the shard; missing, left as <c>.partial</c>, cut short or garbled
/// files are played again; a file of another batch or another shard is refused, naming the file.
/// </summary>
public sealed class ShardResultsTests : TempFolderTest
{
    private static readonly BatchHeader Whole = new("default", string.Empty, "chase-ball;chase-ball", "scenario", 100, 1, 6, 3, 0, 1);

    public ShardResultsTests()
        : base("urwpg-shards-")
    {
        for (int i = 0; i < 3; i++)
        {
            var run = CliRun.Of(string.Empty, "run", "--item", "default", "--batch", "6", "--cycles", "3", "--shard", $"{i}/3", "--threads", "1", "--results", Shard(i));
            Assert.True(run.ExitCode == 0, run.Stderr);
        }
    }

    [Fact]
    public void EveryShardDoneLeavesNothingToPlay() => Assert.Empty(ShardResults.ToPlay(Folder, Whole, 3));

    [Fact]
    public void AnEmptyOrAbsentFolderPlaysEveryShard() =>
        Assert.Equal([0, 1, 2, 3], ShardResults.ToPlay(Path.Combine(Folder, "not there"), Whole, 4));

    [Fact]
    public void MissingPartialShortAndGarbledShardsArePlayedAgain()
    {
        File.Move(Shard(0), Shard(0) + ".partial");                                     // stopped before the rename
        File.WriteAllLines(Shard(2), File.ReadAllLines(Shard(2)).Take(2));              // header and 1 of its 2 matches
        Assert.Equal([0, 2], ShardResults.ToPlay(Folder, Whole, 3));

        File.WriteAllText(Shard(1), File.ReadAllText(Shard(1))[..40]);                  // not JSON any more
        Assert.Equal([0, 1, 2], ShardResults.ToPlay(Folder, Whole, 3));
    }

    [Fact]
    public void AShardWithItsMatchesOutOfOrderIsPlayedAgain()
    {
        string[] lines = File.ReadAllLines(Shard(1));
        File.WriteAllLines(Shard(1), [lines[0], lines[2], lines[1]]); // both matches, out of order
        Assert.Equal([1], ShardResults.ToPlay(Folder, Whole, 3));
    }

    [Fact]
    public void AFileOfAnotherBatchIsRefusedNamingIt()
    {
        var e = Assert.Throws<ResultFileException>(() => ShardResults.ToPlay(Folder, Whole with { Cycles = 4 }, 3));
        Assert.Equal($"{Shard(0)}: belongs to another batch (3 vs 4 cycles); use another --slurm folder or delete its shard files", e.Message);

        e = Assert.Throws<ResultFileException>(() => ShardResults.ToPlay(Folder, Whole, 2));
        Assert.Equal($"{Shard(0)}: belongs to another batch (3 vs 2 shards); use another --slurm folder or delete its shard files", e.Message);
    }

    [Fact]
    public void AFileOfAnotherShardIsRefusedNamingIt()
    {
        File.Copy(Shard(0), Shard(1), overwrite: true);
        var e = Assert.Throws<ResultFileException>(() => ShardResults.ToPlay(Folder, Whole, 3));
        Assert.Equal($"{Shard(1)}: holds shard 0/3, not 1/3", e.Message);
    }

    private string Shard(int i) => Path.Combine(Folder, ShardResults.FileName(i));
}
