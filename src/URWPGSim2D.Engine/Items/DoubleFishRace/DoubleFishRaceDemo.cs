using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.DoubleFishRace;

/// <summary>
/// The demo strategy of 双鱼竞速: the fish swims a loop of waypoints round the circuit the way the
/// angle grows (up the left side, right through the top hole, down the right side outside the right
/// wall, left through the bottom hole), starting at the first waypoint ahead of it, slowing for the
/// holes.
/// </summary>
internal sealed class DoubleFishRaceDemo : IStrategy
{
    private const float Reached = 160f;

    // The loop, with the hole waypoints lined up on the holes' centre line (|z| 932.5).
    private static readonly (Vector2 Point, int Speed)[] Loop =
    [
        (new(-1200f, -650f), 6), (new(-500f, -932f), 3), (new(500f, -932f), 3), (new(1200f, -650f), 6),
        (new(1200f, 650f), 6), (new(500f, 932f), 3), (new(-500f, 932f), 3), (new(-1200f, 650f), 6),
    ];

    private int _next = -1;
    private Stuck _stuck;

    /// <inheritdoc/>
    public string TeamName => "double-fish-race-via-holes demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        FishView me = snapshot.Fish[fish[0]];
        if (_next < 0)
        {
            // The first waypoint ahead: the least angle forward of the fish's own about the centre.
            float mine = DoubleFishRaceReferee.Place(me.Position).Angle;
            float best = float.PositiveInfinity;
            for (int i = 0; i < Loop.Length; i++)
            {
                float ahead = DoubleFishRaceReferee.Place(Loop[i].Point).Angle - mine;
                ahead = ahead < 0.1f ? ahead + (2f * MathF.PI) : ahead;
                if (ahead < best)
                {
                    best = ahead;
                    _next = i;
                }
            }
        }

        if (Vector2.Distance(me.Position, Loop[_next].Point) < Reached)
        {
            _next = (_next + 1) % Loop.Length;
        }

        decisions[0] = _stuck.Escaping(me, out Decision escape) ? escape : Dribble.Swim(me, Loop[_next].Point, Loop[_next].Speed);
    }
}
