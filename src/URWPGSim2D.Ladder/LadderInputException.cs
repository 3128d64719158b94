using System;

namespace URWPGSim2D.Ladder;

/// <summary>Bad input to the ladder (a request's field, a setting): one line naming the field and the value; HTTP 400, exit 2.</summary>
public sealed class LadderInputException : Exception
{
    /// <summary>Creates the exception.</summary>
    /// <param name="message">The one-line message.</param>
    public LadderInputException(string message)
        : base(message)
    {
    }
}
