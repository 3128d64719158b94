namespace URWPGSim2D.Collision.Benchmarks.Baseline.Motion;

/// <summary>A pair that the broad phase says may touch during the rest of the step.</summary>
/// <param name="A">The first body's id (always a moving body).</param>
/// <param name="B">The second body's id (a moving body after A, a static body or the walls).</param>
/// <param name="MoverA">A's mover slot.</param>
/// <param name="MoverB">B's mover slot, or −1 when B does not move.</param>
/// <param name="Limit">Largest relative travel (mm) of the pair between two samples: half the sum of their thinnest widths.</param>
internal readonly record struct PlannedPair(int A, int B, int MoverA, int MoverB, float Limit);
