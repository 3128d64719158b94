namespace URWPGSim2D.Collision.Queries;

public static partial class ShapeQuery
{
    /// <summary>
    /// Where the ray from <paramref name="from"/> to <paramref name="to"/> first enters a shape.
    /// A ray that starts inside the shape does not hit it (one starting on its boundary and
    /// pointing in hits at fraction 0); a ray of zero length hits nothing.
    /// </summary>
    /// <param name="shape">The shape.</param>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The entry point, the outward normal there and the fraction of the way, or <see cref="RayCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public static RayCastResult RayCast(in Shape shape, Vector2 from, Vector2 to)
    {
        CheckRay(from, to);
        return RayCast(new QueryBody(in shape), from, to);
    }

    /// <summary>Where a ray first enters a convex polygon (the same as the <see cref="Shape"/> overload, without wrapping it).</summary>
    /// <param name="polygon">The polygon.</param>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The entry, or <see cref="RayCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public static RayCastResult RayCast(in ConvexPolygon polygon, Vector2 from, Vector2 to)
    {
        CheckRay(from, to);
        return RayCaster.Polygon(polygon.Vertices, polygon.Normals, from, to, out float fraction, out Vector2 normal)
            ? new RayCastResult(from + (fraction * (to - from)), normal, fraction)
            : default;
    }

    /// <summary>Where a ray first enters a fish: the nearest entry into one of its leaves, with the leaf in <see cref="RayCastResult.Part"/>.</summary>
    /// <param name="fish">The fish.</param>
    /// <param name="from">The ray's start, mm.</param>
    /// <param name="to">The ray's end, mm.</param>
    /// <returns>The entry, or <see cref="RayCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="fish"/> is null.</exception>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public static RayCastResult RayCast(FishModel fish, Vector2 from, Vector2 to)
    {
        ArgumentNullException.ThrowIfNull(fish);
        CheckRay(from, to);
        return RayCast(new QueryBody(fish), from, to);
    }

    internal static RayCastResult RayCast(scoped in QueryBody body, Vector2 from, Vector2 to)
    {
        if (body.Fish is not null)
        {
            // The root circle first: a ray that starts outside it and misses it misses every leaf.
            Circle root = body.Fish.Root;
            if (Vector2.DistanceSquared(from, root.Center) >= root.Radius * root.Radius
                && !RayCaster.Circle(root.Center, root.Radius, from, to, out _, out _))
            {
                return default;
            }
        }

        VertexBuffer8 buffer = default;
        float best = float.PositiveInfinity;
        Vector2 bestNormal = default;
        int bestPart = -1;
        for (int i = 0; i < body.Count; i++)
        {
            var q = body.Part(i, ref buffer);
            if (RayCaster.Cast(q, from, to, out float fraction, out Vector2 normal) && fraction < best)
            {
                best = fraction;
                bestNormal = normal;
                bestPart = i;
            }
        }

        return bestPart < 0 ? default : new RayCastResult(from + (best * (to - from)), bestNormal, best, body.PartIndex(bestPart));
    }

    internal static void CheckRay(Vector2 from, Vector2 to)
    {
        Guard.Finite(from, nameof(from));
        Guard.Finite(to, nameof(to));
    }
}
