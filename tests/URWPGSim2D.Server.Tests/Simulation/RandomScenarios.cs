namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>Random but valid scenario files (fixed seed per scenario) for the invariant tests.</summary>
internal static class RandomScenarios
{
    private static readonly string[] Strategies = ["chase-ball", "idle", "fixed"];

    /// <summary>The JSON of random scenario number <paramref name="index"/>.</summary>
    public static string Json(int index)
    {
        var r = new Random(1000 + index);
        bool big = r.Next(3) == 0;
        float length = big ? 4500f : 3000f;
        float width = big ? 3000f : 2000f;
        var s = new StringBuilder();
        s.Append(Inv($"{{\"field\":{{\"length\":{length},\"width\":{width},\"goalBlocks\":{(r.Next(4) != 0 ? "true" : "false")}}},"));
        s.Append(Inv($"\"seed\":{r.Next(1000)},\"noise\":{(r.Next(2) == 0 ? "true" : "false")},\"fish\":["));
        int fish = r.Next(5);
        for (int i = 0; i < fish; i++)
        {
            string strategy = Strategies[r.Next(Strategies.Length)];
            s.Append(i == 0 ? string.Empty : ",").Append(Inv($"{{\"team\":{i % 2},\"position\":[{Coord(r, length, 350)},{Coord(r, width, 350)}],\"heading\":{(r.NextDouble() * 6.28) - 3.14:0.###},\"strategy\":\"{strategy}\""));
            if (strategy == "fixed")
            {
                s.Append(Inv($",\"decision\":{{\"vcode\":{r.Next(16)},\"tcode\":{r.Next(16)}}}"));
            }

            s.Append('}');
        }

        s.Append("],\"balls\":[");
        int balls = r.Next(10);
        for (int i = 0; i < balls; i++)
        {
            float radius = new[] { 38f, 58f, 78f }[r.Next(3)];
            double speed = r.Next(3) == 0 ? r.NextDouble() * 5000 : r.NextDouble() * 600;
            double angle = r.NextDouble() * Math.PI * 2;
            s.Append(i == 0 ? string.Empty : ",").Append(Inv($"{{\"position\":[{Coord(r, length, radius + 5)},{Coord(r, width, radius + 5)}],\"velocity\":[{speed * Math.Cos(angle):0.#},{speed * Math.Sin(angle):0.#}],\"radius\":{radius}}}"));
        }

        s.Append("],\"obstacles\":[");
        int obstacles = r.Next(5);
        for (int i = 0; i < obstacles; i++)
        {
            s.Append(i == 0 ? string.Empty : ",");
            if (r.Next(2) == 0)
            {
                s.Append(Inv($"{{\"type\":\"rectangle\",\"center\":[{Coord(r, length, 200)},{Coord(r, width, 200)}],\"length\":{20 + r.Next(180)},\"width\":{20 + r.Next(180)},\"heading\":{r.NextDouble() * 3:0.###}}}"));
            }
            else
            {
                int radius = 20 + r.Next(80);
                s.Append(Inv($"{{\"type\":\"round\",\"center\":[{Coord(r, length, radius + 5)},{Coord(r, width, radius + 5)}],\"radius\":{radius}}}"));
            }
        }

        s.Append("]}");
        return s.ToString();
    }

    private static string Coord(Random r, float size, float margin) =>
        (((r.NextDouble() * 2) - 1) * ((size / 2) - margin)).ToString("0.#", CultureInfo.InvariantCulture);

    private static string Inv(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
