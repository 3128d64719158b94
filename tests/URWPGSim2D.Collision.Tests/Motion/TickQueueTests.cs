namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The tick queue against a plain model (a list of entries per tick): whatever was pushed, taken
/// or looked at before, <see cref="TickQueue.Clear"/> leaves no entry behind (it starts from the
/// lowest tick it knows of), and the queue then gives exactly the entries pushed after, in order.
/// </summary>
public sealed class TickQueueTests
{
    [Fact]
    public void ClearForgetsEveryEntryWhateverWasLookedAt()
    {
        var random = new Random(7);
        var queue = new TickQueue();
        for (int trial = 0; trial < 400; trial++)
        {
            // Some entries, some of them taken, the next time asked or not, pushes below the time
            // asked (a contact going back in time): then cleared.
            int pushes = random.Next(0, 40);
            for (int i = 0; i < pushes; i++)
            {
                queue.PushTick(RandomTick(random), i, 0);
                if (random.Next(4) == 0)
                {
                    double next = queue.NextTime();
                    if (next >= 0.0 && random.Next(2) == 0)
                    {
                        queue.Recycle(queue.Take(next));
                    }
                }
            }

            queue.Clear();
            Assert.Equal(-1.0, queue.NextTime());

            // Afterwards the queue holds exactly what is pushed now, by tick, first in first out.
            var model = new SortedDictionary<int, List<int>>();
            int after = random.Next(0, 12);
            for (int i = 0; i < after; i++)
            {
                int tick = RandomTick(random);
                queue.PushTick(tick, 1000 + i, i);
                if (!model.TryGetValue(tick, out var list))
                {
                    model[tick] = list = [];
                }

                list.Add(1000 + i);
            }

            foreach (var (tick, slots) in model)
            {
                Assert.Equal((double)tick / TickQueue.Ticks, queue.NextTime());
                int first = queue.Take(queue.NextTime());
                var got = new List<int>();
                for (int node = first; node >= 0; node = queue.Next(node))
                {
                    got.Add(queue.SlotOf(node));
                }

                queue.Recycle(first);
                Assert.Equal(slots, got);
            }

            Assert.Equal(-1.0, queue.NextTime());
        }
    }

    // Ticks 1 … Ticks, often near the ends of the 64-tick words and of the step.
    private static int RandomTick(Random random) => random.Next(3) switch
    {
        0 => 1 + random.Next(TickQueue.Ticks),
        1 => Math.Clamp((64 * random.Next(1, 33)) + random.Next(-1, 2), 1, TickQueue.Ticks),
        _ => TickQueue.Ticks - random.Next(3),
    };
}
