namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The held hits come out ordered by tick and, within a tick, in the order they were held,
/// whichever of the two sorts runs (insertion for a few hits, counting for many): checked
/// against LINQ's stable ordering over random ticks, with few distinct ticks so ties are common.
/// </summary>
public sealed class HeldHitsTests
{
    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(7)]
    [InlineData(HeldHits.InsertionSortLimit)]
    [InlineData(HeldHits.InsertionSortLimit + 1)]
    [InlineData(300)]
    public void SortByTickIsStableAndOrdered(int count)
    {
        var random = new Random(count);
        for (int trial = 0; trial < 50; trial++)
        {
            var from = new HeldHits();
            int[] ticks = new int[count];
            int spread = trial % 2 == 0 ? 6 : TickQueue.Ticks;
            for (int i = 0; i < count; i++)
            {
                ticks[i] = random.Next(spread) * (TickQueue.Ticks / spread);
                from.Add(ticks[i], slot: i, generation: 1000 + i, default);
            }

            var sorted = new HeldHits();
            sorted.SortByTick(from);

            int[] expected = Enumerable.Range(0, count).OrderBy(i => ticks[i]).ToArray();
            Assert.Equal(count, sorted.Count);
            Assert.Equal(expected, sorted.Slot.ToArray());
            Assert.Equal(expected.Select(i => ticks[i]), sorted.Tick.ToArray());
            Assert.Equal(expected.Select(i => 1000 + i), sorted.Generation.ToArray());
        }
    }

    [Fact]
    public void SortingAgainReusesTheSetAndForgetsTheLastOrder()
    {
        var from = new HeldHits();
        from.Add(5, 0, 0, default);
        from.Add(3, 1, 0, default);
        var sorted = new HeldHits();
        sorted.SortByTick(from);
        Assert.Equal(new[] { 1, 0 }, sorted.Slot.ToArray());

        from.Clear();
        from.Add(9, 7, 0, default);
        sorted.SortByTick(from);
        Assert.Equal(new[] { 7 }, sorted.Slot.ToArray());
        Assert.Equal(new[] { 9 }, sorted.Tick.ToArray());
    }
}
