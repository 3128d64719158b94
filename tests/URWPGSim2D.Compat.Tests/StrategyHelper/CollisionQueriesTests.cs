using System.Numerics;
using URWPGSim2D.Compat.Adapter;
using URWPGSim2D.Strategies;
using URWPGSim2D.StrategyHelper;
using XnaVector3 = Microsoft.Xna.Framework.Vector3;

namespace URWPGSim2D.Compat.Tests.StrategyHelper;

/// <summary><see cref="CollisionQueries"/> answers exactly as the SDK's <see cref="FieldSensor"/> on the snapshot the mission was built from.</summary>
[Collection(Common.FieldCollection.Name)]
public sealed class CollisionQueriesTests
{
    [Fact]
    public void AnswersAsTheSdkDoes()
    {
        var rng = new Random(2706);
        Span<SensedBody> a = stackalloc SensedBody[16];
        Span<SensedBody> b = stackalloc SensedBody[16];
        for (int scene = 0; scene < 5; scene++)
        {
            var snapshot = Scene(rng, swapped: scene % 2 == 1);
            var mission = new MissionBuilder().Build(snapshot);
            var sdk = new FieldSensor();
            sdk.Observe(snapshot);
            for (int k = 0; k < 200; k++)
            {
                Vector2 p = Point(rng), q = Point(rng);
                var ignore = k % 3 == 0 ? SensedBody.Fish(k % 4) : SensedBody.None;
                Assert.Equal(sdk.RayCast(p, q, ignore: ignore), CollisionQueries.RayCast(mission, XnaVector3.FromXZ(p), XnaVector3.FromXZ(q), ignore: ignore));
                Assert.Equal(sdk.Nearest(p, SensedKinds.Balls | SensedKinds.Fish), CollisionQueries.Nearest(mission, XnaVector3.FromXZ(p), SensedKinds.Balls | SensedKinds.Fish));
                Assert.Equal(sdk.Clearance(p), CollisionQueries.Clearance(mission, new XnaVector3(p.X, 123f, p.Y)));
                int n = sdk.Overlap(new Collision.Shapes.Circle(p, 150f), a);
                Assert.Equal(n, CollisionQueries.Overlap(mission, XnaVector3.FromXZ(p), 150f, b));
                Assert.True(a[..Math.Min(n, 16)].SequenceEqual(b[..Math.Min(n, 16)]));
                var d1 = sdk.Distance(SensedBody.Fish(k % 4), SensedBody.Ball(k % 3));
                var d2 = CollisionQueries.Distance(mission, SensedBody.Fish(k % 4), SensedBody.Ball(k % 3));
                Assert.Equal((d1.Distance, d1.PointA, d1.PointB, d1.PartA), (d2.Distance, d2.PointA, d2.PointB, d2.PartA));
            }

            // The original's (team, fish) names the fish at the same place as the mission's RoboFish.
            for (int team = 0; team < mission.TeamsRef.Count; team++)
            {
                for (int i = 0; i < mission.TeamsRef[team].Fishes.Count; i++)
                {
                    var body = CollisionQueries.Fish(mission, team, i);
                    Assert.Equal(mission.TeamsRef[team].Fishes[i].PositionMm.ToXZ(), snapshot.Fish[body.Index].Position);
                }
            }
        }
    }

    [Fact]
    public void AMissionMadeByHandIsRefused()
    {
        Assert.Equal("mission", Assert.Throws<ArgumentException>(() => CollisionQueries.Clearance(new Mission(), XnaVector3.Zero)).ParamName);
        var mission = new MissionBuilder().Build(Scene(new Random(1), swapped: false));
        Assert.Equal("teamId", Assert.Throws<ArgumentException>(() => CollisionQueries.Fish(mission, 2, 0)).ParamName);
        Assert.Equal("fishIndex", Assert.Throws<ArgumentException>(() => CollisionQueries.Fish(mission, 0, 2)).ParamName);

        // A clone keeps its match.
        Assert.Equal(CollisionQueries.Clearance(mission, XnaVector3.Zero), CollisionQueries.Clearance((Mission)mission.Clone(), XnaVector3.Zero));
    }

    private static MatchSnapshot Scene(Random rng, bool swapped)
    {
        var obstacles = new[]
        {
            new ObstacleView(0, ObstacleKind.Rectangle, Point(rng), 300f, 80f, rng.NextSingle() * 3f, 0f),
            new ObstacleView(1, ObstacleKind.Round, Point(rng), 0f, 0f, 0f, 90f),
        };
        var snapshot = new MatchSnapshot(4, 3, obstacles, 3000f, 2000f);
        for (int i = 0; i < 3; i++)
        {
            snapshot.BallBuffer[i] = new BallView(i, Point(rng), Vector2.Zero, 58f);
        }

        for (int i = 0; i < 4; i++)
        {
            snapshot.FishBuffer[i] = new FishView(i, i % 2, Point(rng), rng.NextSingle() * 6f, 0f, 0f, 160f, 30f, Strategies.Decision.Stop) { Joint1 = 0.2f, Joint3 = -0.3f };
        }

        snapshot.SetHeader(rng.Next(1, 100), [0, 0]);
        snapshot.SetSidesSwapped(swapped);
        return snapshot;
    }

    private static Vector2 Point(Random rng) => new((rng.NextSingle() * 2f - 1f) * 1400f, (rng.NextSingle() * 2f - 1f) * 900f);
}
