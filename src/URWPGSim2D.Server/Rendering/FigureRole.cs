namespace URWPGSim2D.Server.Rendering;

/// <summary>What a shape is in a figure: one of a list of shapes, or side a or b of a pair (which sets its colours).</summary>
internal enum FigureRole
{
    /// <summary>An element of a list of shapes.</summary>
    Single,

    /// <summary>The first shape of a pair: the one the MTV moves.</summary>
    A,

    /// <summary>The second shape of a pair.</summary>
    B,
}
