using System;
using System.Numerics;

namespace URWPGSim2D.Server.Items.Demo;

/// <summary>
/// What a demo fish must keep clear of when it plans a way: the pool's walls and the obstacles of the
/// snapshot, and the way round them (<see cref="Waypath"/>, made once by the strategy).
/// <see cref="Clearance"/> is the distance from a point to the nearest of them (negative inside one).
/// Nothing is allocated.
/// </summary>
internal readonly ref struct Surroundings
{
    private readonly ReadOnlySpan<ObstacleView> _obstacles;
    private readonly Vector2 _half;

    /// <summary>The surroundings of a snapshot, with the way-finder of its obstacles.</summary>
    public Surroundings(MatchSnapshot snapshot, Waypath ways)
    {
        _obstacles = snapshot.Obstacles;
        _half = new Vector2(snapshot.FieldLength, snapshot.FieldWidth) * 0.5f;
        Ways = ways;
    }

    /// <summary>The way round the obstacles.</summary>
    public Waypath Ways { get; }

    /// <summary>A way-finder for the snapshot's field and obstacles (once per strategy: they never move).</summary>
    public static Waypath WaysOf(MatchSnapshot snapshot) => new(snapshot.Obstacles, new Vector2(snapshot.FieldLength, snapshot.FieldWidth) * 0.5f);

    /// <summary>Half the field's length and width, mm.</summary>
    public Vector2 HalfField => _half;

    /// <summary>The obstacles.</summary>
    public ReadOnlySpan<ObstacleView> Obstacles => _obstacles;

    /// <summary>Distance from <paramref name="p"/> to the nearest wall or obstacle surface, mm (negative inside).</summary>
    public float Clearance(Vector2 p)
    {
        float clear = MathF.Min(_half.X - MathF.Abs(p.X), _half.Y - MathF.Abs(p.Y));
        foreach (ref readonly var o in _obstacles)
        {
            clear = MathF.Min(clear, Distance(o, p));
        }

        return clear;
    }

    /// <summary>Distance from a point to an obstacle's surface, mm (negative inside).</summary>
    public static float Distance(in ObstacleView o, Vector2 p)
    {
        Vector2 d = p - o.Center;
        if (o.Kind == ObstacleKind.Round)
        {
            return d.Length() - o.Radius;
        }

        float c = MathF.Cos(o.Heading), s = MathF.Sin(o.Heading);
        Vector2 local = new(MathF.Abs((d.X * c) + (d.Y * s)), MathF.Abs((-d.X * s) + (d.Y * c)));
        Vector2 outside = local - new Vector2(o.Length * 0.5f, o.Width * 0.5f);
        return outside.X <= 0f && outside.Y <= 0f
            ? MathF.Max(outside.X, outside.Y)
            : Vector2.Max(outside, Vector2.Zero).Length();
    }
}
