using URWPGSim2D.Engine.Matches;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Server.Tests.Simulation;

/// <summary>
/// The original's velocity response against numbers worked out by hand from the reference's
/// formulas (masses fish 0.8, ball 0.49; fish–ball e = −0.005·(1 − d/300), d from the head tip
/// (110 mm ahead of the centre) along the axis; exchange v₁' = (m₁v₁ + m₂(v₂ + e(v₂ − v₁)))/(m₁ + m₂);
/// turning J = m·|Δv_n|, heading += (J·r⊥/6000)·0.01 with r⊥ = r × (unit impulse on the fish)).
/// The fish rests at the origin heading +X with a straight tail (deployed sizes), so its left
/// flank is the −Z side; a ball of radius 58 arrives square on (along the contact normal).
/// </summary>
public sealed class ReferenceExchangeTests
{
    // Head: the face from (80, −22.5) to (110, 0), outward normal (0.6, −0.8), struck at its middle (95, −11.25):
    //   d = 110 − 95 = 15, e = −0.00475; v_ball' = V·(0.49 + 0.8·0.00475)/1.29 = 0.382791·V;
    //   J = 0.49·0.617209·V = 0.302432·V along n = (−0.6, 0.8); r⊥ = 95·0.8 − (−11.25)·(−0.6) = 69.25;
    //   Δθ = 0.302432·V·69.25/600000 = +3.49058e−5·V (V = 100: +0.0034906, V = 300: +0.0104717 rad = +0.60°).
    // Body: the flank z = −22.5 struck at x = 60 (clear of the pectoral fin, which ends at x = 40), n = (0, 1):
    //   d = 50, e = −0.0041667; v_ball' = V·(0.49 + 0.0033333)/1.29 = 0.382429·V; J = 0.302610·V; r⊥ = 60;
    //   Δθ = +3.02610e−5·V (V = 100: +0.0030261, V = 300: +0.0090783 rad = +0.52°).
    // Tail: the left caudal tip (−344, −50) struck from −Z, n = (0, 1): d = 454, e = −0.005·(1 − 454/300) = +0.0025667;
    //   v_ball' = V·(0.49 − 0.0020533)/1.29 = 0.378253·V (300 → 113.48, the reference's "about 114");
    //   J = 0.304656·V; r⊥ = −344; Δθ = −1.74669e−4·V (V = 100: −0.0174669, V = 300: −0.0524008 rad = −3.0°).
    // Head and body hits turn the heading up (the head swings to +Z, away from the ball); a tail hit turns it down
    // (the tail swings to +Z): the struck point always moves away from the ball (the original always turned up).
    [Theory]
    [InlineData("head", 100f, 0.382791f, 0.0034906f)]
    [InlineData("head", 300f, 0.382791f, 0.0104717f)]
    [InlineData("body", 100f, 0.382429f, 0.0030261f)]
    [InlineData("body", 300f, 0.382429f, 0.0090783f)]
    [InlineData("tail", 100f, 0.378253f, -0.0174669f)]
    [InlineData("tail", 300f, 0.378253f, -0.0524008f)]
    public void ABallHittingARestingFishSquareOn(string where, float speed, float kept, float turn)
    {
        (Vector2 point, Vector2 n) = where switch
        {
            "head" => (new Vector2(95f, -11.25f), new Vector2(-0.6f, 0.8f)),
            "body" => (new Vector2(60f, -22.5f), new Vector2(0f, 1f)),
            _ => (new Vector2(-344f, -50f), new Vector2(0f, 1f)),
        };

        var match = RestingFishAndBall(point - (n * (58f - 0.05f)), n * speed);
        var fish = match.World.Fish[0];
        var ball = match.World.Balls[0];
        var pair = new CandidatePair(PairKind.FishBall, 0, 0, 60f);
        Contact hit = match.World.Detect(pair);
        Assert.True(hit.Intersect);
        Assert.Equal(n.X, hit.Normal.X, 1e-3f);
        Assert.Equal(n.Y, hit.Normal.Y, 1e-3f);

        new ContactResponse(match.World).Apply(pair, hit);

        Assert.Equal(kept * speed * n.X, ball.Velocity.X, 0.01f);
        Assert.Equal(kept * speed * n.Y, ball.Velocity.Y, 0.01f);
        Assert.Equal(turn, fish.Heading, Math.Abs(turn) * 0.005f);
        Assert.Equal(Vector2.Zero, fish.Velocity);
        Assert.Equal(0f, fish.AngularVelocity);
        Assert.Equal(0f, fish.Speed.Value);
        Assert.Equal(0f, fish.Turn.Value);
    }

    [Fact]
    public void FiveThousandMillimetresPerSecondAtTheCaudalTipTurnsTheFishFiftyDegreesNotMore()
    {
        // As above with V = 5000: Δθ = −1.74669e−4·5000 = −0.873347 rad (−50.0°); the ball keeps 0.378253·5000 = 1891.27.
        var match = RestingFishAndBall(new Vector2(-344f, -50f - 57.95f), new Vector2(0f, 5000f));
        var pair = new CandidatePair(PairKind.FishBall, 0, 0, 60f);
        new ContactResponse(match.World).Apply(pair, match.World.Detect(pair));
        Assert.Equal(-0.873347f, match.World.Fish[0].Heading, 0.005f);
        Assert.Equal(1891.27f, match.World.Balls[0].Velocity.Y, 0.5f);
    }

    [Fact]
    public void InAMatchABallStruckFishTurnsOnceAndYieldsWithoutPassingThrough()
    {
        // The body case in a match: the ball starts 15 mm above the flank at x = 60 moving +Z at 300 mm/s and hits in
        // the middle of cycle 1 (drag applies after the cycle's travel). First contact: the exchange above (ball
        // 114.729, Δθ = +0.0090783); the ball still closes on the fish, and its next contact in the cycle is pressing:
        // both move on at (0 + 114.729)/2 = 57.364 along the normal and nothing turns. Drag at 50 ≤ v < 100:
        // −100·0.1 → 47.364. The fish's speed (its gear approach) stays 0; the ball is still on the −Z side.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"strategy":"idle"}],"balls":[{"position":[60,-95.5],"velocity":[0,300]}]}""");
        match.Step();
        var fish = match.World.Fish[0];
        var ball = match.World.Balls[0];
        Assert.Equal(0.0090783f, fish.Heading, 5e-5f);
        Assert.Equal(47.364f, ball.Velocity.Length(), 0.2f);
        Assert.Equal(0f, fish.Speed.Value);
        Assert.True(ball.Position.Y < fish.Position.Y - 58f, $"ball at {ball.Position}, fish at {fish.Position}");
    }

    [Fact]
    public void AFiveThousandMillimetresPerSecondBallDoesNotPassThroughOrSpinTheFish()
    {
        // The body case at 5000 mm/s (75 mm above the flank, contact at t = 0.015 s): Δθ = +3.02610e−5·5000 = +0.151305 rad
        // (8.7°) in the cycle of impact, the ball stays on its side of the fish, the fish's speed stays 0, and in the
        // following cycles (the ball slides off the turned flank) it never ends a cycle inside the fish.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"strategy":"idle"}],"balls":[{"position":[60,-155.5],"velocity":[0,5000]}]}""");
        match.Step();
        var fish = match.World.Fish[0];
        var ball = match.World.Balls[0];
        Assert.Equal(0.151305f, fish.Heading, 0.002f);
        Assert.Equal(0f, fish.Speed.Value);
        Assert.True(ball.Position.Y < fish.Position.Y - 58f, $"ball at {ball.Position}, fish at {fish.Position}");
        var pair = new CandidatePair(PairKind.FishBall, 0, 0, 60f);
        for (int k = 2; k <= 20; k++)
        {
            match.Step();
            Assert.True(match.World.Detect(pair).Depth <= 0.5f, $"cycle {k}: ball inside the fish");
        }
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void FishFishExchangeAndTheSignOfItsTurn(bool struckFishSecond)
    {
        // A (heading +Z, in-cycle velocity (0, 300)) drives its head tip 0.05 mm into B's left flank at x = 60; B rests.
        // n = (0, −1) from B toward A: v_A = −300, v_B = 0; d_A = 0, d_B = 50, e' = −0.005·(1 − 50/600) = −0.0045833;
        // v_A' = (−300 + e'·300)/2 = −150.6875, v_B' = (−300 − e'·300)/2 = −149.3125 → A moves on at (0, 150.6875),
        // B at (0, 149.3125). B's impulse 0.8·149.3125 = 119.45 along +Z at r_B = (60, −22.5): r⊥ = 60,
        // Δθ_B = 119.45·60/600000 = +0.011945 (B's head swings away from A). A is struck along its axis: no turn.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"strategy":"idle"},{"team":1,"position":[60,-132.45],"heading":1.5707964,"strategy":"idle"}],"balls":[]}""");
        var b = match.World.Fish[0];
        var a = match.World.Fish[1];
        a.Velocity = new Vector2(0f, 300f);
        // Either fish may be the pair's first (the normal then points the other way): the result is the same.
        var pair = struckFishSecond ? new CandidatePair(PairKind.FishFish, 1, 0, 10f) : new CandidatePair(PairKind.FishFish, 0, 1, 10f);
        Contact hit = match.World.Detect(pair);
        Assert.True(hit.Intersect);
        new ContactResponse(match.World).Apply(pair, hit);
        Assert.Equal(0.011945f, b.Heading, 1e-4f);
        Assert.Equal(1.5707964f, a.Heading, 1e-4f);
        Assert.Equal(150.6875f, a.Velocity.Y, 0.05f);
        Assert.Equal(149.3125f, b.Velocity.Y, 0.05f);
        Assert.Equal(0f, a.Speed.Value);
        Assert.Equal(0f, b.Speed.Value);
    }

    [Fact]
    public void AFishSwimmingIntoAnObstacleKeepsOnlyThreeThousandthsOfItsNormalSpeed()
    {
        // VCode 14 from rest: 30.7 mm/s in cycle 1; the head tip (110, 0) is 2 mm from a round obstacle (radius 58 at
        // x = 170): contact at t ≈ 0.065 s at d ≈ 0. n = (−1, 0): v_n = −30.7 → −0.003·(1 − 0/300)·(−30.7) = +0.0921, so
        // the fish moves on at (−0.0921, 0) for the rest of the cycle; struck along its axis it does not turn; its
        // speed stays the gear's 30.7.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"decision":{"vcode":14,"tcode":7}}],"balls":[],"obstacles":[{"type":"round","center":[170,0],"radius":58}]}""");
        match.Step();
        var fish = match.World.Fish[0];
        Assert.Equal(-0.0921f, fish.Velocity.X, 0.002f);
        Assert.Equal(0f, fish.Heading, 1e-5f);
        Assert.Equal(30.7f, fish.Speed.Value, 1e-3f);
    }

    // A fish heading +X at 300 mm/s strikes a round obstacle (radius 58) with the middle (95, ∓11.25) of a head face,
    // square on: n = (−0.6, ±0.8) from the obstacle into the fish. v_n = 300·(−0.6) = −180; d = 110 − 95 = 15;
    // v_n' = −0.003·(1 − 15/300)·(−180) = +0.513; Δv_n = 180.513 → v = (300, 0) + 180.513·(−0.6, ±0.8) = (191.692, ±144.410).
    // J = 0.8·180.513 = 144.410 along n; r⊥ = 95·(±0.8) − (∓11.25)(−0.6) = ±69.25; Δθ = 144.410·(±69.25)/600000 = ±0.0166674:
    // the head is pushed away from the obstacle (to +Z when struck on its −Z face), so the heading turns toward +Z.
    [Theory]
    [InlineData(-1f)]
    [InlineData(1f)]
    public void AFishStrikingAnObstacleWithItsHeadTurnsAwayFromIt(float side)
    {
        Vector2 point = new(95f, side * 11.25f);
        Vector2 n = new(-0.6f, -side * 0.8f);
        Vector2 centre = point - (n * (58f - 0.05f));
        string at = string.Create(System.Globalization.CultureInfo.InvariantCulture, $"[{centre.X},{centre.Y}]");
        var match = TestMatches.FromJson("{\"fish\":[{\"team\":0,\"position\":[0,0],\"strategy\":\"idle\"}],\"balls\":[],\"obstacles\":[{\"type\":\"round\",\"center\":" + at + ",\"radius\":58}]}");
        var fish = match.World.Fish[0];
        fish.Velocity = new Vector2(300f, 0f);
        int obstacle = Array.FindIndex(match.World.Statics, s => !s.IsGoalBlock);
        var pair = new CandidatePair(PairKind.FishStatic, 0, obstacle, 0f);
        Contact hit = match.World.Detect(pair);
        Assert.True(hit.Intersect);
        Assert.Equal(n.X, hit.Normal.X, 1e-3f);
        Assert.Equal(n.Y, hit.Normal.Y, 1e-3f);

        new ContactResponse(match.World).Apply(pair, hit);

        Assert.Equal(191.692f, fish.Velocity.X, 0.02f);
        Assert.Equal(-side * 144.410f, fish.Velocity.Y, 0.02f);
        Assert.Equal(-side * 0.0166674f, fish.Heading, 0.0166674f * 0.005f);
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void APectoralFinPushesTheBallThreeQuartersOfTheCorrection(bool pectoral)
    {
        // A ball 2 mm into the left fin's tip (−46.667, −60) from −Z, or 2 mm into the flank at x = 60: the correction
        // (2 + 0.01 margin) is split 3/4 ball, 1/4 fish on the fin, 1/2 each elsewhere. No velocities.
        Vector2 contact = pectoral ? new Vector2(-46.6667f, -60f) : new Vector2(60f, -22.5f);
        var match = RestingFishAndBall(contact - new Vector2(0f, 56f), Vector2.Zero);
        var pair = new CandidatePair(PairKind.FishBall, 0, 0, 60f);
        Contact hit = match.World.Detect(pair);
        Assert.Equal(2f, hit.Depth, 0.01f);
        new ContactResponse(match.World).Apply(pair, hit);
        float ballShare = pectoral ? 0.75f : 0.5f;
        Assert.Equal(contact.Y - 56f - (ballShare * 2.01f), match.World.Balls[0].Position.Y, 0.01f);
        Assert.Equal((1f - ballShare) * 2.01f, match.World.Fish[0].Position.Y, 0.01f);
    }

    [Fact]
    public void ABallIntoAWallKeepsAThousandthOfItsNormalSpeedAndItsDirectionIsNotForcedIntoPlusZ()
    {
        // Toward the bottom wall z = 1000 at (0, 1000) mm/s from 30 mm away: contact at t = 0.03; v_n' = −0.001·1000 → the
        // ball leaves at (0, −1); drag below 25 mm/s: −6.25·0.1 → (0, −0.375). (The original turned every direction after
        // a wall into [0, π], i.e. +Z: this ball would have stayed on the wall going +Z.) With a tangential 400 mm/s:
        // (400, −1) → speed 400.0012 ≥ 100: −25 → (375, −0.9375).
        var match = TestMatches.Balls(string.Empty, 0f, 1000f - 58f - 30f, 0f, 1000f, -600f, 1000f - 58f - 30f, 400f, 1000f);
        match.Step();
        Assert.Equal(0f, match.World.Balls[0].Velocity.X, 1e-4f);
        Assert.Equal(-0.375f, match.World.Balls[0].Velocity.Y, 1e-3f);
        Assert.Equal(375f, match.World.Balls[1].Velocity.X, 0.01f);
        Assert.Equal(-0.9375f, match.World.Balls[1].Velocity.Y, 1e-3f);
        Assert.InRange(match.World.Balls[0].Position.Y, 1000f - 58f - 0.2f, 1000f - 58f);
    }

    [Fact]
    public void ABallIntoATurnedObstacleKeepsATenthOfItsNormalSpeedAndAllOfItsTangentialSpeed()
    {
        // A 100 × 100 square obstacle at the origin turned by 45°: its face toward −X, −Z has outward normal (−√½, −√½) and
        // lies at distance 50 from the centre. The ball arrives with velocity (600, 200): normal part v_n = −(600 + 200)·√½ =
        // −565.685 (n = (−√½, −√½)), tangential (600, 200) − 565.685·√½·(1, 1) = (200, −200). After: −0.1·v_n = 56.569 along
        // n → (−40, −40) + (200, −200) = (160, −240); speed 288.44 ≥ 100: drag −25 → ×(263.44/288.44) = (146.13, −219.20).
        var match = TestMatches.Balls(""","obstacles":[{"type":"rectangle","center":[0,0],"length":100,"width":100,"heading":0.7853982}]""", -78.5f, -78.5f, 600f, 200f);
        match.Step();
        Vector2 v = match.World.Balls[0].Velocity;
        Assert.Equal(146.13f, v.X, 0.1f);
        Assert.Equal(-219.20f, v.Y, 0.1f);
    }

    [Fact]
    public void AFishPushingABallHeadOnKeepsSwimmingAndTheBallStaysAtItsHead()
    {
        // VCode 8 from rest (the gear approach, untouched by the ball): 17.5, 33.25, …, 157.7665 at cycle 22 (c ← 8),
        // 159.4899 at cycle 23 (c ← 7: mid(154, 175) = 164.5 > 157.77 ≥ mid(135, 154) = 144.5), settled at 172.9048 from
        // cycle 50 on; swimming free it covers 0.1·Σv = 1582.23 mm in 100 cycles (its tail, 339 mm behind its centre,
        // starts clear of the wall at x = −1500). The ball rests 20 mm ahead of the head tip. Every cycle: the ball is
        // never faster than the fish, stays centred on the axis and touching the tip.
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[-1100,0],"decision":{"vcode":8,"tcode":7}}],"balls":[{"position":[-912,0]}]}""");
        var fish = match.World.Fish[0];
        var ball = match.World.Balls[0];
        bool touched = false;
        for (int k = 1; k <= 100; k++)
        {
            match.Step();
            float tipToBall = ball.Position.X - (fish.Position.X + 110f);
            touched |= tipToBall < 58.5f;
            Assert.True(ball.Velocity.Length() <= fish.Speed.Value + 1e-3f, $"cycle {k}: ball {ball.Velocity.Length()} mm/s, fish {fish.Speed.Value}");
            Assert.True(MathF.Abs(ball.Position.Y - fish.Position.Y) < 0.5f, $"cycle {k}: ball off the axis by {ball.Position.Y - fish.Position.Y}");
            Assert.True(MathF.Abs(fish.Heading) < 1e-4f, $"cycle {k}: heading {fish.Heading}");
            if (touched)
            {
                Assert.InRange(tipToBall, 57.9f, 58.5f);
            }
        }

        Assert.True(touched);
        Assert.Equal(172.9048f, fish.Speed.Value, 2e-3f);
        float travelled = fish.Position.X + 1100f;

        // Measured 1520.25: each cycle the water slows the ball by 25 mm/s and the fish, pressing it back up to
        // speed, moves on at their common speed for the rest of the cycle, about 4 % of its travel.
        Assert.InRange(travelled, 0.95f * 1582.23f, 0.97f * 1582.23f);
    }

    private static Match RestingFishAndBall(Vector2 ballPosition, Vector2 ballVelocity)
    {
        var match = TestMatches.FromJson("""{"fish":[{"team":0,"position":[0,0],"strategy":"idle"}],"balls":[{"position":[600,600]}]}""");
        match.World.Balls[0].Position = ballPosition;
        match.World.Balls[0].Velocity = ballVelocity;
        return match;
    }
}
