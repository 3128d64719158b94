using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.Snooker;

/// <summary>
/// The demo strategy of 斯诺克: the fish takes the nearest ball that would be a good pot now and
/// pushes it to the mouth of the pocket nearest to that ball, then through the mouth into the
/// pocket (slowly for the last 400 mm).
/// </summary>
internal sealed class SnookerDemo(SnookerReferee referee) : IStrategy
{
    private static readonly float[] PocketX = [(-SnookerLayout.FieldLength / 2f) + (SnookerLayout.PocketWidth / 2f), 0f, (SnookerLayout.FieldLength / 2f) - (SnookerLayout.PocketWidth / 2f)];
    private Stuck _stuck;
    private Dribble _dribble;

    /// <inheritdoc/>
    public string TeamName => "snooker demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        FishView me = snapshot.Fish[fish[0]];
        if (_stuck.Escaping(me, out Decision escape))
        {
            decisions[0] = escape;
            return;
        }

        int ball = -1;
        float best = float.PositiveInfinity;
        for (int i = 0; i < snapshot.Balls.Length; i++)
        {
            if ((referee.BallsInField & (1 << i)) == 0 || !referee.IsGood(i))
            {
                continue;
            }

            float d = Vector2.Distance(me.Position, snapshot.Balls[i].Position);
            if (d < best)
            {
                best = d;
                ball = i;
            }
        }

        if (ball < 0)
        {
            decisions[0] = Decision.Stop;
            return;
        }

        BallView b = snapshot.Balls[ball];
        float row = b.Position.Y < 0f ? -1f : 1f;
        float x = PocketX[0];
        foreach (float px in PocketX)
        {
            x = MathF.Abs(px - b.Position.X) < MathF.Abs(x - b.Position.X) ? px : x;
        }

        float mouthZ = row * ((SnookerLayout.FieldWidth / 2f) - SnookerLayout.PocketWidth - 250f);
        bool inMouth = MathF.Abs(b.Position.X - x) < 60f && MathF.Abs(b.Position.Y - mouthZ) < 300f;
        Vector2 target = inMouth ? new Vector2(x, row * SnookerLayout.FieldWidth / 2f) : new Vector2(x, mouthZ);
        bool close = Vector2.Distance(b.Position, target) < 400f;
        decisions[0] = _dribble.Toward(me, b.Position, b.Radius, target, close ? 4 : 6, new Vector2(snapshot.FieldLength, snapshot.FieldWidth));
    }
}
