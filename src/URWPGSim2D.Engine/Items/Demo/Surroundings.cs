namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// What a demo fish must keep clear of when it plans a way this cycle: the field's borders and
/// obstacles (<see cref="ObstacleField"/>) and the way round them (<see cref="Waypath"/>), both made
/// once by the strategy. Nothing is allocated.
/// </summary>
internal readonly ref struct Surroundings
{
    private readonly ObstacleField _field;

    /// <summary>The surroundings of a field, with the way-finder of its obstacles.</summary>
    public Surroundings(ObstacleField field, Waypath ways)
    {
        _field = field;
        Ways = ways;
    }

    /// <summary>The way round the obstacles.</summary>
    public Waypath Ways { get; }

    /// <summary>Distance from <paramref name="p"/> to the nearest border or obstacle surface, mm (negative inside one): <see cref="ObstacleField.Clearance"/>.</summary>
    public float Clearance(Vector2 p) => _field.Clearance(p);
}
