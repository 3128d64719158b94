namespace URWPGSim2D.Collision.Tests.NarrowPhase;

/// <summary>
/// Circle against circle, by hand: depth = rₐ + r_b − d along (cₐ − c_b)/d; action point = the
/// middle of the overlap of the two diameters on the centre line.
/// </summary>
public sealed class CircleCircleTests
{
    [Fact]
    public void OverlapAlongX()
    {
        // d = 15, depth 5; the lens spans x = 5..10 on the centre line.
        ContactAssert.Contact(new Circle(new(0, 0), 10), new Circle(new(15, 0), 10), -5, 0, 7.5, 0);
    }

    [Fact]
    public void ThreeFourFiveTriangle()
    {
        // d = 5, depth 1 along (−0.6, −0.8); overlap on the line from b: t ∈ [1, 2], middle 1.5.
        ContactAssert.Contact(new Circle(new(0, 0), 4), new Circle(new(3, 4), 2), -0.6, -0.8, 2.1, 2.8);
    }

    [Fact]
    public void SmallCircleInsideLargeOneGetsTheTrueMtv()
    {
        // Containment: depth rₐ + r_b − d = 12 − 3 = 9, out along (cₐ − c_b)/d = (−1, 0); the overlap on the
        // centre line is a's whole diameter, whose middle is a's centre.
        ContactAssert.Contact(new Circle(new(0, 0), 2), new Circle(new(3, 0), 10), -9, 0, 0, 0);
    }

    [Fact]
    public void ConcentricCirclesPushAlongPlusXByTheSumOfRadii()
    {
        var r = CollisionDetector.Detect(new Circle(new(5, 5), 3), new Circle(new(5, 5), 4));
        Assert.True(r.Intersect);
        Assert.Equal(new Vector3(7, 0, 0), r.MinimumTranslationVector);
        Assert.Equal(new Vector3(1, 0, 0), r.NormalAxis);
        Assert.Equal(new Vector3(5, 0, 5), r.ActionPoint);
    }

    [Fact]
    public void DeepOverlapOfEqualCircles()
    {
        // d = 1, depth 19; overlap on the line from b: [−10 ∩ ..] = [−9, 10], middle 0.5.
        ContactAssert.Contact(new Circle(new(0, 1), 10), new Circle(new(0, 0), 10), 0, 19, 0, 0.5);
    }

    [Fact]
    public void ExactlyTouchingIsNotIntersecting() =>
        ContactAssert.Apart(new Circle(new(0, 0), 3), new Circle(new(5, 0), 2));

    [Fact]
    public void JustApart() =>
        ContactAssert.Apart(new Circle(new(0, 0), 3), new Circle(new(5.001f, 0), 2));

    [Fact]
    public void TinyOverlapIsFound() =>
        ContactAssert.Contact(new Circle(new(0, 0), 5), new Circle(new(9.99f, 0), 5), -0.01, 0, 4.995, 0, 2e-6);

    [Fact]
    public void FarFromTheOriginKeepsTheAccuracyGoal()
    {
        // d = 1000, depth 100; overlap on the line from b (toward −x): t ∈ [200, 300].
        ContactAssert.Contact(
            new Circle(new(24000, -24000), 800), new Circle(new(25000, -24000), 300),
            -100, 0, 24750, -24000, Tolerances.Depth);
    }
}
