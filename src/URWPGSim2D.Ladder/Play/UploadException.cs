using System;

namespace URWPGSim2D.Ladder.Play;

/// <summary>An upload refused before anything of it is kept: one line naming what is wrong.</summary>
internal sealed class UploadException(string message) : Exception(message);
