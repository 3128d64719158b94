# What the ladder benchmarks share (sourced by ladder-vs-tournament.sh and ladder-workers.sh).

# The two user strategies they play, as sources: write_strategies DIR makes DIR/toward (each fish
# swims at a ball) and DIR/still (every fish stops).
write_strategies() {
  strategies=$1
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

# serve_ladder SERVER OUT ARGS...: `ladder serve ARGS` in the background (ball-grab, one-minute
# matches, the organiser's token bench-organiser), its output in OUT.out and OUT.err; once it answers,
# sets pid and url, adds the teams toward and still and submits their sources (write_strategies first).
serve_ladder() {
  local server=$1 out=$2 team token
  shift 2
  dotnet "$server" ladder serve --item ball-grab --minutes 1 --port 0 --admin-token bench-organiser "$@" >"$out.out" 2>"$out.err" &
  pid=$!
  until [ -s "$out.out" ]; do sleep 0.05; done
  url=$(head -1 "$out.out" | cut -d' ' -f4)
  for team in toward still; do
    token=$(dotnet "$server" ladder team add "$team" --server "$url" --admin-token bench-organiser | tail -1)
    dotnet "$server" ladder submit --server "$url" --token "$token" "$strategies/$team" >/dev/null
  done
}
