// <snippet>
using System;
using System.Numerics;                       // Vector2: X = world X, Y = world Z
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Pool;
using URWPGSim2D.Collision.Shapes;

// The pair-level call: when does a ball rolling at 1,000 mm/s meet a resting one 300 mm away?
TimeOfImpactResult first = TimeOfImpact.Find(
    MovingBody.Circle(new Circle(new Vector2(0f, 0f), 50f), new Vector2(1000f, 0f)),
    MovingBody.Static(new Circle(new Vector2(300f, 0f), 50f)),
    seconds: 0.3f);
Console.WriteLine($"pair: contact at {first.Time:0.####} s, depth {first.Result.Depth:0.###} mm");

// The pool (3000 × 2000 mm): its walls and its four goal blocks.
var field = new Field();
var world = new MotionWorld();
world.AddWalls(field);
foreach (var block in field.GoalBlocks)
{
    world.AddStatic(block);
}

// A fish swimming at 300 mm/s toward a resting ball, and a fast ball rolling at a wall.
BodyId fish = world.AddFish(FishSize.Default, new FishPose(new Vector2(-600f, 0f), 0f, 0.1f, -0.05f, 0.1f));
world.SetVelocity(fish, new Vector2(300f, 0f), 0.2f);
BodyId ball = world.AddCircle(58f, new Vector2(-300f, 10f));
BodyId fast = world.AddCircle(38f, new Vector2(1200f, -600f));
world.SetVelocity(fast, new Vector2(2000f, -1000f));

// Ten cycles of 100 ms; every contact comes to the response, in time order.
var response = new StopAndSeparate();
for (int cycle = 1; cycle <= 10; cycle++)
{
    world.Step(0.1f, response);
}

Console.WriteLine($"{response.Contacts} contacts; ball at {world.PositionOf(ball)}, fast ball at {world.PositionOf(fast)}");
Console.WriteLine($"deepest overlap now: {world.MeasureOverlap():0.###} mm");
// </snippet>

// What the docs promise, checked: the fish pushed the ball, the fast ball stayed in the pool, nothing overlaps.
Vector2 f = world.PositionOf(fast);
bool ok = first.Hit && MathF.Abs(first.Time - 0.2f) <= 0.00025f && response.Contacts > 0 && world.PositionOf(ball).X > -300f && world.MeasureOverlap() <= 0.5f
    && MathF.Abs(f.X) + 38f <= 1500.01f && MathF.Abs(f.Y) + 38f <= 1000.01f;
Console.WriteLine(ok ? "sample Motion: ok" : "sample Motion: FAILED");
return ok ? 0 : 1;

// <snippet>

/// <summary>
/// A plain response: the moving body (or both, half each) is pushed out along the contact's
/// translation, and the velocity that closes the contact is removed. A server plugs its own
/// physics in here.
/// </summary>
internal sealed class StopAndSeparate : IContactHandler
{
    public int Contacts { get; private set; }

    public void OnContact(MotionWorld world, in Contact contact)
    {
        Contacts++;
        BodyId a = contact.BodyA, b = contact.BodyB;
        bool bMoves = world.KindOf(b) is BodyKind.Circle or BodyKind.Polygon or BodyKind.Fish;
        float share = bMoves ? 0.5f : 1f;
        var mtv = new Vector2(contact.Result.MinimumTranslationVector.X, contact.Result.MinimumTranslationVector.Z);
        var normal = new Vector2(contact.Result.NormalAxis.X, contact.Result.NormalAxis.Z);
        Vector2 push = (mtv + (normal * 0.01f)) * share;
        world.SetPose(a, world.PositionOf(a) + push, world.HeadingOf(a));
        if (bMoves)
        {
            world.SetPose(b, world.PositionOf(b) - push, world.HeadingOf(b));
        }

        Vector2 va = world.VelocityOf(a), vb = bMoves ? world.VelocityOf(b) : Vector2.Zero;
        float closing = Vector2.Dot(va - vb, normal);
        if (closing < 0f)
        {
            world.SetVelocity(a, va - (normal * (closing * share)), world.AngularVelocityOf(a));
            if (bMoves)
            {
                world.SetVelocity(b, vb + (normal * (closing * share)), world.AngularVelocityOf(b));
            }
        }
    }

    public void OnMoveRejected(MotionWorld world, BodyId body) => Console.WriteLine($"{body}: move rejected");
}
// </snippet>
