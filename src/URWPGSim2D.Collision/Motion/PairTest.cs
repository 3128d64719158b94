using URWPGSim2D.Collision.NarrowPhase;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// The exact test of two bodies at their current poses (A always moves; B moves, is static or is
/// the walls), and a cheap lower bound on their distance. A fish is tested through its rigid
/// model: the partner is carried into the model's frame (<see cref="RigidFrame"/>) and the
/// contact carried back, so a fish that moved or turned within the step is not rebuilt; a second
/// fish is rebuilt in the first one's frame only when their relative pose changed. A polygon's
/// outline is posed in place. Nothing allocates.
/// </summary>
internal static class PairTest
{
    private const int MaxOutline = ConvexPolygon.MaxVertices;

    /// <summary>The contact of A and B now (MTV moves A), or no contact.</summary>
    public static Hit Detect(Body a, Body b) => a.Kind switch
    {
        BodyKind.Circle => CircleWith(new Circle(a.Position, a.Radius), b),
        BodyKind.Polygon => PolygonWith(a, b),
        _ => FishWith(a, b),
    };

    /// <summary>Lower bound on the gap between A and B now, mm (≤ 0: they may touch).</summary>
    public static float Gap(Body a, Body b)
    {
        a.Groups(out Disc a1, out Disc a2);
        switch (b.Kind)
        {
            case BodyKind.Walls:
            {
                Aabb pool = b.Bounds;
                return MathF.Min(a1.ClearanceInside(pool.Min, pool.Max), a2.ClearanceInside(pool.Min, pool.Max));
            }

            case BodyKind.Static:
                if (b.RoundStatic)
                {
                    Disc d = b.StaticDisc;
                    return MathF.Min(a1.GapTo(d), a2.GapTo(d));
                }

                return MathF.Min(a1.GapTo(b.Bounds.Min, b.Bounds.Max), a2.GapTo(b.Bounds.Min, b.Bounds.Max));
            default:
            {
                b.Groups(out Disc b1, out Disc b2);
                return Disc.LeastGap(a1, a2, b1, b2);
            }
        }
    }

    /// <summary>The exact test, skipped (nothing rebuilt) when the bounds are apart.</summary>
    public static Hit DetectIfNear(Body a, Body b) => Gap(a, b) > 0f ? default : Detect(a, b);

    private static Hit CircleWith(in Circle circle, Body b)
    {
        switch (b.Kind)
        {
            case BodyKind.Circle:
                return Hit.From(CollisionDetector.Detect(circle, new Circle(b.Position, b.Radius)));
            case BodyKind.Polygon:
                b.Outline();
                return Hit.From(CircleConvex.Detect(circle, new ConvexView(b.WorldVertices, b.WorldNormals)));
            case BodyKind.Fish:
                return FishWithCircle(b, circle).Swapped();
            case BodyKind.Walls:
                return Hit.From(b.Field!.Contain(circle));
            default:
            {
                Shape shape = b.Shape;
                return Hit.From(CollisionDetector.Detect(circle, shape));
            }
        }
    }

    private static Hit PolygonWith(Body a, Body b)
    {
        a.Outline();
        var view = new ConvexView(a.WorldVertices, a.WorldNormals);
        switch (b.Kind)
        {
            case BodyKind.Circle:
                return Hit.From(CircleConvex.Detect(new Circle(b.Position, b.Radius), view)).Swapped();
            case BodyKind.Polygon:
                b.Outline();
                return Hit.From(ConvexSat.Detect(view, new ConvexView(b.WorldVertices, b.WorldNormals)));
            case BodyKind.Fish:
                return FishWithOutline(b, a.WorldVertices, a.WorldNormals, new Disc(a.Position, a.Reach)).Swapped();
            case BodyKind.Walls:
                return Hit.From(b.Field!.Contain(a.WorldVertices));
            default:
                if (b.Shape.Kind == ShapeKind.Circle)
                {
                    return Hit.From(CircleConvex.Detect(b.Shape.AsCircle(), view)).Swapped();
                }

                Span<Vector2> v = stackalloc Vector2[MaxOutline];
                Span<Vector2> n = stackalloc Vector2[MaxOutline];
                int count = StaticOutline(b.Shape, v, n);
                return Hit.From(ConvexSat.Detect(view, new ConvexView(v[..count], n[..count])));
        }
    }

    private static Hit FishWith(Body a, Body b)
    {
        switch (b.Kind)
        {
            case BodyKind.Circle:
                return FishWithCircle(a, new Circle(b.Position, b.Radius));
            case BodyKind.Polygon:
                b.Outline();
                return FishWithOutline(a, b.WorldVertices, b.WorldNormals, new Disc(b.Position, b.Reach));
            case BodyKind.Fish:
                return FishWithFish(a, b);
            case BodyKind.Walls:
                return FishWall.Detect(b.Field!, a);
            default:
                return FishWithStatic(a, b);
        }
    }

    private static Hit FishWithCircle(Body fish, in Circle circle)
    {
        FishModel model = fish.RigidModel;
        RigidFrame frame = fish.Frame;
        Circle local = frame.IsIdentity ? circle : new Circle(frame.ToModel(circle.Center), circle.Radius);
        return Hit.From(FishCollision.Detect(model, local)).ToWorld(frame);
    }

    // B's model is carried into A's model frame (only its leaf groups that come near are moved;
    // neither model is rebuilt unless its joints changed); the contact is carried from A's model
    // frame to the world.
    private static Hit FishWithFish(Body a, Body b)
    {
        FishModel modelA = a.RigidModel;
        FishModel modelB = b.RigidModel;
        RigidFrame frameA = a.Frame;
        RigidFrame.Between(b.Frame, frameA, out Vector2 rotation, out Vector2 translation);
        return Hit.From(FishCollision.Detect(modelA, modelB, rotation, translation)).ToWorld(frameA);
    }

    private static Hit FishWithStatic(Body fish, Body body)
    {
        FishModel model = fish.RigidModel;
        RigidFrame frame = fish.Frame;
        Shape shape = body.Shape;
        if (frame.IsIdentity)
        {
            return Hit.From(FishCollision.Detect(model, shape));
        }

        switch (shape.Kind)
        {
            case ShapeKind.Circle:
                return FishWithCircle(fish, shape.AsCircle());
            case ShapeKind.Aabb when frame.IsTranslation:
            {
                Aabb box = shape.AsAabb();
                Vector2 shift = frame.ToModel(Vector2.Zero);
                return Hit.From(FishCollision.Detect(model, new Aabb(box.Min + shift, box.Max + shift))).ToWorld(frame);
            }

            default:
            {
                Span<Vector2> v = stackalloc Vector2[MaxOutline];
                Span<Vector2> n = stackalloc Vector2[MaxOutline];
                int count = StaticOutline(shape, v, n);
                Circle c = shape.BoundingCircle;
                return FishWithOutline(fish, v[..count], n[..count], new Disc(c.Center, c.Radius));
            }
        }
    }

    // A convex outline in world coordinates, carried into the fish model's frame.
    private static Hit FishWithOutline(Body fish, ReadOnlySpan<Vector2> vertices, ReadOnlySpan<Vector2> normals, Disc bound)
    {
        FishModel model = fish.RigidModel;
        RigidFrame frame = fish.Frame;
        Span<Vector2> v = stackalloc Vector2[vertices.Length];
        Span<Vector2> n = stackalloc Vector2[normals.Length];
        for (int i = 0; i < vertices.Length; i++)
        {
            v[i] = frame.ToModel(vertices[i]);
        }

        for (int i = 0; i < normals.Length; i++)
        {
            n[i] = frame.RotateBack(normals[i]);
        }

        var local = new Circle(frame.ToModel(bound.Center), bound.Radius + 0.01f);
        return Hit.From(FishCollision.Detect(model, new ConvexView(v, n), local)).ToWorld(frame);
    }

    // A static shape other than a circle as vertices and outward normals (counter-clockwise); returns the count.
    private static int StaticOutline(in Shape shape, Span<Vector2> v, Span<Vector2> n)
    {
        switch (shape.Kind)
        {
            case ShapeKind.Segment:
                shape.AsSegment().WriteView(v, n);
                return 2;
            case ShapeKind.Polygon:
            {
                ConvexPolygon p = shape.AsPolygon();
                p.Vertices.CopyTo(v);
                p.Normals.CopyTo(n);
                return p.Vertices.Length;
            }

            case ShapeKind.KDop8:
            {
                KDop8 k = shape.AsKDop8();
                var view = k.View();
                view.Vertices.CopyTo(v);
                view.Normals.CopyTo(n);
                return view.Vertices.Length;
            }

            default:
            {
                Aabb box = shape.AsAabb();
                v[0] = box.Min;
                v[1] = new Vector2(box.Max.X, box.Min.Y);
                v[2] = box.Max;
                v[3] = new Vector2(box.Min.X, box.Max.Y);
                for (int i = 0; i < 4; i++)
                {
                    n[i] = Vector2.Normalize(XZPlane.RightPerp(v[(i + 1) % 4] - v[i]));
                }

                return 4;
            }
        }
    }
}
