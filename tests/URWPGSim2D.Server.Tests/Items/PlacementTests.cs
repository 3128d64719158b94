namespace URWPGSim2D.Server.Tests.Items;

public sealed class PlacementTests
{
    [Fact]
    public void AParkedFishMeetsNothingAndStaysPutEvenOutsideThePool()
    {
        // Ball 0 at rest where fish 0 is parked: nothing touches it; a parked fish outside the pool stays there.
        var match = ItemMatches.FromJson("""{"item":"ball-grab","fish":[{"strategy":"fixed","decision":{"vcode":15,"tcode":7}},{"strategy":"idle"},{"strategy":"idle"},{"strategy":"idle"}],"balls":[{"position":[0,600]}]}""");
        Placement.Park(match.World.Fish[0], new Vector2(0, 600), 0f);
        Placement.Park(match.World.Fish[1], new Vector2(-2115, 1591), 0f);
        for (int k = 0; k < 20; k++)
        {
            match.Step();
        }

        Assert.Equal(new Vector2(0, 600), match.World.Balls[0].Position);
        Assert.Equal(new Vector2(0, 600), match.World.Fish[0].Position);
        Assert.Equal(new Vector2(-2115, 1591), match.World.Fish[1].Position);
        Assert.Equal(0f, match.World.Fish[0].Speed.Value);

        // Back in play it swims (its fixed decision) and pushes the ball it overlaps.
        Placement.Place(match.World.Fish[0], new Vector2(-200, 600), 0f);
        for (int k = 0; k < 40; k++)
        {
            match.Step();
        }

        Assert.True(match.World.Fish[0].Position.X > -150f, $"fish at {match.World.Fish[0].Position}");
        Assert.True(match.World.Balls[0].Position.X > 1f, $"ball at {match.World.Balls[0].Position}");
    }
}
