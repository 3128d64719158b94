using URWPGSim2D.Strategies;

namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// Notices a demo fish that has not moved 40 mm in two seconds and turns it hard the other way for
/// a while (2.5 s), so no fish stays pinned against a wall or an obstacle.
/// </summary>
internal struct Stuck
{
    private const int StuckCycles = 20;
    private const int EscapeCycles = 25;

    private Vector2 _anchor;
    private int _still;
    private int _escape;

    /// <summary>Whether the fish is escaping this cycle, and the decision if so.</summary>
    public bool Escaping(in FishView me, out Decision escape)
    {
        escape = default;
        if (_escape > 0)
        {
            _escape--;
            escape = new Decision(3, me.AngularSpeed > 0f ? 0 : 14);
            return true;
        }

        if (Vector2.DistanceSquared(me.Position, _anchor) > 40f * 40f)
        {
            _anchor = me.Position;
            _still = 0;
            return false;
        }

        if (++_still < StuckCycles)
        {
            return false;
        }

        _still = 0;
        _escape = EscapeCycles;
        escape = new Decision(3, me.AngularSpeed > 0f ? 0 : 14);
        return true;
    }
}
