# The two user strategies the ladder benchmarks play, as sources: write_strategies DIR makes
# DIR/toward (each fish swims at a ball) and DIR/still (every fish stops). Sourced by
# ladder-vs-tournament.sh and ladder-workers.sh.
write_strategies() {
  mkdir -p "$1/toward" "$1/still"
  cat >"$1/toward/Toward.cs" <<'CS'
using System;
using System.Numerics;
using URWPGSim2D.Strategies;
public sealed class Toward : IStrategy
{
    public string TeamName => "toward";
    public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d)
    {
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = s.Fish[fish[k]];
            Vector2 to = s.Balls[k % s.Balls.Length].Position - me.Position;
            float error = MathF.IEEERemainder(MathF.Atan2(to.Y, to.X) - me.Heading, 2f * MathF.PI);
            d[k] = new Decision(MathF.Abs(error) < 0.5f ? 12 : 4, 7 + (int)MathF.Round(Math.Clamp(error / 0.5f, -1f, 1f) * 7f));
        }
    }
}
CS
  cat >"$1/still/Still.cs" <<'CS'
using System;
using URWPGSim2D.Strategies;
public sealed class Still : IStrategy
{
    public string TeamName => "still";
    public void Decide(MatchSnapshot s, ReadOnlySpan<int> fish, Span<Decision> d) { d.Fill(Decision.Stop); }
}
CS
}
