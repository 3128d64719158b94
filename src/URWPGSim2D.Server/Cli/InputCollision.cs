using URWPGSim2D.Collision;
using URWPGSim2D.Collision.Fish;

namespace URWPGSim2D.Server.Cli;

/// <summary>
/// Collision of two input SHAPEs, each a primitive shape or a fish: primitives go to
/// <see cref="CollisionDetector"/>, anything with a fish to <see cref="FishCollision"/> (the
/// deepest leaf contact). In every case the MTV moves <c>a</c> and the normal points from
/// <c>b</c> toward <c>a</c>.
/// </summary>
internal static class InputCollision
{
    /// <summary>Tests <paramref name="a"/> against <paramref name="b"/>.</summary>
    /// <param name="a">The first SHAPE (moved by the MTV).</param>
    /// <param name="b">The second SHAPE.</param>
    /// <returns>The contact; its parts are set only for fish sides (and only when they intersect).</returns>
    public static FishContact Detect(InputShape a, InputShape b)
    {
        if (a.IsFish)
        {
            return b.IsFish ? FishCollision.Detect(a.Fish, b.Fish) : FishCollision.Detect(a.Fish, b.Shape);
        }

        return b.IsFish
            ? FishCollision.Detect(a.Shape, b.Fish)
            : new FishContact(CollisionDetector.Detect(a.Shape, b.Shape), null, null);
    }

    /// <summary>Whether the answer for this pair carries <c>partA</c> / <c>partB</c>: when at least one side is a fish.</summary>
    /// <param name="a">The first SHAPE.</param>
    /// <param name="b">The second SHAPE.</param>
    /// <returns>True when a or b is a fish.</returns>
    public static bool HasParts(InputShape a, InputShape b) => a.IsFish || b.IsFish;
}
