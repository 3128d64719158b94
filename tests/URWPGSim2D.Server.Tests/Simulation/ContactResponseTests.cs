using Xunit.Sdk;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>Ball–ball exchange, fish against a wall, ball against an obstacle (the fish–ball, fish–fish and static cases by hand: <see cref="ReferenceExchangeTests"/>).</summary>
public sealed class ContactResponseTests
{
    [Fact]
    public void BallBallConservesMomentumAndAppliesTheRestitutionOverRandomContacts()
    {
        var random = new Random(42);
        for (int trial = 0; trial < 2000; trial++)
        {
            try
            {
                var match = TestMatches.Balls(string.Empty, -60f, 0f, 0f, 0f, 60f, 0f, 0f, 0f);
                var a = match.World.Balls[0];
                var b = match.World.Balls[1];
                float angle = (float)(random.NextDouble() * Math.PI * 2);
                Vector2 n = new(MathF.Cos(angle), MathF.Sin(angle));
                a.Position = new Vector2(0f, 0f) + (n * 57f);
                b.Position = new Vector2(0f, 0f) - (n * 57f);
                a.Velocity = new Vector2((float)(random.NextDouble() * 2000 - 1000), (float)(random.NextDouble() * 2000 - 1000));
                b.Velocity = new Vector2((float)(random.NextDouble() * 2000 - 1000), (float)(random.NextDouble() * 2000 - 1000));
                Vector2 momentum = a.Velocity + b.Velocity;
                float approach = Vector2.Dot(a.Velocity - b.Velocity, n);
                Vector2 tangent = new(-n.Y, n.X);
                float tangentA = Vector2.Dot(a.Velocity, tangent);
                float tangentB = Vector2.Dot(b.Velocity, tangent);
                var pair = new CandidatePair(PairKind.BallBall, 0, 1, 58f);
                Contact hit = match.World.Detect(pair);
                Assert.True(hit.Intersect);
                new ContactResponse(match.World).Apply(pair, hit);

                Assert.Equal(momentum.X, (a.Velocity + b.Velocity).X, 0.05f);
                Assert.Equal(momentum.Y, (a.Velocity + b.Velocity).Y, 0.05f);
                Assert.Equal(tangentA, Vector2.Dot(a.Velocity, tangent), 0.05f);
                Assert.Equal(tangentB, Vector2.Dot(b.Velocity, tangent), 0.05f);
                float after = Vector2.Dot(a.Velocity - b.Velocity, n);
                float expected = approach < 0f ? -0.005f * approach : approach;
                Assert.Equal(expected, after, 0.05f);
                Assert.True(Vector2.Distance(a.Position, b.Position) >= 116f - 0.01f, "the balls are apart after the correction");
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(42, trial, e);
            }
        }
    }

    [Fact]
    public void AFishDrivingIntoAWallStopsMovingIntoIt()
    {
        // Heading +X at 317 mm/s along z = 600, straight into the lower right goal block (x ≥ 1350, z ≥ 200).
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[1150,600],"decision":{"vcode":15,"tcode":7}}],"balls":[]}""");
        match.Play(40);
        var fish = match.World.Fish[0];
        Assert.Contains(match.Contacts.Cycle.ToArray(), c => c.Pair.Kind == PairKind.FishStatic);
        Assert.InRange(fish.Velocity.X, -1f, 0.01f);
        var model = new FishModel(fish.Size, fish.Pose);
        Assert.True(model.Bounds.Max.X <= 1350f + 0.02f, $"head at {model.Bounds.Max.X}");
        Assert.Equal(312.3145f, fish.Speed.Value, 1e-3f); // VCode 15 after 40 cycles of the gear approach (untouched by the wall)
    }

    [Fact]
    public void AStaticPartnerNeverMovesAndABallBouncesOffAnObstacleWithRestitutionOneTenth()
    {
        var match = TestMatches.Balls(""","obstacles":[{"type":"round","center":[0,0],"radius":58}]""", -200f, 0f, 1000f, 0f);
        match.Step();
        var contact = Assert.Single(match.Contacts.Cycle.ToArray());
        Assert.Equal(PairKind.BallStatic, contact.Pair.Kind);
        Assert.Equal(new Vector2(0f, 0f), match.World.Statics[0].Circle.Center);
        // −0.1 × 1000 mm/s after the hit, then drag of 25 mm/s² × 0.1 s at 100 mm/s.
        Assert.Equal(-100f + 25f, match.World.Balls[0].Velocity.X, 0.1f);
    }
}
