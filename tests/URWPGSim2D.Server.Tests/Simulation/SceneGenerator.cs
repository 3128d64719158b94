using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// Random valid scenes for the motion guarantee: 1–8 fish a team (chase-ball, which fights for the
/// balls and pins them against walls, goal blocks and obstacles, or a fixed random gear), 0–12
/// balls of radius 38, 58 or 78 mm at up to 2,000 mm/s, round and turned rectangular obstacles,
/// a 3000×2000 or 4500×3000 pool, noise on or off. Bodies are placed one by one at random and
/// a placement that overlaps anything placed before (brute force, <see cref="OverlapAudit"/>) is
/// drawn again, so every scene starts apart. Scene i is a pure function of i.
/// </summary>
internal static class SceneGenerator
{
    private static readonly float[] Radii = [38f, 58f, 78f];

    /// <summary>A match of scene <paramref name="index"/> (and its JSON, for a failure message).</summary>
    public static Match Build(int index, out string json)
    {
        var r = new Random(7919 * (index + 1));
        bool big = r.Next(2) == 0;
        float length = big ? 4500f : 3000f, width = big ? 3000f : 2000f;
        bool noise = r.Next(2) == 0;
        int fishPerTeam = 1 + r.Next(8);
        int balls = r.Next(13);
        int obstacles = r.Next(5);
        var fish = new List<string>();
        var ball = new List<string>();
        var obstacle = new string[obstacles];
        for (int i = 0; i < obstacles; i++)
        {
            obstacle[i] = r.Next(2) == 0
                ? Inv($"{{\"type\":\"rectangle\",\"center\":[{Coord(r, length, 250)},{Coord(r, width, 250)}],\"length\":{20 + r.Next(200)},\"width\":{20 + r.Next(120)},\"heading\":{r.NextDouble() * Math.PI:0.###}}}")
                : Inv($"{{\"type\":\"round\",\"center\":[{Coord(r, length, 150)},{Coord(r, width, 150)}],\"radius\":{20 + r.Next(100)}}}");
        }

        // Each fish and ball is drawn again (up to 40 times) until it overlaps nothing placed so far; else it is left out.
        string Scene() => Compose(length, width, noise, index, fish, ball, obstacle);
        for (int i = 0; i < 2 * fishPerTeam; i++)
        {
            for (int attempt = 0; attempt < 40; attempt++)
            {
                fish.Add(FishJson(r, i % 2, length, width));
                if (Apart(Scene()))
                {
                    break;
                }

                fish.RemoveAt(fish.Count - 1);
            }
        }

        for (int i = 0; i < balls; i++)
        {
            for (int attempt = 0; attempt < 40; attempt++)
            {
                float radius = Radii[r.Next(3)];
                double speed = r.NextDouble() * 2000.0, angle = r.NextDouble() * 2 * Math.PI;
                ball.Add(Inv($"{{\"position\":[{Coord(r, length, radius + 160)},{Coord(r, width, radius + 5)}],\"velocity\":[{speed * Math.Cos(angle):0.#},{speed * Math.Sin(angle):0.#}],\"radius\":{radius}}}"));
                if (Apart(Scene()))
                {
                    break;
                }

                ball.RemoveAt(ball.Count - 1);
            }
        }

        json = Scene();
        return Parse(json);
    }

    private static string FishJson(Random r, int team, float length, float width)
    {
        string place = Inv($"\"team\":{team},\"position\":[{Coord(r, length, 300)},{Coord(r, width, 300)}],\"heading\":{(r.NextDouble() * 2 * Math.PI) - Math.PI:0.###}");
        return r.Next(3) != 0
            ? $"{{{place},\"strategy\":\"chase-ball\"}}"
            : Inv($"{{{place},\"strategy\":\"fixed\",\"decision\":{{\"vcode\":{8 + r.Next(8)},\"tcode\":{r.Next(16)}}}}}");
    }

    private static string Compose(float length, float width, bool noise, int index, List<string> fish, List<string> balls, string[] obstacles)
    {
        var s = new StringBuilder();
        s.Append(Inv($"{{\"field\":{{\"length\":{length},\"width\":{width},\"goalBlocks\":true}},\"seed\":{index},\"noise\":{(noise ? "true" : "false")},"));
        s.Append("\"fish\":[").AppendJoin(',', fish).Append("],\"balls\":[").AppendJoin(',', balls);
        s.Append("],\"obstacles\":[").AppendJoin(',', obstacles).Append("]}");
        return s.ToString();
    }

    private static bool Apart(string json)
    {
        try
        {
            return OverlapAudit.DeepestOverlap(Parse(json).World, out _) == 0f;
        }
        catch (ScenarioException)
        {
            return false;
        }
    }

    private static Match Parse(string json)
    {
        var scenario = ScenarioFile.Parse(json);
        return MatchBuilder.Build(scenario, noise: scenario.Noise);
    }

    private static string Coord(Random r, float size, float margin) =>
        (((r.NextDouble() * 2) - 1) * ((size / 2) - margin)).ToString("0.#", CultureInfo.InvariantCulture);

    private static string Inv(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
