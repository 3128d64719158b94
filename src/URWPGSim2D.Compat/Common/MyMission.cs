namespace URWPGSim2D.Common;

/// <summary>
/// The original's process-wide holder of the running mission's objects. In the original a strategy ran in
/// its own application domain, where this holder was never filled; so here too the server leaves every
/// reference null (<see cref="IsRomteMode"/> stays true). It is one object for the whole process, shared by
/// all teams' strategies, like <see cref="Field.Instance"/>. The original's <c>IMissionRef</c> (of its
/// simulation interface <c>IMission</c>) is not offered.
/// </summary>
public class MyMission
{
    private static readonly MyMission Shared = new();

    private MyMission()
    {
    }

    /// <summary>The mission (null: never filled for strategies).</summary>
    public Mission? MissionRef;

    /// <summary>The mission's parameters (null: never filled for strategies).</summary>
    public MissionCommonPara? ParasRef;

    /// <summary>The teams (null: never filled for strategies).</summary>
    public List<Team<RoboFish>>? TeamsRef;

    /// <summary>The environment (null: never filled for strategies).</summary>
    public SimEnvironment? EnvRef;

    /// <summary>The decision table (null: never filled for strategies).</summary>
    public Decision[,]? DecisionRef;

    /// <summary>Whether the original's server ran in remote mode (true, the original's default).</summary>
    public bool IsRomteMode = true;

    /// <summary>The process's one holder.</summary>
    /// <returns>The one <see cref="MyMission"/>.</returns>
    public static MyMission Instance() => Shared;
}
