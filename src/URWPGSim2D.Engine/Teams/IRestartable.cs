namespace URWPGSim2D.Engine.Teams;

/// <summary>A built-in strategy that can go back to the state of a new one of the same team (a match restarted in place).</summary>
internal interface IRestartable
{
    /// <summary>Forgets everything seen and decided, keeping its buffers.</summary>
    void Restart();
}
