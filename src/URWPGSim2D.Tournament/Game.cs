namespace URWPGSim2D.Tournament;

/// <summary>One decided game between two entrants, as the rating model sees it.</summary>
/// <param name="A">The first entrant.</param>
/// <param name="B">The second entrant.</param>
/// <param name="ScoreA">What <paramref name="A"/> scored: 1 a win, 0.5 a draw, 0 a loss.</param>
internal readonly record struct Game(int A, int B, double ScoreA);
