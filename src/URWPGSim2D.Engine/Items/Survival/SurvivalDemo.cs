using URWPGSim2D.Engine.Items.Demo;

namespace URWPGSim2D.Engine.Items.Survival;

/// <summary>
/// The demo strategy of 生存挑战. Hunting, fish 0 chases the nearest prey not yet caught, aiming a
/// little ahead of it and round the squares (the parked fish 1–3 cannot move). Hunted, each prey
/// fish keeps still while the hunter is far and, once it comes within a metre, swims at up to speed
/// gear 8 toward whichever of eight directions leads farthest from the hunter without meeting a
/// wall or a square; the free fish 0 keeps still.
/// </summary>
internal sealed class SurvivalDemo(int team, SurvivalReferee referee) : IStrategy
{
    private const float Margin = 90f;
    private const float Alarm = 1000f;
    private Stuck[] _stuck = [];
    private ObstacleField? _field;

    /// <inheritdoc/>
    public string TeamName => "survival demo";

    /// <inheritdoc/>
    public void Decide(MatchSnapshot snapshot, ReadOnlySpan<int> fish, Span<Decision> decisions)
    {
        if (_stuck.Length != fish.Length)
        {
            _stuck = new Stuck[fish.Length];
        }

        int hunterFish = HunterFish(snapshot);
        for (int k = 0; k < fish.Length; k++)
        {
            FishView me = snapshot.Fish[fish[k]];
            int rank = referee.Rank(me.Index);
            bool hunting = referee.Hunter == team;
            if ((hunting && rank != 0) || (!hunting && (rank == 0 || referee.IsCaught(team, rank))) || hunterFish < 0)
            {
                decisions[k] = Decision.Stop;
                continue;
            }

            if (_stuck[k].Escaping(me, out Decision escape))
            {
                decisions[k] = escape;
                continue;
            }

            decisions[k] = hunting ? Hunt(snapshot, me) : Flee(snapshot, me, snapshot.Fish[hunterFish].Position);
        }
    }

    // The field's squares, found the first time (they never move).
    private ObstacleField FieldOf(MatchSnapshot snapshot) => _field ??= new ObstacleField(snapshot);

    private int HunterFish(MatchSnapshot snapshot)
    {
        foreach (ref readonly var f in snapshot.Fish)
        {
            if (f.Team == referee.Hunter && referee.Rank(f.Index) == 0)
            {
                return f.Index;
            }
        }

        return -1;
    }

    private Decision Hunt(MatchSnapshot snapshot, in FishView me)
    {
        int prey = 1 - team;
        float best = float.PositiveInfinity;
        Vector2 target = default;
        foreach (ref readonly var f in snapshot.Fish)
        {
            int rank = referee.Rank(f.Index);
            if (f.Team != prey || rank < 1 || referee.IsCaught(prey, rank))
            {
                continue;
            }

            float d = Vector2.Distance(me.Position, f.Position);
            if (d < best)
            {
                best = d;
                float lead = MathF.Min(d / 300f, 1.5f) * f.Speed;
                target = f.Position + (Steering.Direction(f.Heading) * lead);
            }
        }

        if (float.IsPositiveInfinity(best))
        {
            return Decision.Stop;
        }

        return Steering.SwimTo(me, Detour.Aim(FieldOf(snapshot), me.Position, target, Margin), 14);
    }

    private Decision Flee(MatchSnapshot snapshot, in FishView me, Vector2 hunter)
    {
        if (Vector2.Distance(me.Position, hunter) > Alarm)
        {
            return Decision.Stop;
        }

        Vector2 room = new((snapshot.FieldLength * 0.5f) - 300f, (snapshot.FieldWidth * 0.5f) - 300f);
        Vector2 bestAim = me.Position;
        float bestScore = float.NegativeInfinity;
        for (int k = 0; k < 8; k++)
        {
            Vector2 aim = me.Position + (Steering.Direction(k * MathF.PI / 4f) * 500f);
            Vector2 inside = Vector2.Clamp(aim, -room, room);
            float score = Vector2.Distance(inside, hunter) - (2f * Vector2.Distance(inside, aim));
            if (!FieldOf(snapshot).Free(me.Position, inside, Margin))
            {
                score -= 400f;
            }

            if (score > bestScore)
            {
                bestScore = score;
                bestAim = inside;
            }
        }

        return Steering.SwimTo(me, bestAim, SurvivalLayout.PreyMaxVCode);
    }
}
