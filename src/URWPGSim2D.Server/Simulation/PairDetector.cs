using URWPGSim2D.Collision.Motion;
namespace URWPGSim2D.Server.Simulation;

/// <summary>The exact test of one pair of the world at the bodies' poses now, by the collision library's motion stepper.</summary>
internal static class PairDetector
{
    /// <summary>The contact of <paramref name="pair"/> now (MTV moves A).</summary>
    public static Contact Detect(World world, in CandidatePair pair) => world.Bodies.Detect(pair);
}
