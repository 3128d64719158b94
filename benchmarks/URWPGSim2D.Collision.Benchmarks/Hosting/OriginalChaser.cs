using URWPGSim2D.Common;
using Decision = URWPGSim2D.Common.Decision;

namespace URWPGSim2D.Collision.Benchmarks.Hosting;

/// <summary>
/// A strategy in the original API's style for the benchmarks: every fish heads for the ball
/// nearest to it, as a typical old strategy reads the mission (positions, directions, the ball list).
/// </summary>
public sealed class OriginalChaser : MarshalByRefObject, URWPGSim2D.StrategyLoader.IStrategy
{
    private Decision[]? _decisions;

    /// <inheritdoc/>
    public string GetTeamName() => "original chaser";

    /// <inheritdoc/>
    public Decision[] GetDecision(Mission mission, int teamId)
    {
        var fishes = mission.TeamsRef[teamId].Fishes;
        _decisions ??= new Decision[mission.CommonPara.FishCntPerTeam];
        for (int i = 0; i < fishes.Count; i++)
        {
            var me = fishes[i];
            float best = float.MaxValue;
            float bx = 0f, bz = 0f;
            foreach (var ball in mission.EnvRef.Balls)
            {
                float dx = ball.PositionMm.X - me.PositionMm.X, dz = ball.PositionMm.Z - me.PositionMm.Z;
                float d = (dx * dx) + (dz * dz);
                if (d < best)
                {
                    best = d;
                    bx = dx;
                    bz = dz;
                }
            }

            float error = Microsoft.Xna.Framework.MathHelper.WrapAngle(MathF.Atan2(bz, bx) - me.BodyDirectionRad);
            _decisions[i].VCode = MathF.Abs(error) > 1f ? 3 : 10;
            _decisions[i].TCode = Math.Clamp(7 + (int)MathF.Round(error * 7f / 0.8f), 0, 14);
        }

        return _decisions;
    }
}
