using System.Diagnostics.CodeAnalysis;
using URWPGSim2D.Collision.Fish;
using URWPGSim2D.Collision.Shapes;

namespace URWPGSim2D.Server.Json;

/// <summary>
/// One SHAPE of the input, validated: either a primitive library <see cref="Shape"/> (circle,
/// box, 8-DOP, polygon, segment) or a multi-joint fish, held as its <see cref="FishModel"/>
/// (leaves and bounding-volume tree built at the given pose).
/// </summary>
internal sealed class InputShape
{
    private readonly Shape _shape;

    private InputShape(in Shape shape, FishModel? fish)
    {
        _shape = shape;
        Fish = fish;
    }

    /// <summary>The fish model, or null for a primitive shape.</summary>
    public FishModel? Fish { get; }

    /// <summary>Whether this SHAPE is a fish (then <see cref="Fish"/> is set).</summary>
    [MemberNotNullWhen(true, nameof(Fish))]
    public bool IsFish => Fish is not null;

    /// <summary>The primitive shape; only for a SHAPE that is not a fish.</summary>
    /// <exception cref="InvalidOperationException">This SHAPE is a fish.</exception>
    public ref readonly Shape Shape
    {
        get
        {
            if (IsFish)
            {
                throw new InvalidOperationException("a fish SHAPE has no primitive shape");
            }

            return ref _shape;
        }
    }

    /// <summary>A primitive shape.</summary>
    /// <param name="shape">The validated shape.</param>
    /// <returns>The input shape.</returns>
    public static InputShape Of(in Shape shape) => new(shape, null);

    /// <summary>A fish.</summary>
    /// <param name="fish">Its model at the input pose.</param>
    /// <returns>The input shape.</returns>
    public static InputShape Of(FishModel fish)
    {
        ArgumentNullException.ThrowIfNull(fish);
        return new InputShape(default, fish);
    }
}
