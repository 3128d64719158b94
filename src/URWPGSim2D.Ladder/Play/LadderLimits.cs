namespace URWPGSim2D.Ladder.Play;

/// <summary>What one upload may hold, and how many uploads a team may make per day.</summary>
/// <param name="MaxUploadBytes">The most bytes of one upload (all its files).</param>
/// <param name="MaxFiles">The most files of one upload (or entries of its .zip).</param>
/// <param name="MaxUnpackedBytes">The most bytes a .zip upload unpacks to.</param>
/// <param name="SubmissionsPerDay">The most submissions of one team per UTC day (the organiser may change it).</param>
public sealed record LadderLimits(long MaxUploadBytes = 4 << 20, int MaxFiles = 200, long MaxUnpackedBytes = 16 << 20, int SubmissionsPerDay = 20);
