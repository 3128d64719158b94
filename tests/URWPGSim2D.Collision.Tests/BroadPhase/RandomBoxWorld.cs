namespace URWPGSim2D.Collision.Tests.BroadPhase;

/// <summary>
/// Seeded random worlds of boxes for the broad-phase tests: mostly similar sizes (fish- and
/// ball-like), with the awkward cases mixed in: points and flat boxes, huge boxes, duplicates,
/// boxes that exactly touch (coordinates on a 10 mm lattice), negative coordinates, dense and
/// sparse regions.
/// </summary>
internal sealed class RandomBoxWorld(int seed)
{
    private readonly Random _random = new(seed);

    public Random Random => _random;

    /// <summary>A world of <paramref name="count"/> boxes in a square region of the given half-size.</summary>
    public Aabb[] Boxes(int count, float halfSize)
    {
        var boxes = new Aabb[count];
        for (int i = 0; i < count; i++)
        {
            boxes[i] = i > 0 && _random.Next(20) == 0 ? boxes[_random.Next(i)] : Box(halfSize);
        }

        return boxes;
    }

    /// <summary>One random box whose centre lies in [−halfSize, halfSize]².</summary>
    public Aabb Box(float halfSize)
    {
        Vector2 center = new(Coordinate(halfSize), Coordinate(halfSize));
        Vector2 size = _random.Next(10) switch
        {
            0 => Vector2.Zero,
            1 => new Vector2(Size(), 0f),
            2 => new Vector2(Size() * 20f, Size() * 20f),
            _ => new Vector2(Size(), Size()),
        };
        bool lattice = _random.Next(3) == 0;
        if (lattice)
        {
            center = Snap(center);
            size = Snap(size);
        }

        return new Aabb(center - (size * 0.5f), center + (size * 0.5f));
    }

    /// <summary>
    /// The box moved by a small (coherent) or a large (teleporting) step, sometimes resized,
    /// sometimes far outside the region the world started in.
    /// </summary>
    public Aabb Moved(in Aabb box, float halfSize)
    {
        switch (_random.Next(16))
        {
            case 0:
            case 1:
                return Box(halfSize);
            case 2:
                return Box(halfSize * 10f);
        }

        Vector2 step = new(((float)_random.NextDouble() - 0.5f) * 60f, ((float)_random.NextDouble() - 0.5f) * 60f);
        Vector2 grow = new((float)_random.NextDouble() * 10f);
        return new Aabb(box.Min + step - grow, box.Max + step + grow);
    }

    private float Coordinate(float halfSize) => (float)((_random.NextDouble() * 2.0) - 1.0) * halfSize;

    private float Size() => 20f + ((float)_random.NextDouble() * 400f);

    private static Vector2 Snap(Vector2 v) => new(MathF.Round(v.X / 10f) * 10f, MathF.Round(v.Y / 10f) * 10f);
}
