namespace URWPGSim2D.Server.Tests.Batch.Slurm;

/// <summary><see cref="ArraySpec"/>: the shards to play as sbatch's <c>--array</c> list.</summary>
public sealed class ArraySpecTests
{
    [Theory]
    [InlineData(new[] { 0 }, "0")]
    [InlineData(new[] { 0, 1, 2, 3 }, "0-3")]
    [InlineData(new[] { 1, 3 }, "1,3")]
    [InlineData(new[] { 2, 3 }, "2-3")]
    [InlineData(new[] { 0, 1, 2, 5, 7, 8, 9, 999 }, "0-2,5,7-9,999")]
    public void ConsecutiveShardsBecomeRanges(int[] shards, string array) => Assert.Equal(array, ArraySpec.Format(shards));
}
