using URWPGSim2D.Engine.Simulation.Kinematics;
using URWPGSim2D.Collision.Motion;

namespace URWPGSim2D.Engine.Items;

/// <summary>
/// Moves bodies between cycles, as referees do: fish to a start pose at rest, fish out of play
/// (parked where nothing touches them, possibly outside the pool), balls to a place at rest.
/// The caller settles overlaps afterwards (its <see cref="ItemReferee.Judge"/> returns true).
/// </summary>
internal static class Placement
{
    /// <summary>Puts a fish at a pose, at rest and in play.</summary>
    public static void Place(FishState f, Vector2 position, float heading)
    {
        f.OutOfPlay = false;
        Move(f, position, heading);
    }

    /// <summary>Takes a fish out of play at a pose: it does not move and nothing collides with it.</summary>
    public static void Park(FishState f, Vector2 position, float heading)
    {
        f.OutOfPlay = true;
        Move(f, position, heading);
    }

    /// <summary>Takes a ball out of play at a place: it does not move and nothing collides with it.</summary>
    public static void Park(BallState b, Vector2 position)
    {
        Place(b, position);
        b.OutOfPlay = true;
    }

    /// <summary>Puts a ball at a place, at rest and in play.</summary>
    public static void Place(BallState b, Vector2 position)
    {
        b.OutOfPlay = false;
        b.Position = position;
        b.Velocity = Vector2.Zero;
        b.NoiseVelocity = Vector2.Zero;
    }

    private static void Move(FishState f, Vector2 position, float heading)
    {
        f.Position = position;
        f.Heading = Angle.Wrap(heading);
        f.Speed.Reset(0f, SpeedTable.Speeds);
        f.Turn.Reset(0f, TurnTable.Rates);
        f.Velocity = Vector2.Zero;
        f.AngularVelocity = 0f;
        f.NoiseVelocity = Vector2.Zero;
        f.NoiseAngularVelocity = 0f;
        f.Decision = URWPGSim2D.Strategies.Decision.Stop;
    }
}
