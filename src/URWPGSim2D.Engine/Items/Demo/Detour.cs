namespace URWPGSim2D.Engine.Items.Demo;

/// <summary>
/// The way round obstacles: when the straight line to a point crosses an obstacle (its bounding
/// box grown by a margin: <see cref="ObstacleField.FirstBlocking"/>), head for the corner of that
/// box, a little farther out, that makes the shortest way and can itself be reached straight;
/// otherwise head for the point. Nothing is allocated.
/// </summary>
internal static class Detour
{
    private const float CornerOut = 40f;

    /// <summary>Where to head now on the way from <paramref name="from"/> to <paramref name="to"/>.</summary>
    /// <param name="field">The field's obstacles.</param>
    /// <param name="from">The fish's position.</param>
    /// <param name="to">Where it wants to go.</param>
    /// <param name="margin">Clearance kept from every obstacle's bounding box, mm.</param>
    public static Vector2 Aim(ObstacleField field, Vector2 from, Vector2 to, float margin)
    {
        int blocking = field.FirstBlocking(from, to, margin);
        if (blocking < 0)
        {
            return to;
        }

        Vector2 best = to;
        float bestCost = float.PositiveInfinity;
        bool bestFree = false;
        for (int k = 0; k < 4; k++)
        {
            Vector2 corner = field.Corner(blocking, margin + CornerOut, k);
            bool free = field.Free(from, corner, margin);
            float cost = Vector2.Distance(from, corner) + Vector2.Distance(corner, to);
            if ((free && !bestFree) || (free == bestFree && cost < bestCost))
            {
                best = corner;
                bestCost = cost;
                bestFree = free;
            }
        }

        return best;
    }
}
