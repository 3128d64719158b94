using URWPGSim2D.Collision.Queries;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Common;
using URWPGSim2D.Strategies;
using Xna = Microsoft.Xna.Framework;

namespace URWPGSim2D.StrategyHelper;

/// <summary>
/// The strategy SDK's collision queries (<see cref="FieldSensor"/>) for strategies written against
/// the original's API: where a ray first enters a border, obstacle, ball or fish, which bodies lie
/// within a disc, which body is nearest a point, how far apart two bodies are. They answer about the
/// match the <see cref="Mission"/> was built from (exactly as <see cref="FieldSensor"/> does for an SDK
/// strategy), in the original's millimetre <see cref="Xna.Vector3"/> points (X and Z; Y is ignored).
/// Fish are named as the original names them: <see cref="Fish"/> maps a team of
/// <see cref="Mission.TeamsRef"/> and a fish of its <c>Fishes</c> to a <see cref="SensedBody"/>.
/// </summary>
/// <remarks>
/// Allocation-free after the first call on a thread (each thread keeps one sensor, observed again
/// when the mission's cycle changes). A mission made by hand rather than given to
/// <c>GetDecision</c> has no match behind it and is refused.
/// </remarks>
public static class CollisionQueries
{
    [ThreadStatic]
    private static FieldSensor? _sensor;

    [ThreadStatic]
    private static MatchSnapshot? _observed;

    /// <summary>The body a ray from <paramref name="fromMm"/> to <paramref name="toMm"/> enters first (see <see cref="FieldSensor.RayCast"/>).</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="fromMm">The ray's start, mm.</param>
    /// <param name="toMm">The ray's end, mm.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body passed through (the strategy's own fish), or <see cref="SensedBody.None"/>.</param>
    /// <returns>The body and the entry (point and normal as plane vectors, X = world X, Y = world Z), or a miss.</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, a coordinate is not finite, or <paramref name="kinds"/> has undefined bits.</exception>
    public static SensedHit RayCast(Mission mission, Xna.Vector3 fromMm, Xna.Vector3 toMm, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default) =>
        Sensor(mission).RayCast(fromMm.ToXZ(), toMm.ToXZ(), kinds, ignore);

    /// <summary>The bodies overlapping the disc of <paramref name="radiusMm"/> around <paramref name="centerMm"/> (see <see cref="FieldSensor.Overlap"/>).</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="centerMm">The disc's centre, mm.</param>
    /// <param name="radiusMm">Its radius, mm (&gt; 0).</param>
    /// <param name="bodies">Receives the first bodies, as many as fit.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body left out, or <see cref="SensedBody.None"/>.</param>
    /// <returns>The number of bodies overlapping (may exceed the length of <paramref name="bodies"/>).</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, the centre is not finite, the radius is not positive, or <paramref name="kinds"/> has undefined bits.</exception>
    public static int Overlap(Mission mission, Xna.Vector3 centerMm, float radiusMm, Span<SensedBody> bodies, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default)
    {
        var sensor = Sensor(mission);
        return sensor.Overlap(new Circle(centerMm.ToXZ(), radiusMm), bodies, kinds, ignore);
    }

    /// <summary>The body nearest a point (see <see cref="FieldSensor.Nearest"/>).</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="pointMm">The point, mm.</param>
    /// <param name="kinds">The kinds of bodies looked at.</param>
    /// <param name="ignore">A body left out, or <see cref="SensedBody.None"/>.</param>
    /// <returns>The body and the distance.</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, the point is not finite, or <paramref name="kinds"/> has undefined bits.</exception>
    public static SensedDistance Nearest(Mission mission, Xna.Vector3 pointMm, SensedKinds kinds = SensedKinds.All, SensedBody ignore = default) =>
        Sensor(mission).Nearest(pointMm.ToXZ(), kinds, ignore);

    /// <summary>The distance from a point to the nearest border or obstacle, mm (see <see cref="FieldSensor.Clearance"/>).</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="pointMm">The point, mm.</param>
    /// <returns>The distance (0 on or inside one).</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, or the point is not finite.</exception>
    public static float Clearance(Mission mission, Xna.Vector3 pointMm) => Sensor(mission).Clearance(pointMm.ToXZ());

    /// <summary>How far apart two bodies are, with a closest point on each and the fish parts (see <see cref="FieldSensor.Distance(SensedBody, SensedBody)"/>).</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="a">The first body.</param>
    /// <param name="b">The second body.</param>
    /// <returns>The gap and the closest points.</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, or a body is not one of its.</exception>
    public static DistanceResult Distance(Mission mission, SensedBody a, SensedBody b) => Sensor(mission).Distance(a, b);

    /// <summary>The fish <c>mission.TeamsRef[teamId].Fishes[fishIndex]</c> as the queries name it.</summary>
    /// <param name="mission">The mission given to <c>GetDecision</c>.</param>
    /// <param name="teamId">The team's index in <see cref="Mission.TeamsRef"/> (the <c>teamId</c> of <c>GetDecision</c> for the strategy's own).</param>
    /// <param name="fishIndex">The fish's index in the team's <c>Fishes</c>.</param>
    /// <returns>The fish.</returns>
    /// <exception cref="ArgumentException">The mission has no match behind it, or the team or fish does not exist.</exception>
    public static SensedBody Fish(Mission mission, int teamId, int fishIndex)
    {
        var snapshot = Source(mission);
        int teams = mission.TeamsRef.Count;
        if ((uint)teamId >= (uint)teams)
        {
            throw new ArgumentException($"must be a team index 0 … {teams - 1}, got {teamId}", nameof(teamId));
        }

        // The mission lists each team's fish in snapshot order; with two teams after half time its team 0 is the server's team 1.
        int team = teams == 2 && snapshot.SidesSwapped ? 1 - teamId : teamId;
        int ordinal = 0;
        foreach (ref readonly var f in snapshot.Fish)
        {
            if (f.Team == team && ordinal++ == fishIndex)
            {
                return SensedBody.Fish(f.Index);
            }
        }

        throw new ArgumentException($"team {teamId} has no fish {fishIndex}", nameof(fishIndex));
    }

    private static MatchSnapshot Source(Mission mission)
    {
        ArgumentNullException.ThrowIfNull(mission);
        return mission.Source ?? throw new ArgumentException("must be a mission given to GetDecision (this one was made by hand: no match behind it)", nameof(mission));
    }

    private static FieldSensor Sensor(Mission mission)
    {
        var snapshot = Source(mission);
        var sensor = _sensor ??= new FieldSensor();
        if (!ReferenceEquals(snapshot, _observed) || sensor.Cycle != snapshot.Cycle)
        {
            sensor.Observe(snapshot);
            _observed = snapshot;
        }

        return sensor;
    }
}
