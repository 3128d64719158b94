namespace URWPGSim2D.Collision.Tests.Fish;

/// <summary>
/// Fish of one size share one template; with more sizes than are shared, each template asked for
/// is of its size and holds that size's leaves (against the local geometry written afresh), and
/// the sizes asked for last are the ones shared.
/// </summary>
public sealed class FishTemplatesTests
{
    [Fact]
    public void EverySizeGetsItsOwnLeavesAndOneSizeSharesOneTemplate()
    {
        var templates = new FishTemplates();
        var random = new Random(7);
        var sizes = new List<FishSize>();
        for (int i = 0; i < 40; i++)
        {
            sizes.Add(new FishSize(
                120f + (80f * random.NextSingle()), 30f + (20f * random.NextSingle()), 20f + (20f * random.NextSingle()),
                60f + (40f * random.NextSingle()), 50f + (30f * random.NextSingle()), 40f + (30f * random.NextSingle())));
        }

        // Each size asked for twice, the second time after every other size (more sizes than are shared).
        var first = sizes.Select(s => templates.For(s)).ToList();
        for (int i = 0; i < sizes.Count; i++)
        {
            FishTemplate again = templates.For(sizes[i]);
            Assert.Equal(sizes[i], again.Size);
            Assert.Equal(sizes[i], first[i].Size);
            Assert.Equal(first[i].Vertices.ToArray(), again.Vertices.ToArray());
            Assert.Equal(first[i].Normals.ToArray(), again.Normals.ToArray());

            // The leaves are the size's: the same points the local geometry writes, each leaf counter-clockwise.
            var written = new Vector2[FishLeafLayout.VertexCount];
            FishLocalGeometry.Write(sizes[i], written);
            for (int leaf = 0; leaf < FishLeafLayout.LeafCount; leaf++)
            {
                int at = FishLeafLayout.Offset(leaf), n = FishLeafLayout.Count(leaf);
                Assert.Equal(
                    written.AsSpan(at, n).ToArray().OrderBy(p => p.X).ThenBy(p => p.Y),
                    again.Vertices.Slice(at, n).ToArray().OrderBy(p => p.X).ThenBy(p => p.Y));
                Assert.True(ConvexPolygon.SignedArea2(again.Vertices.Slice(at, n)) > 0f);
            }
        }

        // The last sizes asked for are shared; an older one was replaced by a newer and is made anew.
        for (int i = sizes.Count - FishTemplates.Capacity; i < sizes.Count; i++)
        {
            Assert.Same(templates.For(sizes[i]), templates.For(sizes[i]));
        }

        Assert.NotSame(first[0], templates.For(sizes[0]));
        Assert.Same(templates.For(FishSize.Default), templates.For(new FishSize(160f, 45f, 30f, 88f, 66f, 55f)));
    }
}
