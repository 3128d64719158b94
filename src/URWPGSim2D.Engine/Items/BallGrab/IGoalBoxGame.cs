namespace URWPGSim2D.Engine.Items.BallGrab;

/// <summary>
/// What the goal-box demo (<see cref="BallGrabDemo"/>) reads of a referee whose teams bring balls
/// into the goal boxes of <see cref="BallGrabLayout"/>: 抢球博弈 and 抢球大作战.
/// </summary>
internal interface IGoalBoxGame
{
    /// <summary>Counts the times the referee has placed every body afresh (half time, a new period): the demo forgets its tracks when it changes.</summary>
    int Restarts { get; }

    /// <summary>The end (−1 left, +1 right) whose goal box scores for <paramref name="team"/> now.</summary>
    int BoxSide(int team);

    /// <summary>Whether <paramref name="team"/> has no more to gain from ball <paramref name="ball"/> (the demo leaves it alone).</summary>
    bool HasScored(int team, int ball);

    /// <summary>The points of a ball.</summary>
    double BallValue(int ball);
}
