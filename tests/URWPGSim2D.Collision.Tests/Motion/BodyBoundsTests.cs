namespace URWPGSim2D.Collision.Tests.Motion;

/// <summary>
/// The bounds a motion world fish gives without rebuilding its model hold every leaf vertex of the
/// model rebuilt at its pose: after a joint change (body circle carried with the body, tail
/// skeleton circle) and after a rigid move (the model's circles carried by the frame), over random poses.
/// </summary>
public sealed class BodyBoundsTests
{
    [Fact]
    public void BoundsWithoutARebuildHoldEveryLeaf()
    {
        var random = new Random(99);
        Body fish = Body.Fish(0, FishSize.Default, new FishPose(Vector2.Zero, 0f));
        double slackTail = 0, slackBody = 0;
        for (int trial = 0; trial < 3000; trial++)
        {
            try
            {
                bool jointsChange = trial % 2 == 0;
                fish.Position = new Vector2(Signed(random) * 1000f, Signed(random) * 800f);
                fish.Heading = Signed(random) * MathF.PI;
                if (jointsChange)
                {
                    fish.Joint1 = Signed(random) * 1.2f;
                    fish.Joint2 = Signed(random) * 1.2f;
                    fish.Joint3 = Signed(random) * 1.2f;
                }
                else
                {
                    fish.SyncModelAt(fish.Position + new Vector2(Signed(random) * 50f, Signed(random) * 50f), fish.Heading + (Signed(random) * 0.3f));
                }

                fish.Invalidate();
                Assert.Equal(!jointsChange, fish.JointsCurrent);
                fish.Groups(out Disc body, out Disc tail);
                Disc bound = fish.Bound();

                FishModel exact = fish.PosedModel;
                for (var part = FishPart.LeftPectoral; part <= FishPart.RightCaudal; part++)
                {
                    bool isBody = part <= FishPart.RightPectoral;
                    Disc group = isBody ? body : tail;
                    foreach (Vector2 v in exact.GetLeaf(part))
                    {
                        float inside = group.Radius - Vector2.Distance(v, group.Center);
                        Assert.True(inside >= -1e-3f, $"trial {trial}: {part} vertex {v} is {-inside} mm outside its group circle");
                        Assert.True(bound.Radius - Vector2.Distance(v, bound.Center) >= -1e-3f, $"trial {trial}: {part} outside the bound");
                        if (jointsChange)
                        {
                            slackTail = isBody ? slackTail : Math.Max(slackTail, tail.Radius - exact.TailGroup.Radius);
                            slackBody = isBody ? Math.Max(slackBody, body.Radius - exact.BodyGroup.Radius) : slackBody;
                        }
                    }
                }
            }
            catch (XunitException e)
            {
                throw RandomCaseException.At(99, trial, e);
            }
        }

        // The skeleton circle is a usable bound: at most a few tens of mm wider than the exact tail circle.
        Assert.InRange(slackTail, 0.0, 80.0);
        Assert.InRange(slackBody, 0.0, 0.05);
    }

    private static float Signed(Random random) => (float)((random.NextDouble() * 2.0) - 1.0);
}
