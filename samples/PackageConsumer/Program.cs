using System;
using System.Numerics;
using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Collision.Shapes;
using URWPGSim2D.Strategies;

// A consumer of the packages: one call into each library, checked against hand-computed numbers.
// Exits 1 on a wrong answer.
int failures = 0;

// URWPGSim2D.Collision: a ball of radius 58 at x = 100 overlaps a box starting at x = 120 by
// 38 mm; the MTV pushes it back along −x by that much.
var ball = new Circle(new Vector2(100f, 0f), 58f);
var block = new Aabb(new Vector2(120f, -200f), new Vector2(270f, 200f));
CollisionDetectionResult hit = CollisionDetector.Detect(ball, block);
Check("ball–box intersect", hit.Intersect);
Check("ball–box MTV is (−38, 0, 0)", MathF.Abs(hit.MinimumTranslationVector.X + 38f) < 1e-3f
                                     && MathF.Abs(hit.MinimumTranslationVector.Z) < 1e-3f);

// The motion world: a ball rolling at 1,000 mm/s toward a resting one 200 mm away (radii 58) first
// touches it after (200 − 116) / 1000 s = 0.084 s of the 0.1 s step (the motion world finds the time
// of first contact to within about 0.5 mm of travel: here 0.005 of the step).
var world = new MotionWorld();
BodyId a = world.AddCircle(58f, new Vector2(0f, 0f));
BodyId b = world.AddCircle(58f, new Vector2(200f, 0f));
world.SetVelocity(a, new Vector2(1000f, 0f));
var firstContact = new FirstContact();
world.Step(0.1f, firstContact);
Check($"first contact at 0.84 of the step (got {firstContact.Time})", Math.Abs(firstContact.Time - 0.84) <= 0.005);

// A fish model at the reference's deployed pose is a real, posed object.
var fish = new FishModel(FishSize.Default, new FishPose(Vector2.Zero, 0f, 0f, 0f, 0f));
Check("the fish's bounds contain its centre", fish.Bounds.Min.X < 0f && fish.Bounds.Max.X > 0f);

// URWPGSim2D.Strategies: a decision's gears.
var decision = new Decision(12, 7);
Check("decision gears", decision.VCode == 12 && decision.TCode == 7);

// URWPGSim2D.Compat: the original's vector type.
var v = new Microsoft.Xna.Framework.Vector3(3f, 0f, 4f);
Check("Vector3 length 5", MathF.Abs(v.Length() - 5f) < 1e-6f);

Console.WriteLine(failures == 0 ? "package consumer: all checks passed" : $"package consumer: {failures} check(s) failed");
return failures == 0 ? 0 : 1;

void Check(string what, bool ok)
{
    if (!ok)
    {
        Console.WriteLine($"FAILED: {what}");
        failures++;
    }
}

/// <summary>Records the time of the first contact of a step and applies no response.</summary>
internal sealed class FirstContact : IContactHandler
{
    public double Time { get; private set; } = double.NaN;

    public void OnContact(MotionWorld world, in Contact contact)
    {
        if (double.IsNaN(Time))
        {
            Time = contact.Time;
        }

        world.SetVelocity(contact.BodyA, Vector2.Zero); // the striker stops
    }

    public void OnMoveRejected(MotionWorld world, BodyId body)
    {
    }
}
