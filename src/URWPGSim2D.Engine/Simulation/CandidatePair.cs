namespace URWPGSim2D.Engine.Simulation;

/// <summary>A pair that the broad phase says may touch during the rest of the cycle.</summary>
/// <param name="Kind">What A and B index.</param>
/// <param name="A">First body (a fish or a ball).</param>
/// <param name="B">Second body (fish, ball or static index; unused for walls).</param>
/// <param name="Limit">Largest relative travel (mm) of the pair in one sub-step: half the sum of their thinnest widths.</param>
public readonly record struct CandidatePair(PairKind Kind, int A, int B, float Limit);
