namespace URWPGSim2D.Server.Tests.Items;

/// <summary>
/// Every competition item's match allocates nothing on the playing thread once warmed up: the
/// item's layout with its demo strategy on every team, seed 1 (noise on), cycles 300–999 measured
/// one by one. Busy moments come late: a contact whose own push leaves a fish still overlapping
/// its partner (the separation then lays out the fish's leaves to sum their pushes; a fish–fish
/// contact needs two layouts) first came at cycle 353 of ball-grab, 846 of polo 1 vs 1, and 381
/// (one fish) and 770 (two fish) of push-ball-via-channel; while the separation built its scratch
/// fish models on first need, those cycles allocated 4,032, 4,032, 2,016 and 2,016 B. A cycle in
/// which the referee records an event (a goal, a catch, half time, …) is not counted: the event
/// and its text are the match's record, kept for the summary and the trace. A cycle that allocates
/// is played again in a fresh match of the same seed: the play is deterministic, so a buffer of
/// the match grows again at the same cycle and fails; a one-off allocation of the runtime's (a
/// type or static first used there) does not come back and is not counted.
/// </summary>
public sealed class ItemMatchAllocationTests
{
    private const int First = 300, End = 1000;
    private const ulong Seed = 1;

    [Theory]
    [MemberData(nameof(ItemMatches.Slugs), MemberType = typeof(ItemMatches))]
    public void AnItemsDemoMatchAllocatesNothingAfterWarmUp(string slug)
    {
        var match = ItemMatches.Item(slug, Seed);
        match.PlayOut(First);
        Assert.False(match.IsOver, $"{slug} is over before cycle {First}: the test must measure another stretch");
        var perCycle = new long[End];
        var withEvent = new bool[End];
        int end = First;
        for (; end < End && !match.IsOver; end++)
        {
            int events = match.Rules.Events.Count;
            long before = GC.GetAllocatedBytesForCurrentThread();
            match.Step();
            perCycle[end] = GC.GetAllocatedBytesForCurrentThread() - before;
            withEvent[end] = match.Rules.Events.Count != events;
        }

        for (int cycle = First; cycle < end; cycle++)
        {
            if (perCycle[cycle] != 0L && !withEvent[cycle])
            {
                long repeated = AllocatedAt(slug, cycle);
                Assert.True(repeated == 0L, $"cycle {cycle} of {slug} allocated {perCycle[cycle]} B, and {repeated} B again in a fresh match");
            }
        }
    }

    // Bytes that cycle `cycle` allocates in a fresh match of the item.
    private static long AllocatedAt(string slug, int cycle)
    {
        var match = ItemMatches.Item(slug, Seed);
        match.PlayOut(cycle);
        long before = GC.GetAllocatedBytesForCurrentThread();
        match.Step();
        return GC.GetAllocatedBytesForCurrentThread() - before;
    }
}
