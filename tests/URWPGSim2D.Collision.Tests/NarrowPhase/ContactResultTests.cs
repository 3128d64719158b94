using System.Runtime.Intrinsics;

namespace URWPGSim2D.Collision.Tests.NarrowPhase;

public sealed class ContactResultTests
{
    [Fact]
    public void WritesTheSameResultAsTheConstructorBitForBit()
    {
        // Signed zeros, negative components, large coordinates; from plane vectors (Plane) and
        // from vectors laid out as x, +0, z, +0 (World), negative depths included (whose product
        // with the normal's zero lanes is −0: the MTV's y must still be +0).
        var rng = new Random(94);
        float[] specials = [0f, -0f, 1f, -1f, 25000f, -25000f, 1e-30f];
        for (int trial = 0; trial < 5000; trial++)
        {
            float Pick() => rng.Next(4) == 0 ? specials[rng.Next(specials.Length)] : (float)((rng.NextDouble() - 0.5) * 50000);
            var normal = new Vector2(Pick(), Pick());
            float depth = Pick();
            var point = new Vector2(Pick(), Pick());
            var expected = CollisionDetectionResult.FromPlane(normal, depth, point);
            var world = ContactResult.World(Vector128.Create(normal.X, 0f, normal.Y, 0f), depth, Vector128.Create(point.X, 0f, point.Y, 0f));
            foreach (var actual in new[] { ContactResult.Plane(normal, depth, point), world })
            {
                Assert.True(expected.Intersect && actual.Intersect);
                Assert.Equal(Bits(expected.MinimumTranslationVector), Bits(actual.MinimumTranslationVector));
                Assert.Equal(Bits(expected.NormalAxis), Bits(actual.NormalAxis));
                Assert.Equal(Bits(expected.ActionPoint), Bits(actual.ActionPoint));
                Assert.Equal(expected, actual);
            }
        }
    }

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));
}
