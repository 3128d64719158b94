using URWPGSim2D.StrategyHelper;
using XnaFramework = Microsoft.Xna.Framework;

namespace URWPGSim2D.Compat.Tests.StrategyHelper;

/// <summary>
/// The helpers against values computed by hand from their documented behaviour and the gear tables
/// (speeds 0, 10, 35, 67, 98, 112, 135, 154, 175, … mm/s; turn rates −0.394 … 0.349 rad/s).
/// </summary>
public sealed class HelpersTests
{
    // Dribble with the parameters every case here uses (direction 0, 10°/30° aim thresholds, 150 mm near, VCodes 14/8, 15 cycles of 100 ms), as (VCode, TCode); fromCentre: measure from the centre, else from the head tip.
    private static (int VCode, int TCode) Dribble(RoboFish fish, XnaFramework.Vector3 target, bool fromCentre)
    {
        var d = default(Decision);
        Helpers.Dribble(ref d, fish, target, 0f, 10f, 30f, 150f, 14, 8, 15, 100, fromCentre);
        return (d.VCode, d.TCode);
    }

    private static RoboFish FishAtOrigin(float heading = 0f, float angularVelocity = 0f, float speed = 0f)
    {
        var fish = new RoboFish { BodyDirectionRad = heading, AngularVelocityRadPs = angularVelocity, VelocityMmPs = speed };
        fish.PolygonVertices[0] = new XnaFramework.Vector3(110f, 0f, 0f);
        return fish;
    }

    [Theory]
    [InlineData(1f, 1f, 45f)]
    [InlineData(-1f, 0f, 180f)]
    [InlineData(-1f, -1f, -135f)]
    [InlineData(-1f, 1f, 135f)]
    [InlineData(0f, -5f, -90f)]
    [InlineData(0f, 5f, 90f)]
    [InlineData(0f, 0f, 0f)]
    [InlineData(3f, -3f, -45f)]
    public void GetAngleDegreeIsTheFieldDirection(float x, float z, float degrees) =>
        Assert.Equal(degrees, Helpers.GetAngleDegree(new XnaFramework.Vector3(x, 7f, z)), 4);

    [Fact]
    public void DribbleStraightAheadAndFarSwimsAtVCode1()
    {
        // From the head tip (110, 0) to (1000, 0): 890 mm > 150, aim error 0 < 10° → VCode1; no turn → TCode 7.
        Assert.Equal((14, 7), Dribble(FishAtOrigin(), new XnaFramework.Vector3(1000f, 0f, 0f), false));
    }

    [Fact]
    public void DribbleNearAndAlignedSwimsAtVCode2()
    {
        Assert.Equal((8, 7), Dribble(FishAtOrigin(), new XnaFramework.Vector3(200f, 0f, 0f), false)); // 90 mm from the head tip
    }

    [Fact]
    public void DribbleFarOffAxisTurnsSlowly()
    {
        // Target straight down (+Z): error π/2 > 30° → VCode 1; rate needed (π/2)/1.5 s ≈ 1.05 rad/s → sharpest right, 14.
        Assert.Equal((1, 14), Dribble(FishAtOrigin(), new XnaFramework.Vector3(0f, 0f, 1000f), true));
    }

    [Fact]
    public void DribbleBetweenTheThresholdsPicksGearsFromTheTables()
    {
        // 20° off, 1000 mm: turn time 0.349066/0.3715 = 0.94 s → 1064 mm/s needed → VCode capped at 10.
        // Turn rate 0.349066/1.5 = 0.2327 rad/s → first TCode from 7 with rate ≥ it: 12 (0.244).
        var target = new XnaFramework.Vector3(1000f * System.MathF.Cos(0.34906584f), 0f, 1000f * System.MathF.Sin(0.34906584f));
        Assert.Equal((10, 12), Dribble(FishAtOrigin(), target, true));

        // Already turning right at 0.3 rad/s: 0.3·1.5 s = 0.45 rad > 0.349 → counter-steer, TCode 2.
        Assert.Equal((10, 2), Dribble(FishAtOrigin(angularVelocity: 0.3f), target, true));
    }

    [Fact]
    public void DribbleCloseAndSlightlyOffTakesTheSlowestSufficientSpeed()
    {
        // 15° off, 100 mm: turn time 0.261799/0.3715 = 0.7047 s → 141.9 mm/s → VCode 7 (154);
        // horizon min(100/307, 1.5) = 0.3257 s → 0.80 rad/s → TCode 14.
        var target = new XnaFramework.Vector3(100f * System.MathF.Cos(0.2617994f), 0f, 100f * System.MathF.Sin(0.2617994f));
        Assert.Equal((7, 14), Dribble(FishAtOrigin(), target, true));
    }

    [Fact]
    public void PoseToPoseFarFromTheStagingPointHeadsForIt()
    {
        // Target (0, 0) facing +X, staging point 200 mm behind it at (−200, 0): the fish at (−1000, 0)
        // heading +X swims at VCode 8, straight (no line-of-sight rate).
        var fish = new RoboFish { PositionMm = new XnaFramework.Vector3(-1000f, 0f, 0f), VelocityMmPs = 100f };
        var d = default(Decision);
        int times = 0;
        Helpers.PoseToPose(ref d, fish, XnaFramework.Vector3.Zero, 0f, 30f, 200f, 100, ref times);
        Assert.Equal((8, 7, 0), (d.VCode, d.TCode, times));
    }

    [Fact]
    public void PoseToPoseFacingAwayTurnsOnTheSpot()
    {
        // At the target itself facing +X: the staging point (−200, 0) lies behind. The aim error is the
        // float π, a hair above π as a double, so it wraps to −π: turn left on the spot, V1 T1.
        var d = default(Decision);
        int times = 0;
        Helpers.PoseToPose(ref d, new RoboFish(), XnaFramework.Vector3.Zero, 0f, 30f, 200f, 100, ref times);
        Assert.Equal((1, 1), (d.VCode, d.TCode));

        // At (300, −1) facing +X the staging point lies behind and 1 mm toward +Z: aim 179.885°, error
        // +3.1396 rad (inside π) → turn right on the spot, V1 T13.
        Helpers.PoseToPose(ref d, new RoboFish { PositionMm = new XnaFramework.Vector3(300f, 0f, -1f) }, XnaFramework.Vector3.Zero, 0f, 30f, 200f, 100, ref times);
        Assert.Equal((1, 13), (d.VCode, d.TCode));
    }

    [Fact]
    public void PoseToPoseNearPhaseCreepsThenStops()
    {
        // Near phase (times > 0) at (−300, 0): u1 = 0.6·300·sin²(0.2) = 7.1 mm/s → lowest gear 2, straight.
        var d = default(Decision);
        int times = 1;
        Helpers.PoseToPose(ref d, new RoboFish { PositionMm = new XnaFramework.Vector3(-300f, 0f, 0f) }, XnaFramework.Vector3.Zero, 0f, 30f, 200f, 100, ref times);
        Assert.Equal((2, 7, 2), (d.VCode, d.TCode, times));

        // Within 150 mm and 10° of aim: stop.
        Helpers.PoseToPose(ref d, new RoboFish { PositionMm = new XnaFramework.Vector3(-100f, 0f, 0f) }, XnaFramework.Vector3.Zero, 0f, 30f, 200f, 100, ref times);
        Assert.Equal((0, 7, 3), (d.VCode, d.TCode, times));
    }
}
