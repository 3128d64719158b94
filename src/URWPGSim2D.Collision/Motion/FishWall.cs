using URWPGSim2D.Collision.Pool;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// A fish against the pool's walls when its model sits at an older pose: the leaf vertices are
/// carried onto the fish (<see cref="RigidFrame"/>) and tested with the pool's point-set
/// containment; the part is the leaf reaching farthest past the walls (along −normal; the first
/// such leaf on a tie), as <see cref="Field.Contain(FishModel)"/> reports it for a posed model.
/// </summary>
internal static class FishWall
{
    /// <summary>The wall contact of the fish now (MTV moves the fish back inside), or no contact.</summary>
    public static Hit Detect(Field field, Body fish)
    {
        FishModel model = fish.RigidModel;
        RigidFrame frame = fish.Frame;
        if (frame.IsIdentity)
        {
            return Hit.From(field.Contain(model));
        }

        // The model's box carried by the frame (its four corners' box holds every leaf): inside the pool, no contact.
        Aabb box = model.Bounds;
        Vector2 c0 = frame.ToWorld(box.Min), c1 = frame.ToWorld(box.Max);
        Vector2 c2 = frame.ToWorld(new Vector2(box.Min.X, box.Max.Y)), c3 = frame.ToWorld(new Vector2(box.Max.X, box.Min.Y));
        Vector2 lo = Vector2.Min(Vector2.Min(c0, c1), Vector2.Min(c2, c3)), hi = Vector2.Max(Vector2.Max(c0, c1), Vector2.Max(c2, c3));
        Aabb pool = field.Bounds;
        if (lo.X >= pool.Min.X && lo.Y >= pool.Min.Y && hi.X <= pool.Max.X && hi.Y <= pool.Max.Y)
        {
            return Hit.From(CollisionDetectionResult.None);
        }

        // Every leaf vertex carried onto the fish (leaf after leaf, as the model packs them).
        Span<Vector2> points = stackalloc Vector2[FishLeafLayout.VertexCount];
        frame.ToWorld(model.Vertices, points);
        CollisionDetectionResult result = field.Contain(points);
        if (!result.Intersect)
        {
            return Hit.From(result);
        }

        Vector2 inward = XZPlane.ToPlane(result.NormalAxis);
        int deepest = 0;
        float best = float.NegativeInfinity;
        for (int part = 0; part < FishLeafLayout.LeafCount; part++)
        {
            foreach (Vector2 point in points.Slice(FishLeafLayout.Offset(part), FishLeafLayout.Count(part)))
            {
                float reach = -Vector2.Dot(point, inward);
                if (reach > best)
                {
                    best = reach;
                    deepest = part;
                }
            }
        }

        return Hit.From(new FishContact(result, (FishPart)deepest, null));
    }
}
