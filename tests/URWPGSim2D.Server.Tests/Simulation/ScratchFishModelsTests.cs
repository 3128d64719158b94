using System;
using System.Numerics;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Motion;
using URWPGSim2D.Server.Simulation;
using Xunit;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// The separation's scratch fish models: each use lays out the fish at its pose now, exactly as a
/// model built fresh there would, whatever fish of whatever size the model last held; a world of
/// several fish sizes gets a pair of models per size up front, so alternating sizes allocates nothing.
/// </summary>
public sealed class ScratchFishModelsTests
{
    private static readonly FishSize Small = new(120f, 35f, 22f, 66f, 50f, 41f);

    [Fact]
    public void AModelIsTheFishAtItsPoseNowAsAFreshModelWouldBe()
    {
        var fish = World(out var motion);
        var scratch = new ScratchFishModels(fish);
        var random = new Random(7);
        for (int trial = 0; trial < 200; trial++)
        {
            int index = random.Next(fish.Length), slot = random.Next(2);
            var f = fish[index];
            f.Position = new Vector2(random.NextSingle() * 2000f - 1000f, random.NextSingle() * 1400f - 700f);
            f.Heading = random.NextSingle() * 6f - 3f;
            f.SetJoints(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f);
            FishModel model = scratch.Posed(slot, index);
            var fresh = new FishModel(f.Size, f.Pose);
            Assert.Equal(f.Size, model.Size);
            Assert.Equal(fresh.Pose, model.Pose);
            Assert.Equal(fresh.Bounds, model.Bounds);
            Assert.Equal(fresh.Root, model.Root);
            Assert.Equal(fresh.TailGroup, model.TailGroup);
            foreach (FishPart part in Enum.GetValues<FishPart>())
            {
                Assert.True(fresh.GetLeaf(part).SequenceEqual(model.GetLeaf(part)), $"trial {trial}: leaf {part} of fish {index} differs from a fresh model's");
            }
        }

        GC.KeepAlive(motion);
    }

    [Fact]
    public void APairOfModelsPerSizeIsSharedByTheFishOfThatSize()
    {
        var fish = World(out _);
        var scratch = new ScratchFishModels(fish);
        Assert.Same(scratch.Posed(0, 0), scratch.Posed(0, 2));
        Assert.Same(scratch.Posed(1, 0), scratch.Posed(1, 2));
        Assert.NotSame(scratch.Posed(0, 0), scratch.Posed(1, 2));
        Assert.NotSame(scratch.Posed(0, 0), scratch.Posed(0, 1));
        Assert.Equal(Small, scratch.Posed(0, 1).Size);
        Assert.Equal(FishSize.Default, scratch.Posed(1, 2).Size);
    }

    [Fact]
    public void PosingFishOfAlternatingSizesAllocatesNothing()
    {
        var fish = World(out _);
        var scratch = new ScratchFishModels(fish);
        scratch.Posed(0, 0);
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            scratch.Posed(0, i % 3);
            scratch.Posed(1, (i + 1) % 3);
        }

        Assert.Equal(0L, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    // Three fish: the default size, a smaller one, the default size again.
    private static FishState[] World(out Stepper motion)
    {
        motion = new Stepper();
        return
        [
            new FishState(motion, 0, 0, FishSize.Default, new Vector2(-500f, 0f), 0f),
            new FishState(motion, 1, 1, Small, new Vector2(0f, 300f), 1f),
            new FishState(motion, 2, 1, FishSize.Default, new Vector2(500f, 0f), 2f),
        ];
    }
}
