namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The contact cache against a plain dictionary of the same touches: random answers over a few
/// bodies (so that many pairs share a probe run of the open-addressing table and it wraps and
/// grows, or reserved far larger than the touches), random step ends: the same pairs touch, the same ones end at each step's end (each
/// once, in the order of the answer that began the touch), the same ones are pressing.
/// </summary>
public sealed class ContactCacheTests
{
    [Theory]
    [InlineData(1, 0)]
    [InlineData(2, 0)]
    [InlineData(3, 0)]
    [InlineData(4, 0)]
    [InlineData(5, 3000)] // a table reserved far larger than the touches (as a crowd's is): mostly empty words of the used-slot bitmap
    [InlineData(6, 100)]
    public void TouchesBeginPressAndEndAsAPlainDictionarySays(int seed, int reserve)
    {
        var random = new Random(seed);
        var cache = new ContactCache();
        cache.Reserve(reserve);
        var model = new Dictionary<(int, int), (long Step, double Time)>();
        var began = new Dictionary<(int, int), (int, int)>();
        long step = 0;
        cache.BeginStep();
        step++;
        for (int round = 0; round < 4000; round++)
        {
            int op = random.Next(10);
            if (op < 7)
            {
                int a = random.Next(40), b = random.Next(40);
                if (a == b)
                {
                    continue;
                }

                double time = random.NextDouble();
                var key = (Math.Min(a, b), Math.Max(a, b));
                bool expected = !model.ContainsKey(key);
                Assert.Equal(expected, cache.Touch(a, b, time));
                if (expected)
                {
                    began[key] = (a, b);
                }

                model[key] = (step, time);
            }
            else if (op < 9)
            {
                int a = random.Next(40), b = random.Next(40);
                double time = random.NextDouble(), window = random.NextDouble() * 1.5;
                var key = (Math.Min(a, b), Math.Max(a, b));
                bool expected = model.TryGetValue(key, out var last) && ((step - last.Step) + time) - last.Time <= window;
                Assert.Equal(expected, cache.IsPressing(a, b, time, window));
                Assert.Equal(model.ContainsKey(key), cache.IsTouching(b, a));
            }
            else
            {
                var sink = new Collect();
                int count = cache.EndStep(ref sink);
                var expected = model.Where(kv => step - kv.Value.Step >= 1).Select(kv => began[kv.Key]).OrderBy(k => k).ToList();
                Assert.Equal(expected.Count, count);
                Assert.Equal(expected, sink.Pairs.OrderBy(k => k).ToList());
                foreach (var (a, b) in expected)
                {
                    model.Remove((Math.Min(a, b), Math.Max(a, b)));
                }

                cache.BeginStep();
                step++;
            }

            Assert.Equal(model.Count, cache.Count);
        }

        foreach (var key in model.Keys)
        {
            Assert.True(cache.IsTouching(key.Item1, key.Item2));
        }
    }

    [Fact]
    public void ClearForgetsEveryTouch()
    {
        var cache = new ContactCache();
        cache.BeginStep();
        for (int i = 1; i < 100; i++)
        {
            cache.Touch(0, i, 0.5);
        }

        Assert.Equal(99, cache.Count);
        cache.Clear();
        Assert.Equal(0, cache.Count);
        Assert.False(cache.IsTouching(0, 5));
        Assert.True(cache.Touch(0, 5, 0.25));
    }

    private struct Collect : ContactCache.IEndedSink
    {
        public Collect()
        {
        }

        public List<(int, int)> Pairs { get; } = [];

        public readonly void Ended(int a, int b) => Pairs.Add((a, b));
    }
}
