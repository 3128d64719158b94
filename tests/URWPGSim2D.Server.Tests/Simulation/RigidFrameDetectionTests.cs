using System;
using System.Numerics;
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Server.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// A fish tested through a model left at an older pose (the partner carried into its frame) finds
/// the same contact as a model rebuilt at the fish's pose: fish against fish, ball, round and
/// rectangle obstacles, goal blocks and walls, over random poses, joints and model offsets.
/// </summary>
public sealed class RigidFrameDetectionTests
{
    private const int Trials = 1500;

    [Fact]
    public void EveryPairKindMatchesAModelRebuiltAtThePose()
    {
        var random = new Random(2024);
        var match = TestMatches.FromJson("""
            {"fish":[{"team":0,"position":[0,0],"strategy":"idle"},{"team":1,"position":[300,0],"strategy":"idle"}],
             "balls":[{"position":[0,300]}],
             "obstacles":[{"type":"round","center":[0,-300],"radius":58},{"type":"rectangle","center":[-300,0],"length":100,"width":60,"heading":0.4}]}
            """);
        var world = match.World;
        int contacts = 0, kinds = 0, different = 0;
        int[] seen = new int[7];
        for (int trial = 0; trial < Trials; trial++)
        {
            var a = world.Fish[0];
            var b = world.Fish[1];
            Place(random, a, Vector2.Zero, 1600f);
            Place(random, b, a.Position, 420f);
            world.Balls[0].Position = a.Position + RandomVector(random, 330f);
            // Models at older poses (same joints), as inside a cycle.
            a.SyncModelAt(a.Position - RandomVector(random, 40f), a.Heading - ((float)random.NextDouble() - 0.5f) * 0.2f);
            b.SyncModelAt(b.Position - RandomVector(random, 40f), b.Heading - ((float)random.NextDouble() - 0.5f) * 0.2f);

            foreach (var pair in Pairs(world))
            {
                Hit rigid = PairDetector.Detect(world, pair);
                Hit exact = Exact(world, pair);
                Assert.True(rigid.Intersect == exact.Intersect || MathF.Max(rigid.Depth, exact.Depth) < 1e-3f, $"{pair.Kind} trial {trial}: {rigid.Depth} vs {exact.Depth}");
                if (!exact.Intersect || !rigid.Intersect)
                {
                    continue;
                }

                contacts++;
                seen[(int)pair.Kind]++;
                Assert.Equal(exact.Depth, rigid.Depth, 2e-3f);

                // Two leaf pairs can be equally deep (a tie settled by rounding): the same depth is
                // required, the same MTV, action point and parts for nearly every contact.
                bool same = Vector2.Distance(exact.Mtv, rigid.Mtv) < 5e-3f && Vector2.Distance(exact.Point, rigid.Point) < 0.05f
                    && exact.PartA == rigid.PartA && exact.PartB == rigid.PartB;
                different += same ? 0 : 1;
            }
        }

        Assert.True(different <= contacts / 50, $"{different} of {contacts} contacts differ in MTV, action point or parts");

        foreach (int n in seen)
        {
            kinds += n > 20 ? 1 : 0;
        }

        Assert.True(contacts > 1500 && kinds >= 4, $"{contacts} contacts; by kind {string.Join(",", seen)}");
    }

    private static CandidatePair[] Pairs(World world) =>
    [
        new(PairKind.FishFish, 0, 1, 10f),
        new(PairKind.FishBall, 0, 0, 60f),
        new(PairKind.FishStatic, 0, 0, 60f),
        new(PairKind.FishStatic, 0, 1, 60f),
        new(PairKind.FishStatic, 0, 2, 60f),
        new(PairKind.FishWall, 0, 0, float.PositiveInfinity),
    ];

    // The reference: both fish rebuilt exactly at their poses, the library's own tests.
    private static Hit Exact(World world, in CandidatePair pair)
    {
        var a = world.Fish[pair.A];
        a.SyncModel();
        FishContact contact = pair.Kind switch
        {
            PairKind.FishFish => FishCollision.Detect(a.Model, Synced(world.Fish[pair.B])),
            PairKind.FishBall => FishCollision.Detect(a.Model, world.Balls[pair.B].Shape),
            PairKind.FishWall => world.Field.Contain(a.Model),
            _ => Static(a.Model, world.Statics[pair.B]),
        };
        Hit hit = Hit.From(contact);
        a.SyncModelAt(a.Position - new Vector2(13f, -7f), a.Heading + 0.05f);
        return hit;
    }

    private static FishModel Synced(FishState fish)
    {
        fish.SyncModel();
        return fish.Model;
    }

    private static FishContact Static(FishModel fish, StaticBody body) => body.Kind switch
    {
        ShapeKind.Circle => FishCollision.Detect(fish, body.Circle),
        ShapeKind.Polygon => FishCollision.Detect(fish, body.Polygon),
        _ => FishCollision.Detect(fish, body.Box),
    };

    private static void Place(Random random, FishState fish, Vector2 around, float spread)
    {
        fish.Position = around + RandomVector(random, spread);
        fish.Position = Vector2.Clamp(fish.Position, new Vector2(-1350f, -900f), new Vector2(1350f, 900f));
        fish.Heading = (float)((random.NextDouble() * 2.0 * Math.PI) - Math.PI);
        fish.Joint1 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Joint2 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Joint3 = ((float)random.NextDouble() - 0.5f) * 0.6f;
        fish.Invalidate();
    }

    private static Vector2 RandomVector(Random random, float size) =>
        new(((float)random.NextDouble() - 0.5f) * 2f * size, ((float)random.NextDouble() - 0.5f) * 2f * size);
}
