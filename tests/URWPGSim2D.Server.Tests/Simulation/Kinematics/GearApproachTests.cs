using URWPGSim2D.Engine.Simulation.Kinematics;

namespace URWPGSim2D.Server.Tests.Simulation.Kinematics;

/// <summary>
/// The original's gear approach, against sequences worked out by hand from the reference's four
/// rules (T = the VCode table 0, 10, 35, 67, 98, 112, 135, 154, 175, 227, 273, 291, 298, 294, 307,
/// 317; "mid(a, b)" is the midpoint the nearest-code conversion compares with).
/// </summary>
public sealed class GearApproachTests
{
    [Fact]
    public void FromRestTowardVCode14TheSpeedApproachesByTenthsAndSettlesBelowTheTable()
    {
        var g = Rest();

        // Rule 3 only while c = 0: v_k = 307·(1 − 0.9^k) = 30.7, 58.33, 83.197, 105.5773, 125.7196.
        float[] first = [30.7f, 58.33f, 83.197f, 105.5773f, 125.7196f];
        foreach (float v in first)
        {
            g.Advance(14, SpeedTable.Speeds);
            Assert.Equal(v, g.Value, 1e-3f);
            Assert.Equal(0, g.Code);
        }

        // k = 21: 307·0.9^21 = 33.59 > 30.7 = |307 − 0|/10, no snap yet; k = 22: 307·0.9^22 = 30.2325 ≤ 30.7,
        // v = 276.7675 and c ← 14.
        Advance(ref g, 14, 16);
        Assert.Equal(273.4084f, g.Value, 1e-3f);
        Assert.Equal(0, g.Code);
        g.Advance(14, SpeedTable.Speeds);
        Assert.Equal(276.7675f, g.Value, 1e-3f);
        Assert.Equal(14, g.Code);

        // k = 23: c = p = d = 14 but |276.7675 − 307| > 0.01, so rule 2: mid(273, 291) = 282 > 276.7675 ≥
        // mid(227, 273) = 250, c ← 10; then v = 276.7675 + 30.2325/10 = 279.7908 (no snap: 27.21 > |307 − 273|/10 = 3.4).
        g.Advance(14, SpeedTable.Speeds);
        Assert.Equal(279.7908f, g.Value, 1e-3f);
        Assert.Equal(10, g.Code);

        // Gap 30.2325·0.9^n ≤ 3.4 first at n = 21 (3.308): k = 43, v = 303.692, c ← 14. After that rule 2 gives
        // c ← 14 again (mid(294, 307) = 300.5 ≤ 303.692 < mid(307, 317) = 312) = d: the speed stays at 303.692.
        Advance(ref g, 14, 19);
        Assert.Equal(10, g.Code);
        g.Advance(14, SpeedTable.Speeds);
        Assert.Equal(303.692f, g.Value, 2e-3f);
        Assert.Equal(14, g.Code);
        Advance(ref g, 14, 30);
        Assert.Equal(303.692f, g.Value, 2e-3f);
        Assert.Equal(14, g.Code);
    }

    [Fact]
    public void DownFromVCode14ToVCode5()
    {
        var g = Rest();
        Advance(ref g, 14, 60); // settled at 303.692 (previous test)

        // v_k = 112 + (303.692 − 112)·0.9^k = 112 + 191.692·0.9^k: k = 1 → 284.5228.
        g.Advance(5, SpeedTable.Speeds);
        Assert.Equal(284.5228f, g.Value, 2e-3f);
        Assert.Equal(14, g.Code);

        // Snap when 191.692·0.9^k ≤ |112 − 307|/10 = 19.5: k = 21 gives 20.975, k = 22 gives 18.877 → v = 130.877, c ← 5.
        Advance(ref g, 5, 20);
        Assert.Equal(14, g.Code);
        g.Advance(5, SpeedTable.Speeds);
        Assert.Equal(130.877f, g.Value, 2e-3f);
        Assert.Equal(5, g.Code);

        // Next: rule 2, mid(112, 135) = 123.5 ≤ 130.877 < mid(135, 154) = 144.5 → c ← 6; v = 130.877 − 18.877/10 = 128.989.
        g.Advance(5, SpeedTable.Speeds);
        Assert.Equal(128.989f, g.Value, 2e-3f);
        Assert.Equal(6, g.Code);
    }

    [Fact]
    public void AReversalMidApproachTurnsBackAtOnce()
    {
        var g = Rest();
        Advance(ref g, 14, 5); // 125.7196, c = 0, p = 14

        // d = 0 ≠ p = 14 and d = c = 0: rule 1, c ← 14; rule 3: v = 125.7196 − 12.57196 = 113.1476 (no snap:
        // 113.1 > |0 − 307|/10 = 30.7). Without rule 1 (c = d) the fish would keep 125.7 mm/s for ever.
        g.Advance(0, SpeedTable.Speeds);
        Assert.Equal(113.1476f, g.Value, 1e-3f);
        Assert.Equal(14, g.Code);

        // 125.7196·0.9^n ≤ 30.7 first at n = 14: 28.7606, c ← 0 (k = 19).
        Advance(ref g, 0, 12);
        Assert.Equal(31.9562f, g.Value, 1e-3f);
        g.Advance(0, SpeedTable.Speeds);
        Assert.Equal(28.7606f, g.Value, 1e-3f);
        Assert.Equal(0, g.Code);

        // Rule 2: mid(10, 35) = 22.5 ≤ 28.7606 < mid(35, 67) = 51 → c ← 2; v = 0.9·28.7606 = 25.8845.
        g.Advance(0, SpeedTable.Speeds);
        Assert.Equal(25.8845f, g.Value, 1e-3f);
        Assert.Equal(2, g.Code);
    }

    [Fact]
    public void ZeroToFifteenToZeroSettlesAt314AndThenCreepsAt3Point4()
    {
        var g = Rest();

        // 317·(1 − 0.9^k); snap at k = 22 (317·0.9^22 = 31.217 ≤ 31.7): 285.7828; rule 2 → c = 11 (mid(273, 291) = 282 ≤
        // 285.78 < mid(291, 298) = 294.5); gap 31.217·0.9^n ≤ |317 − 291|/10 = 2.6 first at n = 24: 2.4901 → 314.5099 at k = 46.
        Advance(ref g, 15, 22);
        Assert.Equal(285.7828f, g.Value, 1e-3f);
        Assert.Equal(15, g.Code);
        g.Advance(15, SpeedTable.Speeds);
        Assert.Equal(11, g.Code);
        Advance(ref g, 15, 23);
        Assert.Equal(314.5099f, g.Value, 2e-3f);
        Assert.Equal(15, g.Code);
        Advance(ref g, 15, 14); // settled: mid(307, 317) = 312 ≤ 314.51 → c = 15 = d
        Assert.Equal(314.5099f, g.Value, 2e-3f);

        // Back to 0: 314.5099·0.9^n ≤ 31.7 first at n = 22: 30.972 (c ← 0); rule 2 → c = 2 (22.5 ≤ 30.97 < 51); then
        // 30.972·0.9^n ≤ |0 − 35|/10 = 3.5 first at n = 21: 3.3889 (c ← 0); rule 2 gives 0 (3.3889 < mid(0, 10) = 5) = d:
        // the fish creeps on at 3.3889 mm/s.
        g.Advance(0, SpeedTable.Speeds);
        Assert.Equal(283.0589f, g.Value, 2e-3f);
        Advance(ref g, 0, 21);
        Assert.Equal(30.972f, g.Value, 2e-3f);
        Assert.Equal(0, g.Code);
        Advance(ref g, 0, 21);
        Assert.Equal(3.3889f, g.Value, 1e-3f);
        Assert.Equal(0, g.Code);
        Advance(ref g, 0, 50);
        Assert.Equal(3.3889f, g.Value, 1e-3f);
    }

    [Fact]
    public void TheAngularSpeedFollowsTheSameRulesOnTheTurnTable()
    {
        var g = default(GearApproach);
        g.Reset(0f, TurnTable.Rates);

        // 0 rad/s is TCode 7 (mid(−0.052, 0) = −0.026 ≤ 0 < mid(0, 0.052) = 0.026). Toward TCode 14 (0.349):
        // ω_k = 0.349·(1 − 0.9^k) = 0.0349, 0.06631, 0.094579.
        Assert.Equal(7, g.Code);
        float[] expected = [0.0349f, 0.06631f, 0.094579f];
        foreach (float w in expected)
        {
            g.Advance(14, TurnTable.Rates);
            Assert.Equal(w, g.Value, 1e-5f);
        }

        // Toward TCode 0 (−0.394) from rest: −0.0394 in one cycle.
        g.Reset(0f, TurnTable.Rates);
        g.Advance(0, TurnTable.Rates);
        Assert.Equal(-0.0394f, g.Value, 1e-6f);
    }

    [Theory]
    [InlineData(-5f, 0)]
    [InlineData(4.99f, 0)]
    [InlineData(5f, 1)]
    [InlineData(282f, 11)]
    [InlineData(296.2f, 13)] // mid(298, 294) = 296 ≤ 296.2 < mid(294, 307) = 300.5: the table order decides
    [InlineData(312f, 15)]
    [InlineData(900f, 15)]
    public void TheNearestCodeIsDecidedByMidpointsInTableOrder(float value, int code) =>
        Assert.Equal(code, GearApproach.NearestCode(value, SpeedTable.Speeds));

    private static GearApproach Rest()
    {
        var g = default(GearApproach);
        g.Reset(0f, SpeedTable.Speeds);
        return g;
    }

    private static void Advance(ref GearApproach g, int code, int cycles)
    {
        for (int i = 0; i < cycles; i++)
        {
            g.Advance(code, SpeedTable.Speeds);
        }
    }
}
