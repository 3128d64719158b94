using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.SynchronisedSwimming;

/// <summary>
/// The demo strategy of 花样游泳: the nine fish the team controls (fish 0 is the server's) swim a
/// ring: evenly spaced slots on an ellipse 1400 × 900 mm round the centre, which turns at
/// 0.12 rad/s, so the ring keeps moving and stays at least 600 mm off every wall. At the first cycle
/// the fish take the slots in the order of their angle round the centre, so few paths cross; each
/// fish heads for a point a little ahead of its slot.
/// </summary>
internal sealed class SynchronisedSwimmingDemo(SynchronisedSwimmingReferee referee) : IStrategy
{
    private const float RadiusX = 1400f;
    private const float RadiusZ = 900f;
    private const float Turn = 0.12f;
    private const float Lead = 0.3f;
    private float[] _slot = [];
    private Stuck[] _stuck = [];

    /// <inheritdoc/>
    public string TeamName => "synchronised-swimming demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_slot.Length != fish.Length)
        {
            Assign(snapshot, fish);
        }

        float t = (float)snapshot.Time;
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            if (fish[k] == referee.DrivenFish)
            {
                decisions[k] = Decision.Stop; // the server swims it
                continue;
            }

            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            float angle = _slot[k] + (Turn * t) + Lead;
            decisions[k] = Steering.SwimTo(me, new Vector2(RadiusX * MathF.Cos(angle), RadiusZ * MathF.Sin(angle)), 10);
        }
    }

    // Slots evenly round the ring, handed out in the order of the fish's angles round the centre.
    private void Assign(MatchSnapshot snapshot, ReadOnlySpan<int> fish)
    {
        _slot = new float[fish.Length];
        _stuck = new Stuck[fish.Length];
        var order = new int[fish.Length];
        var angles = new float[fish.Length];
        int n = 0;
        for (int k = 0; k < fish.Length; k++)
        {
            if (fish[k] != referee.DrivenFish)
            {
                Vector2 p = snapshot.Fish[fish[k]].Position;
                order[n] = k;
                angles[n] = MathF.Atan2(p.Y / RadiusZ, p.X / RadiusX);
                n++;
            }
        }

        Array.Sort(angles, order, 0, n);
        for (int m = 0; m < n; m++)
        {
            _slot[order[m]] = angles[0] + (2f * MathF.PI * m / n);
        }
    }
}
