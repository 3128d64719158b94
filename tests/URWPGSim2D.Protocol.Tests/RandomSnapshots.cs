using System.Numerics;

namespace URWPGSim2D.Protocol.Tests;

/// <summary>Random snapshots and assignments for round-trip tests (seeded, so a failure is reproducible).</summary>
internal static class RandomSnapshots
{
    /// <summary>A float from a mix of ordinary values, extremes, subnormals, signed zeros and exact integers.</summary>
    public static float Float(Random random) => random.Next(8) switch
    {
        0 => BitConverter.Int32BitsToSingle(random.Next() & 0x7F7FFFFF | (random.Next(2) << 31)), // any finite bit pattern (exponent < 255)
        1 => random.Next(2) == 0 ? 0f : -0f,
        2 => float.Epsilon * random.Next(1, 100),
        3 => random.Next(-3000, 3000),
        4 => float.MaxValue * (random.Next(2) == 0 ? 1 : -1),
        _ => (float)((random.NextDouble() - 0.5) * 4000),
    };

    public static Vector2 Vector(Random random) => new(Float(random), Float(random));

    public static AssignmentMessage Assignment(Random random)
    {
        int fishCount = random.Next(0, 12);
        var obstacles = new ObstacleView[random.Next(0, 4)];
        for (int i = 0; i < obstacles.Length; i++)
        {
            obstacles[i] = new ObstacleView(i, random.Next(2) == 0 ? ObstacleKind.Round : ObstacleKind.Rectangle, Vector(random), Float(random), Float(random), Float(random), Float(random));
        }

        var fish = new List<int>();
        for (int i = 0; i < fishCount; i++)
        {
            if (random.Next(2) == 0)
            {
                fish.Add(i);
            }
        }

        return new AssignmentMessage(1, random.Next(2), random.Next(2) == 0 ? "" : "ball-grab", random.Next(2) == 0 ? "match" : "抢球博弈 \"quoted\"\n",
            fish.ToArray(), fishCount, random.Next(0, 4), random.Next(0, 7000), random.Next(1, 1000), Float(random), Float(random), obstacles);
    }

    /// <summary>Fills <paramref name="s"/> with random contents, as the server's match does each cycle.</summary>
    public static void Fill(MatchSnapshot s, Random random, string itemName, int totalCycles)
    {
        var fish = s.FishBuffer;
        for (int i = 0; i < fish.Length; i++)
        {
            fish[i] = new FishView(i, random.Next(2), Vector(random), Float(random), Float(random), Float(random), Float(random), Float(random), new Decision(random.Next(16), random.Next(16)))
            {
                Width = Float(random),
                Joint1 = Float(random),
                Joint2 = Float(random),
                Joint3 = Float(random),
                TailLength1 = Float(random),
                TailLength2 = Float(random),
                TailLength3 = Float(random),
            };
        }

        var balls = s.BallBuffer;
        for (int i = 0; i < balls.Length; i++)
        {
            balls[i] = new BallView(i, Vector(random), Vector(random), Float(random));
        }

        s.SetHeader(random.Next(0, 7000), random.Next(2) == 0 ? [random.Next(0, 20), random.Next(0, 20)] : [random.Next(0, 20), random.Next(0, 20), random.Next(0, 20), random.Next(0, 20)]);
        var variables = new OrderedVariables();
        int n = random.Next(0, 5);
        for (int i = 0; i < n; i++)
        {
            variables.Set(random.Next(3) == 0 ? $"键{i}" : $"key{random.Next(10)}", random.Next(3) == 0 ? "" : $"value \\ {random.Next()}");
        }

        s.SetItem(itemName, variables, totalCycles);
        s.SetSidesSwapped(random.Next(2) == 0);
    }

    /// <summary>Fails unless the two snapshots hold the same values bit for bit.</summary>
    public static void AssertSame(MatchSnapshot expected, MatchSnapshot actual)
    {
        Xunit.Assert.Equal(expected.Cycle, actual.Cycle);
        Xunit.Assert.Equal(expected.TeamCount, actual.TeamCount);
        for (int t = 0; t < expected.TeamCount; t++)
        {
            Xunit.Assert.Equal(expected.GoalsOf(t), actual.GoalsOf(t));
        }

        Xunit.Assert.Equal(expected.SidesSwapped, actual.SidesSwapped);
        Xunit.Assert.Equal(expected.ItemName, actual.ItemName);
        Xunit.Assert.Equal(expected.TotalCycles, actual.TotalCycles);
        Xunit.Assert.Equal(expected.FieldLength, actual.FieldLength);
        Xunit.Assert.Equal(expected.Variables, actual.Variables); // ordered pairs
        Xunit.Assert.Equal(expected.Fish.Length, actual.Fish.Length);
        for (int i = 0; i < expected.Fish.Length; i++)
        {
            var e = expected.Fish[i];
            var a = actual.Fish[i];
            Xunit.Assert.Equal(Bits(e), Bits(a));
            Xunit.Assert.Equal(e.Decision, a.Decision);
            Xunit.Assert.Equal((e.Index, e.Team), (a.Index, a.Team));
        }

        for (int i = 0; i < expected.Balls.Length; i++)
        {
            var e = expected.Balls[i];
            var a = actual.Balls[i];
            Xunit.Assert.Equal(
                (e.Index, B(e.Position.X), B(e.Position.Y), B(e.Velocity.X), B(e.Velocity.Y), B(e.Radius)),
                (a.Index, B(a.Position.X), B(a.Position.Y), B(a.Velocity.X), B(a.Velocity.Y), B(a.Radius)));
        }
    }

    private static int B(float f) => BitConverter.SingleToInt32Bits(f);

    private static string Bits(FishView f) => string.Join(',', B(f.Position.X), B(f.Position.Y), B(f.Heading), B(f.Speed), B(f.AngularSpeed),
        B(f.BodyLength), B(f.HeadLength), B(f.Width), B(f.Joint1), B(f.Joint2), B(f.Joint3), B(f.TailLength1), B(f.TailLength2), B(f.TailLength3));
}
