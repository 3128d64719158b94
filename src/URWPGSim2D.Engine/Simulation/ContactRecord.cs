namespace URWPGSim2D.Engine.Simulation;

/// <summary>One resolved contact of a cycle, as the trace reports it.</summary>
/// <param name="Pair">The pair (kinds and indices of A and B).</param>
/// <param name="PartA">Fish part of A (a <see cref="URWPGSim2D.Collision.Fish.FishPart"/> value) or −1.</param>
/// <param name="PartB">Fish part of B or −1.</param>
/// <param name="Mtv">Minimum translation of A, mm.</param>
/// <param name="Normal">Unit normal from B toward A.</param>
/// <param name="Point">Action point, mm.</param>
/// <param name="Time">When in the cycle it was resolved, as a fraction 0..1 of the cycle (the time of first contact, or the sub-step's end for a pair already touching).</param>
public readonly record struct ContactRecord(CandidatePair Pair, sbyte PartA, sbyte PartB, Vector2 Mtv, Vector2 Normal, Vector2 Point, double Time);
