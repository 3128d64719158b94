namespace URWPGSim2D.Strategies;

/// <summary>What a strategy's debug drawing is.</summary>
public enum DebugShapeKind : byte
{
    /// <summary>A dot at <see cref="DebugShape.A"/>.</summary>
    Point,

    /// <summary>A segment from <see cref="DebugShape.A"/> to <see cref="DebugShape.B"/>.</summary>
    Line,

    /// <summary>A circle around <see cref="DebugShape.A"/> of <see cref="DebugShape.Radius"/>.</summary>
    Circle,

    /// <summary>A text at <see cref="DebugShape.A"/>.</summary>
    Text,
}
