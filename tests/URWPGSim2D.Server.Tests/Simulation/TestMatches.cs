using URWPGSim2D.Engine.Matches;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>Builds matches from scenario JSON for tests (noise off unless the JSON turns it on).</summary>
internal static class TestMatches
{
    /// <summary>A match from scenario JSON; "noise" defaults to false here.</summary>
    public static Match FromJson(string json, TeamStrategy?[]? teams = null, int timeoutMs = MatchBuilder.DefaultStrategyTimeoutMs, System.TimeSpan? timeBank = null)
    {
        var scenario = ScenarioFile.Parse(json);
        bool noise = json.Contains("\"noise\"", System.StringComparison.Ordinal) && scenario.Noise;
        return MatchBuilder.BuildRecording(scenario, teams, noise: noise, strategyTimeoutMs: timeoutMs, timeBank: timeBank);
    }

    /// <summary>A match with only balls (positions and velocities given as x, z, vx, vz quadruples).</summary>
    public static Match Balls(string extra, params float[] ball)
    {
        var parts = new System.Text.StringBuilder();
        for (int i = 0; i < ball.Length; i += 4)
        {
            parts.Append(i == 0 ? string.Empty : ",").Append(System.FormattableString.Invariant($"{{\"position\":[{ball[i]},{ball[i + 1]}],\"velocity\":[{ball[i + 2]},{ball[i + 3]}]}}"));
        }

        return FromJson($"{{\"fish\":[],\"balls\":[{parts}]{extra}}}");
    }

    /// <summary>Plays <paramref name="cycles"/> cycles.</summary>
    public static void Play(this Match match, int cycles)
    {
        for (int i = 0; i < cycles; i++)
        {
            match.Step();
        }
    }

    /// <summary>Ball position.</summary>
    public static Vector2 BallAt(this Match match, int ball) => match.World.Balls[ball].Position;
}
