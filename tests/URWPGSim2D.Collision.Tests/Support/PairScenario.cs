namespace URWPGSim2D.Collision.Tests.Support;

/// <summary>How <see cref="RandomShapes.Pair"/> placed the second shape relative to the first.</summary>
public enum PairScenario
{
    /// <summary>Centres closer than the sum of the bounding radii: overlapping or apart, either is common.</summary>
    Scattered,

    /// <summary>One shape 4 to 40 times smaller than the other and placed near its centre: containment or deep overlap.</summary>
    Containment,

    /// <summary>Moved along the reference normal to within ±0.03 mm of touching.</summary>
    NearTouching,

    /// <summary>Bounding circles apart: certainly no overlap.</summary>
    Apart,
}
