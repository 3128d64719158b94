using System.Globalization;
using static URWPGSim2D.Engine.Items.DoubleFishRace.DoubleFishRaceLayout;

namespace URWPGSim2D.Engine.Items.DoubleFishRace;

/// <summary>
/// The rules of 双鱼竞速, as the original's <c>DoubleFishRaceViaHoles</c>. Each fish's place on the
/// circuit is its position angle about the centre, measured from +x toward +z in [0, 2π), and its
/// quadrant (1: x &gt; 0, z ≥ 0; 2: x ≤ 0, z &gt; 0; 3: x &lt; 0, z ≤ 0; 4: x ≥ 0, z &lt; 0). After
/// each cycle, for team 0's fish then team 1's:
/// <list type="number">
/// <item>A foul (event <c>foul</c>), unless the fish is on an axis: it moved back a quadrant or
/// jumped two; or it crossed z = 0 (z · previous z ≤ 0) between the side walls' inner faces
/// (−800 ≤ x ≤ 800), or by more than half the field's length in x. The fish is put back by the
/// quadrant it was in: 1 — right of the right wall, (1000, 0) facing +z; 2 — below the centre wall,
/// (0, 915) facing −x; 3 — (−1000, 0) facing −z; 4 — (0, −915) facing +x. Its angle swum is unchanged.</item>
/// <item>Otherwise the angle it moved since the last cycle is added to its angle swum (+2π when it
/// leaves quadrant 4).</item>
/// </list>
/// Then the fish level with each other (angles within 0.035 rad, 2°) or the time up end the match;
/// the larger angle swum wins. The score is the angle swum in whole degrees. The original publishes no
/// <c>HtMissionVariables</c>.
/// </summary>
internal sealed class DoubleFishRaceReferee : ItemReferee
{
    /// <summary>How close (rad) the two angles must be for the fish to be level.</summary>
    public const float Level = 0.035f;

    private readonly float[] _previousAngle = [MathF.PI, 0f];
    private readonly float[] _angle = [MathF.PI, 0f];
    private readonly double[] _swum = [0, 0];
    private readonly int[] _quadrant = [3, 1];
    private readonly int[] _previousQuadrant = [3, 1];
    private readonly Vector2[] _previousPosition = new Vector2[2];

    /// <summary>Creates the referee of one match.</summary>
    public DoubleFishRaceReferee(DoubleFishRaceItem item, ScenarioDefinition scenario, int cycles)
        : base(item, scenario, cycles, halves: 1)
    {
    }

    /// <summary>The angle team <paramref name="team"/>'s fish has swum round the centre, rad.</summary>
    public double Swum(int team) => _swum[team];

    /// <summary>The position angle of team <paramref name="team"/>'s fish after the last cycle, rad in [0, 2π).</summary>
    public float Angle(int team) => _angle[team];

    /// <summary>The position angle in [0, 2π) of a point about the centre and its quadrant, as the original computes them.</summary>
    public static (float Angle, int Quadrant) Place(Vector2 p)
    {
        double a;
        if (p.X != 0)
        {
            a = Math.Atan2(Math.Abs(p.Y), Math.Abs(p.X));
        }
        else
        {
            a = p.Y < 0 ? 3 * Math.PI / 2 : p.Y > 0 ? Math.PI / 2 : 0;
        }

        int q = 0;
        if (p.X > 0 && p.Y >= 0)
        {
            q = 1;
        }
        else if (p.X <= 0 && p.Y > 0)
        {
            a = Math.PI - a;
            q = 2;
        }
        else if (p.X < 0 && p.Y <= 0)
        {
            a = Math.PI + a;
            q = 3;
        }
        else if (p.X >= 0 && p.Y < 0)
        {
            a = (2 * Math.PI) - a;
            q = 4;
        }

        return ((float)a, q);
    }

    /// <summary>Where a fish that fouled is put back, by the quadrant it was in before (1–4), and its heading.</summary>
    public static (Vector2 Position, float Heading) Restart(int quadrant)
    {
        var side = Walls[2];
        var centre = Walls[1];
        return quadrant switch
        {
            1 => (new Vector2(side.Centre.X + (side.Length / 2f) + 50f, side.Centre.Y), MathF.PI / 2f),
            2 => (new Vector2(centre.Centre.X, centre.Centre.Y + (centre.Width / 2f) + 50f), MathF.PI),
            3 => (new Vector2(-side.Centre.X - (side.Length / 2f) - 50f, side.Centre.Y), 3f * MathF.PI / 2f),
            _ => (new Vector2(centre.Centre.X, centre.Centre.Y - (centre.Width / 2f) - 50f), 0f),
        };
    }

    /// <inheritdoc/>
    protected override void OnStart(World world)
    {
        for (int t = 0; t < 2; t++)
        {
            _previousPosition[t] = world.Fish[t].Position;
        }
    }

    /// <inheritdoc/>
    protected override bool Score(World world, ReadOnlySpan<ContactRecord> contacts)
    {
        bool moved = false;
        for (int t = 0; t < 2; t++)
        {
            var fish = world.Fish[t];
            Vector2 p = fish.Position;
            (_angle[t], _quadrant[t]) = Place(p);
            if (Fouled(p, _previousPosition[t], _quadrant[t], _previousQuadrant[t]))
            {
                var (at, heading) = Restart(_previousQuadrant[t]);
                Placement.Place(fish, at, heading);
                AddEvent(world.Cycle, "foul", t, t, -1, double.NaN, $"team {t}'s fish swims the wrong way or cuts across: put back in quadrant {_previousQuadrant[t]}");
                moved = true;
            }
            else
            {
                float step = _previousQuadrant[t] == 4 && _quadrant[t] != 4
                    ? _angle[t] + (2 * MathF.PI) - _previousAngle[t]
                    : _angle[t] - _previousAngle[t];
                _swum[t] += step;
                _previousAngle[t] = _angle[t];
                _previousQuadrant[t] = _quadrant[t];
            }

            _previousPosition[t] = fish.Position;
            Scores[t] = (int)Math.Floor(_swum[t] * 180 / Math.PI);
        }

        if (MathF.Abs(_angle[0] - _angle[1]) < Level)
        {
            AddEvent(ItemEvent.Plain(world.Cycle, "level", "the fish are level: one has caught up with the other"));
            MatchDone = true;
        }

        return moved;
    }

    /// <inheritdoc/>
    protected override MatchOutcome Decide()
    {
        string swum = string.Create(CultureInfo.InvariantCulture, $"{_swum[0]:0.00} against {_swum[1]:0.00} rad swum");
        return _swum[0] > _swum[1] ? new MatchOutcome(0, "larger angle swum, " + swum)
            : _swum[1] > _swum[0] ? new MatchOutcome(1, "larger angle swum, " + swum)
            : new MatchOutcome(-1, "tie, " + swum);
    }

    // The original's foul test: a quadrant back or two at once; crossing z = 0 between the side walls or by a jump.
    private bool Fouled(Vector2 p, Vector2 previous, int quadrant, int previousQuadrant)
    {
        if (p.X == 0 || p.Y == 0)
        {
            return false;
        }

        int d = quadrant - previousQuadrant;
        if (Math.Abs(d) == 2 || d == -1 || d == 3)
        {
            return true;
        }

        return p.Y * previous.Y <= 0
            && ((p.X >= -CrossingX && p.X <= CrossingX) || MathF.Abs(p.X - previous.X) > FieldLength / 2f);
    }
}
