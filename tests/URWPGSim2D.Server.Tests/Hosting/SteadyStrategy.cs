namespace URWPGSim2D.Server.Tests.Hosting;

/// <summary>
/// A small SDK strategy whose decisions depend on everything a snapshot carries that a transport
/// could get wrong (positions, headings, balls, mission variables, the half-time swap, the score,
/// and its own call count): two matches of it are the same only if every snapshot crossed exactly.
/// </summary>
internal static class SteadyStrategy
{
    /// <summary>Writes the strategy's source as Steady.cs into <paramref name="folder"/> and returns its path.</summary>
    public static string Write(string folder)
    {
        string path = Path.Combine(folder, "Steady.cs");
        File.WriteAllText(path, """
            using System;
            using URWPGSim2D.Strategies;
            public sealed class Steady : IStrategy
            {
                private int _calls;
                public string TeamName => "steady";
                public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
                {
                    _calls++;
                    for (int i = 0; i < d.Length; i++)
                    {
                        var me = s.Fish[fish[i]];
                        var target = s.Balls.Length > 0 ? s.Balls[i % s.Balls.Length].Position : System.Numerics.Vector2.Zero;
                        float want = MathF.Atan2(target.Y - me.Position.Y, target.X - me.Position.X) - me.Heading;
                        int turn = 7 + (int)Math.Clamp(MathF.Round(MathF.IEEERemainder(want, MathF.Tau) * 4), -7, 7);
                        d[i] = new Decision((_calls + s.Variables.Count + (s.SidesSwapped ? 3 : 0) + s.GoalsOf(0)) % 6 + 9, turn);
                    }
                }
            }
            """);
        return path;
    }
}
