namespace URWPGSim2D.Collision.Queries;

public static partial class ShapeQuery
{
    /// <summary>
    /// Moves <paramref name="a"/> along <paramref name="translation"/> and finds when it first
    /// touches <paramref name="b"/> (which stays still).
    /// </summary>
    /// <param name="a">The moving shape, at its start.</param>
    /// <param name="translation">The whole move, mm.</param>
    /// <param name="b">The shape in the way.</param>
    /// <returns>The fraction of the move done at the first contact (0 when they touch or overlap at the start), the contact point and the normal from <paramref name="b"/> toward <paramref name="a"/>; or <see cref="ShapeCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentException"><paramref name="translation"/> is not finite.</exception>
    public static ShapeCastResult Cast(in Shape a, Vector2 translation, in Shape b)
    {
        Guard.Finite(translation, nameof(translation));
        return Cast(new QueryBody(in a), translation, new QueryBody(in b));
    }

    /// <summary>Moves a fish along a translation (pose kept) and finds when one of its leaves first touches a shape.</summary>
    /// <param name="a">The moving fish.</param>
    /// <param name="translation">The whole move, mm.</param>
    /// <param name="b">The shape in the way.</param>
    /// <returns>The first contact with <see cref="ShapeCastResult.PartA"/>, or <see cref="ShapeCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="a"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="translation"/> is not finite.</exception>
    public static ShapeCastResult Cast(FishModel a, Vector2 translation, in Shape b)
    {
        ArgumentNullException.ThrowIfNull(a);
        Guard.Finite(translation, nameof(translation));
        return Cast(new QueryBody(a), translation, new QueryBody(in b));
    }

    /// <summary>Moves a shape along a translation and finds when it first touches a fish.</summary>
    /// <param name="a">The moving shape.</param>
    /// <param name="translation">The whole move, mm.</param>
    /// <param name="b">The fish in the way.</param>
    /// <returns>The first contact with <see cref="ShapeCastResult.PartB"/>, or <see cref="ShapeCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentNullException"><paramref name="b"/> is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="translation"/> is not finite.</exception>
    public static ShapeCastResult Cast(in Shape a, Vector2 translation, FishModel b)
    {
        ArgumentNullException.ThrowIfNull(b);
        Guard.Finite(translation, nameof(translation));
        return Cast(new QueryBody(in a), translation, new QueryBody(b));
    }

    /// <summary>Moves one fish along a translation and finds when it first touches another.</summary>
    /// <param name="a">The moving fish.</param>
    /// <param name="translation">The whole move, mm.</param>
    /// <param name="b">The fish in the way.</param>
    /// <returns>The first contact with both parts, or <see cref="ShapeCastResult.Miss"/>.</returns>
    /// <exception cref="ArgumentNullException">A fish is null.</exception>
    /// <exception cref="ArgumentException"><paramref name="translation"/> is not finite.</exception>
    public static ShapeCastResult Cast(FishModel a, Vector2 translation, FishModel b)
    {
        ArgumentNullException.ThrowIfNull(a);
        ArgumentNullException.ThrowIfNull(b);
        Guard.Finite(translation, nameof(translation));
        return Cast(new QueryBody(a), translation, new QueryBody(b));
    }

    internal static ShapeCastResult Cast(scoped in QueryBody a, Vector2 translation, scoped in QueryBody b)
    {
        // The bounding circles first: if they never meet along the move, nothing inside them does.
        Circle ba = a.Bound, bb = b.Bound;
        float reach = ba.Radius + bb.Radius;
        if (Vector2.DistanceSquared(ba.Center, bb.Center) > reach * reach
            && !RayCaster.Circle(bb.Center, reach, ba.Center, ba.Center + translation, out _, out _))
        {
            return default;
        }

        VertexBuffer8 bufferA = default, bufferB = default;
        float best = float.PositiveInfinity;
        Vector2 bestPoint = default, bestNormal = default;
        int partA = 0, partB = 0;
        bool atStart = false;
        for (int i = 0; i < a.Count; i++)
        {
            var qa = a.Part(i, ref bufferA);
            for (int j = 0; j < b.Count; j++)
            {
                var qb = b.Part(j, ref bufferB);
                if (ShapeCaster.Cast(qa, translation, qb, out float fraction, out Vector2 point, out Vector2 normal, out float startGap)
                    && fraction < best)
                {
                    best = fraction;
                    bestPoint = point;
                    bestNormal = normal;
                    partA = i;
                    partB = j;
                    atStart = startGap <= 0f;
                }
            }
        }

        if (float.IsPositiveInfinity(best))
        {
            return default;
        }

        if (atStart)
        {
            var contact = QueryBody.Contact(a, b);
            if (contact.Intersect)
            {
                return new ShapeCastResult(
                    0f,
                    XZPlane.ToPlane(contact.Result.ActionPoint),
                    XZPlane.ToPlane(contact.Result.NormalAxis),
                    contact.PartA is { } pa ? (int)pa : -1,
                    contact.PartB is { } pb ? (int)pb : -1);
            }
        }

        return new ShapeCastResult(best, bestPoint, bestNormal, a.PartIndex(partA), b.PartIndex(partB));
    }
}
