using System.Collections.Generic;

namespace URWPGSim2D.Collision.Motion;

/// <summary>
/// Every leaf contact of a fish with another body at their poses now (see
/// <see cref="MotionWorld.DetectLeaves"/>). The world's own fish models follow its stepping (a fish is
/// carried rigidly between rebuilds) and are left alone: this query lays the fish out on scratch
/// models instead, two per fish size of the world (one per fish of a pair), made when the bodies
/// are loaded, so that no query builds one; each use poses them again.
/// </summary>
internal sealed class LeafContacts
{
    private FishModel[] _models = [];
    private int[] _sizeOf = [];

    /// <summary>Makes the scratch models for the fish sizes among the movers (allocates only here).</summary>
    public void Load(ReadOnlySpan<Body> movers)
    {
        var sizes = new Dictionary<FishSize, int>();
        var models = new List<FishModel>();
        _sizeOf = new int[movers.Length];
        for (int m = 0; m < movers.Length; m++)
        {
            Body body = movers[m];
            if (body.Kind != BodyKind.Fish)
            {
                _sizeOf[m] = -1;
                continue;
            }

            FishSize size = body.Model!.Size;
            if (!sizes.TryGetValue(size, out int known))
            {
                known = sizes.Count;
                sizes.Add(size, known);
                models.Add(new FishModel(size, PoseOf(body)));
                models.Add(new FishModel(size, PoseOf(body)));
            }

            _sizeOf[m] = known;
        }

        _models = [.. models];
    }

    /// <summary>Every leaf contact of <paramref name="fish"/> (a fish) with <paramref name="other"/> (a fish, a circle or a static body); returns their number.</summary>
    public int Detect(Body fish, Body other, Span<FishContact> contacts)
    {
        FishModel a = Posed(0, fish);
        switch (other.Kind)
        {
            case BodyKind.Fish:
                return FishCollision.DetectAll(a, Posed(1, other), contacts);
            case BodyKind.Circle:
                return FishCollision.DetectAll(a, new Circle(other.Position, other.Radius), contacts);
            default:
                return DetectStatic(a, other.Shape, contacts);
        }
    }

    private static int DetectStatic(FishModel fish, in Shape shape, Span<FishContact> contacts) => shape.Kind switch
    {
        ShapeKind.Circle => FishCollision.DetectAll(fish, shape.AsCircle(), contacts),
        ShapeKind.Aabb => FishCollision.DetectAll(fish, shape.AsAabb(), contacts),
        ShapeKind.KDop8 => FishCollision.DetectAll(fish, shape.AsKDop8(), contacts),
        ShapeKind.Polygon => FishCollision.DetectAll(fish, shape.AsPolygon(), contacts),
        _ => FishCollision.DetectAll(fish, shape.AsSegment(), contacts),
    };

    // Scratch model k (0 or 1) of the fish's size, laid out at the fish's pose and joints now.
    private FishModel Posed(int k, Body fish)
    {
        FishModel model = _models[(2 * _sizeOf[fish.Slot]) + k];
        model.SetPose(PoseOf(fish));
        return model;
    }

    private static FishPose PoseOf(Body b) => new(b.Position, b.Heading, b.Joint1, b.Joint2, b.Joint3);
}
