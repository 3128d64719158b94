// README.md "Using the library". What README.md shows is the text between the snippet markers.
// <snippet>
using System.Numerics;                       // Vector2: X = world X, Y = world Z
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Geometry;
using URWPGSim2D.Collision.Shapes;
// </snippet>

namespace URWPGSim2D.Collision.Samples.Readme;

/// <summary>A ball overlapping a block is pushed out by the minimum translation vector.</summary>
internal static class UsingTheLibrary
{
    /// <summary>Runs the example and checks what it promises: after the push the two just touch.</summary>
    public static void Run()
    {
        // <snippet>
        var ball = new Circle(new Vector2(100f, 0f), 58f);
        var block = new Aabb(new Vector2(120f, -200f), new Vector2(270f, 200f));
        CollisionDetectionResult hit = CollisionDetector.Detect(ball, block);
        if (hit.Intersect)
            ball = ball.Translated(XZPlane.ToPlane(hit.MinimumTranslationVector)); // now just touching
        // </snippet>

        // The ball's right edge (x = 158) was 38 mm inside the block's left face (x = 120).
        Sample.Check(hit.Intersect, "the ball and the block overlap");
        Sample.Near(ball.Center.X, 120f - 58f, "the ball's centre after the push");
        Sample.Near(ball.Center.Y, 0f, "the push is along X only");
    }
}
