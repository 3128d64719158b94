// docs/queries.md "From C#". What the docs show is the text between the snippet markers.
// <snippet>
using System;
using System.Numerics;                       // Vector2: X = world X, Y = world Z
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Queries;
using URWPGSim2D.Collision.Shapes;
// </snippet>

namespace URWPGSim2D.Collision.Samples.Queries;

/// <summary>Is the way from a fish to the ball clear, how far is the ball, and what is in the box ahead.</summary>
internal static class SensingTheWay
{
    /// <summary>Runs the example and checks its answers against the geometry.</summary>
    public static void Run()
    {
        // <snippet>
        var fish = new FishModel(FishSize.Default, new FishPose(new Vector2(-400f, 0f), 0f));
        var ball = new Circle(new Vector2(400f, 0f), 58f);
        var obstacle = new Aabb(new Vector2(0f, -100f), new Vector2(40f, 20f));

        var world = new QueryWorld();
        int fishBody = world.Add(fish);
        int ballBody = world.Add(ball);
        int obstacleBody = world.Add(obstacle);

        // Is the way from the fish's head to the ball clear? The first body the ray enters says.
        BodyRayHit first = world.RayCast(fish.HeadTip + new Vector2(1f, 0f), ball.Center);
        bool clear = first.Body == ballBody;                   // false: the obstacle is in the way

        // How far is the ball from the fish, and which part of the fish is nearest?
        DistanceResult gap = ShapeQuery.Distance(fish, ball);  // (400 − 58) − (−400 + 80 + 30) = 632 mm, from the head

        // Where would the ball stop if pushed 500 mm toward −x?
        ShapeCastResult push = ShapeQuery.Cast(ball, new Vector2(-500f, 0f), obstacle);

        // Which bodies lie in the box ahead of the fish?
        Span<int> ahead = stackalloc int[4];
        int count = world.Overlap(new Aabb(new Vector2(-250f, -50f), new Vector2(100f, 50f)), ahead);
        Console.WriteLine($"clear {clear}, hit body {first.Body} at {first.Result.Point}; gap {gap.Distance} mm ({gap.PartA}); " +
                          $"the ball stops after {push.Fraction * 500f} mm; {count} body ahead: {ahead[0]}");
        // </snippet>

        Sample.Check(!clear && first.Body == obstacleBody, "the obstacle blocks the way");
        Sample.Near(first.Result.Point.X, 0f, "the ray enters the obstacle's left face");
        Sample.Near(gap.Distance, (400f - 58f) - (-400f + 110f), "the gap between the head tip and the ball");
        Sample.Check(gap.PartA == FishPart.Body, "the head (part of the body leaf) is nearest");
        Sample.Check(push.Hit && MathF.Abs((push.Fraction * 500f) - (400f - 58f - 40f)) <= 2e-3f, "the ball stops at the obstacle's right face");
        Sample.Check(count == 1 && ahead[0] == obstacleBody && fishBody == 0, "only the obstacle is in the box ahead");
    }
}
