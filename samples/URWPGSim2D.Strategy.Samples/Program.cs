using System;
using URWPGSim2D.Common;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.Strategy.Samples;

/// <summary>Runs the strategy samples of docs/strategies.md on a hand-made mission; exit code 1 when one fails.</summary>
internal static class Program
{
    private static int Main()
    {
        int failed = 0;
        failed += Check("OriginalApiStrategy", OriginalApi);
        failed += Check("SdkStrategy", () =>
        {
            var s = new MyTeam.TowardTheBall();
            Expect(s.TeamName == "toward the ball", "team name");
        });
        failed += Check("DrawingStrategy", () =>
        {
            var s = new MyTeam.DrawsItsPlan();
            Expect(s.TeamName == "draws its plan" && !URWPGSim2D.Strategies.DebugDraw.IsOn, "team name, drawings off outside a match");
        });
        failed += Check("SensingStrategy", () =>
        {
            var s = new MyTeam.LookBeforeSwimming();
            Expect(s.TeamName == "look before swimming", "team name");
        });
        return failed == 0 ? 0 : 1;
    }

    // A fish at (−500, 0) facing +X with the ball straight ahead at (0, 0): it drives straight at it.
    private static void OriginalApi()
    {
        var mission = new Mission();
        var team = new Team<RoboFish>();
        var fish = new RoboFish { PositionMm = new Xna.Vector3(-500f, 0f, 0f) };
        fish.PolygonVertices[0] = new Xna.Vector3(-390f, 0f, 0f);
        team.Fishes.Add(fish);
        mission.TeamsRef.Add(team);
        mission.TeamsRef.Add(new Team<RoboFish>());
        mission.EnvRef.Balls.Add(new Ball());
        Decision[] d = new URWPGSim2D.Strategy.Strategy().GetDecision(mission, 0);
        Expect(d.Length == 1, "one decision per fish");
        Expect(d[0].VCode == 14 && d[0].TCode == 7, $"full speed straight ahead, got V{d[0].VCode} T{d[0].TCode}");
    }

    private static int Check(string name, Action run)
    {
        try
        {
            run();
            Console.WriteLine($"sample {name}: ok");
            return 0;
        }
        catch (InvalidOperationException e)
        {
            Console.WriteLine($"sample {name}: FAILED: {e.Message}");
            return 1;
        }
    }

    private static void Expect(bool condition, string what)
    {
        if (!condition)
        {
            throw new InvalidOperationException(what);
        }
    }
}
