using System.Numerics;

namespace URWPGSim2D.Server.Items.Demo;

/// <summary>
/// What a demo fish must keep clear of when it plans a way: the pool's borders and the obstacles of
/// the snapshot, as the team's <see cref="FieldSensor"/> last observed them, and the way round them
/// (<see cref="Waypath"/>, made once by the strategy). <see cref="Clearance"/> is the SDK's
/// distance from a point to the nearest of them. Nothing is allocated.
/// </summary>
internal readonly ref struct Surroundings
{
    private readonly FieldSensor _sensor;

    /// <summary>The surroundings the sensor observed, with the way-finder of its obstacles.</summary>
    public Surroundings(FieldSensor sensor, Waypath ways)
    {
        _sensor = sensor;
        Ways = ways;
    }

    /// <summary>The way round the obstacles.</summary>
    public Waypath Ways { get; }

    /// <summary>A way-finder for the snapshot's field and obstacles (once per strategy: they never move).</summary>
    public static Waypath WaysOf(MatchSnapshot snapshot) => new(snapshot.Obstacles, new Vector2(snapshot.FieldLength, snapshot.FieldWidth) * 0.5f);

    /// <summary>Distance from <paramref name="p"/> to the nearest border or obstacle, mm (0 on or inside one).</summary>
    public float Clearance(Vector2 p) => _sensor.Clearance(p);
}
